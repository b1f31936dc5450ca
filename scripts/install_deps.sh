#!/usr/bin/env bash
# Installs every Debian 12 package camcov needs to build, test and benchmark.
# Idempotent: packages already present are skipped, so a second run costs one dpkg query.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git clang-format
  ccache                            # a second tree of the sources builds from the first's objects
  libboost-dev                      # Boost.Geometry (header-only)
  libompl-dev                       # OMPL: PRM* motion planning
  libboost-filesystem-dev libboost-serialization-dev libboost-system-dev  # linked by OMPL
  libeigen3-dev                     # Eigen (pulled by OMPL too)
  nlohmann-json3-dev                # JSON
  libcairo2-dev                     # frames (PNG, SVG)
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev  # videos
  libx264-dev
  ffmpeg                            # ffprobe, used by tests to check videos
  libgtest-dev libgmock-dev         # tests
  libcli11-dev libfmt-dev           # command line, formatting
  libjemalloc-dev                   # the program's allocator (src/cli/CMakeLists.txt)
  ompl-demos python3                # ompl_benchmark_statistics reads our logs in a test
  time                              # /usr/bin/time in scripts/throughput_benchmark.sh
  libbenchmark-dev                  # Google Benchmark
  clang libclang-rt-14-dev          # the sanitizer build and its fuzzers (clang, libFuzzer)
  chromium                          # headless browser test of the HTML report
  chromium-driver python3-selenium  # Selenium test of the explorer page (tests/explorer)
  pybind11-dev python3-dev python3-numpy python3-pytest  # the camcov Python module and its tests
  python3-venv python3-build        # pip install . into a venv, and the wheel (test_pip_install)
  emscripten nodejs                 # the engine as WebAssembly (src/wasm) and its test under node
  python3-torch python3-matplotlib  # scripts/train_learned.py and its test (the learned method)
  python3-cloudpickle python3-typing-extensions python3-pil  # Gymnasium's and PettingZoo's
                                    # checkers (sources in ../shared/vendor/python), frames
  slurmctld slurmd slurm-client munge  # a one-node Slurm cluster for tests/cluster
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install_deps: installing ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install_deps: done"
