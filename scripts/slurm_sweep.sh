#!/usr/bin/env bash
# A parameter study as one Slurm job array: every setting of a grid (the product of the values
# given for each key) is one array task, which runs the whole `camcov bench` for that setting
# into its own folder, OUT_DIR/<key=value_key=value...>. Each folder is a complete results
# folder (summary, logs, report); a task that dies is resubmitted alone (sbatch --array=K) and
# resumes where it stopped.
#
#   n=$(scripts/slurm_sweep.sh --count global.K=50,200,800 global.tau=1.1,1.2)     # 6
#   sbatch --array=1-$n --cpus-per-task=2 --wait scripts/slurm_sweep.sh /shared/sweep \
#          global.K=50,200,800 global.tau=1.1,1.2 -- --scenes /shared/coverage_scenes --seeds 20
#   build/src/cli/camcov report /shared/sweep     # the settings side by side, sweep/report.html
#
# Settings are numbered with the first key varying slowest. Submit from the repository's root
# or set CAMCOV=/path/to/camcov (Slurm runs a copy of this script from its spool folder).
#SBATCH --job-name=camcov-sweep
#SBATCH --output=camcov-sweep-%A_%a.log
set -euo pipefail
usage="usage: slurm_sweep.sh --count KEY=V1,V2... ... | sbatch --array=1-N slurm_sweep.sh OUT_DIR KEY=V1,V2... ... -- [camcov bench options]"
count_only=false
if [ "${1:-}" = --count ]; then
  count_only=true
  shift
else
  out=${1:?$usage}
  shift
fi
keys=()
values=()  # the comma-separated values of keys[i]
while [ $# -gt 0 ] && [ "$1" != -- ]; do
  case "$1" in
    ?*=?*) keys+=("${1%%=*}"); values+=("${1#*=}") ;;
    *) echo "slurm_sweep.sh: '$1' is not KEY=V1,V2,...; $usage" >&2; exit 2 ;;
  esac
  shift
done
[ $# -gt 0 ] && shift  # the --
[ ${#keys[@]} -gt 0 ] || { echo "slurm_sweep.sh: no KEY=V1,V2,... given; $usage" >&2; exit 2; }
settings=1
for v in "${values[@]}"; do
  IFS=, read -r -a list <<<"$v"
  [ ${#list[@]} -ge 1 ] || { echo "slurm_sweep.sh: a key without values; $usage" >&2; exit 2; }
  settings=$((settings * ${#list[@]}))
done
if $count_only; then
  echo "$settings"
  exit 0
fi

k=${SLURM_ARRAY_TASK_ID:?run this as a Slurm job array (sbatch --array=1-$settings)}
count=${SLURM_ARRAY_TASK_COUNT:-1}
if [ "$count" -gt 1 ] && [ "$count" -ne "$settings" ]; then
  echo "slurm_sweep.sh: the grid has $settings settings, the array $count tasks" >&2
  exit 2
fi
if [ "$k" -lt 1 ] || [ "$k" -gt "$settings" ]; then
  echo "slurm_sweep.sh: task $k is not one of the settings 1..$settings" >&2
  exit 2
fi

# Setting k: mixed radix over the keys, the last key fastest.
index=$((k - 1))
sets=()
label=""
for ((i = ${#keys[@]} - 1; i >= 0; i--)); do
  IFS=, read -r -a list <<<"${values[i]}"
  value=${list[index % ${#list[@]}]}
  index=$((index / ${#list[@]}))
  sets=(--set "${keys[i]}=$value" "${sets[@]}")
  label="${keys[i]}=$value${label:+_$label}"
done

if [ -z "${CAMCOV:-}" ]; then
  for root in "${SLURM_SUBMIT_DIR:-}" "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"; do
    [ -n "$root" ] && [ -x "$root/build/src/cli/camcov" ] && CAMCOV=$root/build/src/cli/camcov && break
  done
fi
[ -x "${CAMCOV:-}" ] || {
  echo "slurm_sweep.sh: camcov not found: submit from the repository's root or set CAMCOV" >&2
  exit 2
}
# The setting's --set come after the bench options: they win over a --set of the same key there.
exec "$CAMCOV" bench "$@" "${sets[@]}" --jobs "${SLURM_CPUS_PER_TASK:-1}" --out "$out/$label"
