#!/usr/bin/env bash
# Configures and builds camcov. Usage: scripts/build.sh [release|sanitize] [TARGET...]
#   release  (default) optimised build in build/
#   sanitize AddressSanitizer + UndefinedBehaviorSanitizer build in build-asan/
#   TARGET   only these (e.g. camcov: the main job needs no test program); default: all
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
kind=${1:-release}
targets=("${@:2}")
case "$kind" in
  release)  dir="$repo/build";      flags=(-DCMAKE_BUILD_TYPE=Release) ;;
  sanitize) dir="$repo/build-asan"; flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCAMCOV_SANITIZE=ON -DCAMCOV_BUILD_BENCHMARKS=OFF) ;;
  *) echo "usage: $0 [release|sanitize]" >&2; exit 2 ;;
esac
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
