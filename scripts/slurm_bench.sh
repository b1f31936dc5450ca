#!/usr/bin/env bash
# camcov bench as a Slurm job array: each array task runs one shard of the batch into its own
# folder; one merge afterwards builds the summary and logs. Every machine needs camcov built
# at the same path (or CAMCOV=/path/to/camcov) and the scenes at the same path.
#
#   sbatch --array=1-16 --cpus-per-task=2 scripts/slurm_bench.sh /shared/out \
#          --scenes /shared/coverage_scenes --seeds 20 --duration 30
#   build/src/cli/camcov merge /shared/out/shard-* --out /shared/out/merged
#
# Runs are deterministic, so the merged summary equals that of one machine; a task that dies
# can simply be resubmitted (sbatch --array=K ...): finished jobs are skipped.
#SBATCH --job-name=camcov-bench
#SBATCH --output=camcov-bench-%A_%a.log
set -euo pipefail
out=${1:?usage: sbatch --array=1-N scripts/slurm_bench.sh OUT_DIR [camcov bench options]}
shift
k=${SLURM_ARRAY_TASK_ID:?run this as a Slurm job array (sbatch --array=1-N)}
n=${SLURM_ARRAY_TASK_COUNT:-$((SLURM_ARRAY_TASK_MAX - SLURM_ARRAY_TASK_MIN + 1))}
k=$((k - ${SLURM_ARRAY_TASK_MIN:-1} + 1))  # shards are numbered 1..N whatever the array range
camcov=${CAMCOV:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/build/src/cli/camcov}
exec "$camcov" bench --shard "$k/$n" --jobs "${SLURM_CPUS_PER_TASK:-1}" --out "$out/shard-$k" "$@"
