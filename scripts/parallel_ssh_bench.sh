#!/usr/bin/env bash
# camcov bench over several machines with GNU parallel and ssh: N shards spread over the
# hosts listed in HOSTS_FILE (one ssh login per line, e.g. "2/user@node1" for 2 slots), each
# shard's folder copied back (--return), then merged here.
#
#   scripts/parallel_ssh_bench.sh hosts.txt 8 out --scenes ../shared/coverage_scenes --seeds 20
#
# Every host needs this repository at the same path with camcov built (scripts/build.sh) and
# the scenes at the same absolute path (give --scenes an absolute path). Each shard runs in a
# scratch folder on its host (--workdir ...) that parallel removes after copying it back.
# Deterministic runs: the merged summary equals one machine's.
set -euo pipefail
hosts=${1:?usage: parallel_ssh_bench.sh HOSTS_FILE SHARDS OUT_DIR [camcov bench options]}
shards=${2:?number of shards}
out=${3:?output folder}
shift 3
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
command -v parallel >/dev/null || { echo "GNU parallel is missing: apt-get install parallel" >&2; exit 2; }
mkdir -p "$out"
options=$(printf ' %q' "$@")
cd "$out"
seq 1 "$shards" | parallel --sshloginfile "$hosts" --jobs 1 --workdir ... --return "shard-{}" \
  --cleanup "$repo/build/src/cli/camcov bench --shard {}/$shards --out shard-{} $options"
"$repo/build/src/cli/camcov" merge shard-* --out merged
