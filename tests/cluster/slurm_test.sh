#!/usr/bin/env bash
# The Slurm recipe on a real Slurm cluster (one node, scripts/slurm_cluster.sh):
#  1. `sbatch --array=1-4 --wait scripts/slurm_bench.sh`, then `camcov merge`: the summary and
#     every run file are byte-identical to one `camcov bench` process.
#  2. One array task is cancelled (scancel) in the middle of its shard and resubmitted: what it
#     had finished is kept, the rest is run, and the merge is still identical.
#  3. scripts/slurm_sweep.sh: a 2 x 2 grid as an array of 4, each setting's folder the bytes of
#     `camcov bench --set ...` in one process; `camcov report` over the sweep shows the 4 settings.
# Usage: slurm_test.sh CAMCOV_BINARY. Exits 77 (skipped) where Slurm cannot run.
set -euo pipefail
camcov=${1:?usage: slurm_test.sh CAMCOV_BINARY}
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=$(mktemp -d /tmp/camcov-slurm-test.XXXXXX)
cluster=$work/cluster
trap '"$repo/scripts/slurm_cluster.sh" stop "$cluster"; rm -rf "$work"' EXIT
trap 'exit 1' INT TERM  # a killed test (ctest's timeout) still stops the daemons

status=0
"$repo/scripts/slurm_cluster.sh" start "$cluster" >/dev/null || status=$?
[ "$status" -eq 77 ] && exit 77
[ "$status" -eq 0 ] || { echo "FAIL: the cluster did not start" >&2; exit 1; }
export SLURM_CONF=$cluster/slurm.conf CAMCOV=$camcov

# Byte-identical: the summary and every run file of two results folders.
same() {
  local a=$1 b=$2
  cmp "$a/summary.json" "$b/summary.json" || { echo "FAIL: $a and $b: summaries differ" >&2; exit 1; }
  diff <(cd "$a/runs" && ls) <(cd "$b/runs" && ls) ||
    { echo "FAIL: $a and $b hold different runs" >&2; exit 1; }
  for f in "$a"/runs/*; do
    cmp "$f" "$b/runs/$(basename "$f")" || { echo "FAIL: $f differs" >&2; exit 1; }
  done
}

cd "$repo"
echo "== 1. an array of 4 shards, merged, against one process"
small=(--scenes tests/data/scenes --methods paper,local --seeds 2 --duration 2
       --set global.K=30 --set planner.T2=0.05 --videos none)
"$camcov" bench "${small[@]}" --no-report --out "$work/one" >/dev/null
sbatch --array=1-4 --wait --quiet --output="$work/task-%a.log" \
  scripts/slurm_bench.sh "$work/array" "${small[@]}"
"$camcov" merge "$work"/array/shard-* --out "$work/array/merged" --videos none --no-report >/dev/null
same "$work/one" "$work/array/merged"
echo "ok: 4 Slurm array tasks merge to the bytes of one process"

echo "== 2. a task cancelled mid-shard and resubmitted"
# Two ~1 s runs per shard, so there is a moment with one run written and one under way.
long=(--scenes scenes/crowd_large_room.json --methods paper --seeds 8 --videos none)
"$camcov" bench "${long[@]}" --no-report --jobs 1 --out "$work/one-long" >/dev/null
job=$(sbatch --parsable --array=1-4 --output="$work/long-%a.log" \
  scripts/slurm_bench.sh "$work/long" "${long[@]}")
shard=$work/long/shard-2
for _ in $(seq 1500); do
  compgen -G "$shard/runs/*.json" >/dev/null && break
  sleep 0.02
done
scancel "${job}_2"
written=$(ls "$shard"/runs/*.json 2>/dev/null | wc -l)
[ "$written" -ge 1 ] && [ "$written" -lt 2 ] ||
  { echo "FAIL: task 2 was not caught mid-shard ($written of 2 runs written)" >&2; exit 1; }
while squeue -h -j "$job" 2>/dev/null | grep -q .; do sleep 0.2; done
sbatch --array=2 --wait --quiet --output="$work/long-again.log" \
  scripts/slurm_bench.sh "$work/long" "${long[@]}"
grep -q "1 of 2 jobs already done" "$work/long-again.log" ||
  { echo "FAIL: the resubmitted task did not keep its finished run" >&2; cat "$work/long-again.log" >&2; exit 1; }
"$camcov" merge "$work"/long/shard-* --out "$work/long/merged" --videos none --no-report >/dev/null
same "$work/one-long" "$work/long/merged"
echo "ok: cancelled after $written run, resubmitted, merged to the bytes of one process"

echo "== 3. a parameter sweep, one array task per setting"
grid=(global.K=20,40 global.tau=1.1,1.3)
settings=$(scripts/slurm_sweep.sh --count "${grid[@]}")
[ "$settings" -eq 4 ] || { echo "FAIL: --count says $settings settings, not 4" >&2; exit 1; }
sbatch --array=1-"$settings" --wait --quiet --output="$work/sweep-%a.log" \
  scripts/slurm_sweep.sh "$work/sweep" "${grid[@]}" -- "${small[@]}" --no-report
for k in 20 40; do
  for tau in 1.1 1.3; do
    folder=$work/sweep/global.K=${k}_global.tau=$tau
    "$camcov" bench "${small[@]}" --no-report --set global.K=$k --set global.tau=$tau \
      --out "$work/one-$k-$tau" >/dev/null
    same "$work/one-$k-$tau" "$folder"
  done
done
echo "ok: 4 settings, each the bytes of one process with its --set"
"$camcov" report "$work/sweep" >/dev/null
for k in 20 40; do
  for tau in 1.1 1.3; do
    grep -q "<tr data-setting=\"global.K=${k}_global.tau=$tau\"><th scope=\"row\">K=$k τ=$tau" \
      "$work/sweep/report.html" || { echo "FAIL: the sweep's report lacks K=$k τ=$tau" >&2; exit 1; }
  done
done
echo "ok: camcov report shows the 4 settings side by side"
