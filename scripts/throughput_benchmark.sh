#!/usr/bin/env bash
# Throughput of the main job on the full published protocol (paper section VI-B): every
# published scene x both methods x 20 seeds x 30 s = 1,280 runs, once per worker count.
# Prints jobs/s, wall time, CPU time and peak memory, and the speedup over one worker.
#
#   scripts/throughput_benchmark.sh                 # workers 1 and 2, 20 seeds
#   SEEDS=5 WORKERS="2" scripts/throughput_benchmark.sh
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
scenes=${COVERAGE_SCENES_DIR:-$repo/../shared/coverage_scenes}
seeds=${SEEDS:-20}
workers=${WORKERS:-1 2}
"$repo/scripts/install_deps.sh" >/dev/null
"$repo/scripts/build.sh" release >/dev/null
camcov="$repo/build/src/cli/camcov"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

echo "camcov $("$camcov" --version | cut -d' ' -f2), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
printf '%-8s %8s %10s %10s %10s %12s %8s\n' workers jobs wall_s cpu_s jobs/s peak_MiB speedup
base_wall=""
for w in $workers; do
  out="$scratch/w$w"
  /usr/bin/time -f '%e %U %S %M' -o "$scratch/time" \
    "$camcov" bench --scenes "$scenes" --seeds "$seeds" --duration 30 --jobs "$w" --out "$out" \
    >"$scratch/stdout" 2>"$scratch/stderr"
  read -r wall user sys rss <"$scratch/time"
  jobs=$(ls "$out"/runs/*.json | grep -vc '\.error\.json$')
  base_wall=${base_wall:-$wall}
  awk -v w="$w" -v j="$jobs" -v wall="$wall" -v u="$user" -v s="$sys" -v rss="$rss" -v b="$base_wall" \
    'BEGIN { printf "%-8s %8d %10.1f %10.1f %10.2f %12.1f %8.2f\n", w, j, wall, u + s, j / wall, rss / 1024, b / wall }'
done
tail -n 3 "$scratch/stdout"
