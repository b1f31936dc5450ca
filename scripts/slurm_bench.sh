#!/usr/bin/env bash
# camcov bench as a Slurm job array: each array task runs one shard of the batch into its own
# folder; one merge afterwards builds the summary and logs. Every machine needs camcov built
# at the same path and the scenes at the same path. Submit from the repository's root (Slurm
# runs a copy of this script from its spool folder, so camcov is found from the folder the job
# was submitted from), or say where camcov is with CAMCOV=/path/to/camcov.
#
#   sbatch --array=1-16 --cpus-per-task=2 --wait scripts/slurm_bench.sh /shared/out \
#          --scenes /shared/coverage_scenes --seeds 20 --duration 30
#   build/src/cli/camcov merge /shared/out/shard-* --out /shared/out/merged
#
# Runs are deterministic, so the merged summary equals that of one machine; a task that dies
# can simply be resubmitted (sbatch --array=K ... with the same OUT_DIR and options): it runs
# its own shard again, skipping the jobs it had finished. tests/cluster runs both on a real
# one-node cluster.
#SBATCH --job-name=camcov-bench
#SBATCH --output=camcov-bench-%A_%a.log
set -euo pipefail
out=${1:?usage: sbatch --array=1-N scripts/slurm_bench.sh OUT_DIR [camcov bench options]}
shift
k=${SLURM_ARRAY_TASK_ID:?run this as a Slurm job array (sbatch --array=1-N)}
count=${SLURM_ARRAY_TASK_COUNT:-$((SLURM_ARRAY_TASK_MAX - SLURM_ARRAY_TASK_MIN + 1))}
# Task K of the array runs shard K of N. N is the size of the array the batch was first
# submitted as, kept in OUT_DIR/shards: a task resubmitted alone (an array of one) still runs
# its own shard of N, not the whole batch.
mkdir -p "$out"
# The first task to get here records N; link() is atomic, so no task reads a half-written file.
echo "$count" >"$out/.shards.$k.$$"
ln "$out/.shards.$k.$$" "$out/shards" 2>/dev/null || true
rm -f "$out/.shards.$k.$$"
n=$(cat "$out/shards")
if [ "$count" -gt 1 ] && [ "$count" -ne "$n" ]; then
  echo "slurm_bench.sh: $out was submitted as $n shards, this array has $count tasks" >&2
  exit 2
fi
if [ "$k" -lt 1 ] || [ "$k" -gt "$n" ]; then
  echo "slurm_bench.sh: task $k is not one of the shards 1..$n (submit --array=1-$n)" >&2
  exit 2
fi
if [ -z "${CAMCOV:-}" ]; then
  for root in "${SLURM_SUBMIT_DIR:-}" "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"; do
    [ -n "$root" ] && [ -x "$root/build/src/cli/camcov" ] && CAMCOV=$root/build/src/cli/camcov && break
  done
fi
[ -x "${CAMCOV:-}" ] || {
  echo "slurm_bench.sh: camcov not found: submit from the repository's root or set CAMCOV" >&2
  exit 2
}
camcov=$CAMCOV
exec "$camcov" bench --shard "$k/$n" --jobs "${SLURM_CPUS_PER_TASK:-1}" --out "$out/shard-$k" "$@"
