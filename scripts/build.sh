#!/usr/bin/env bash
# Configures and builds camcov. Usage: scripts/build.sh [release|sanitize] [TARGET...]
#   release  (default) optimised build in build/
#   sanitize AddressSanitizer + UndefinedBehaviorSanitizer build in build-asan/, with clang, and
#            with the libFuzzer targets (scripts/fuzz.sh runs them from there)
#   TARGET   only these (e.g. camcov: the main job needs no test program); default: all
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
kind=${1:-release}
targets=("${@:2}")
case "$kind" in
  release)  dir="$repo/build";      flags=(-DCMAKE_BUILD_TYPE=Release) ;;
  # clang at -O1 with line tables only: the heaviest file takes 19 s instead of GCC's 89 s at
  # RelWithDebInfo's -O2 -g, stack traces still name file and line, and one build serves the
  # sanitizer tests and the fuzzers.
  sanitize) dir="$repo/build-asan"
    export CC=clang CXX=clang++
    # A folder configured by GCC before (the sanitizer build used to be GCC's) starts afresh:
    # CMake keeps a folder's first compiler, and only clang builds the fuzzers.
    if [ -f "$dir/CMakeCache.txt" ] && ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang' "$dir/CMakeCache.txt"; then
      rm -rf "$dir"
    fi
    flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only -DNDEBUG"
           -DCAMCOV_SANITIZE=ON -DCAMCOV_BUILD_FUZZERS=ON -DCAMCOV_BUILD_BENCHMARKS=OFF) ;;
  *) echo "usage: $0 [release|sanitize]" >&2; exit 2 ;;
esac
# Through ccache where it is installed (scripts/install_deps.sh installs it): a second tree of
# the same sources (the tutorial test's copy of the clone, another checkout) then compiles only
# the files that differ, since paths under each tree are hashed relative to it (CCACHE_BASEDIR).
if command -v ccache >/dev/null; then
  flags+=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$repo}
fi
# Progress and errors go to stderr, so callers can take the folder from stdout and a log
# still shows why a build failed.
cmake -S "$repo" -B "$dir" -G Ninja "${flags[@]}" >/dev/null
cmake --build "$dir" --parallel "$(nproc)" ${targets[@]:+--target "${targets[@]}"} >&2
# `import camcov` for Debian's python3, from anywhere (the sanitizer build has no module).
if [ "$kind" = release ] && [ ${#targets[@]} -eq 0 ]; then
  if [ -w /usr/local/lib ]; then
    cmake --install "$dir" --component python >/dev/null
  else
    echo "build.sh: the Python module is not installed (no write access to /usr/local):" \
      "use PYTHONPATH=$dir/python" >&2
  fi
fi
echo "$dir"
