#!/usr/bin/env bash
# Builds the libFuzzer targets (in the sanitizer build, build-asan/: clang, ASan + UBSan) and
# runs each one.
# Usage: scripts/fuzz.sh [RUNS | SECONDSs] [TARGET...]
#   RUNS      inputs per target (default 30000), with a fixed seed: the same binary runs the
#             same inputs, so a CI failure reproduces
#   SECONDSs  e.g. 600s: run each target that long instead (exploratory, not reproducible)
#   TARGET    only these (e.g. scene run_file: the targets a change touched); default: all
# Targets: the scene loader, the visibility sweep, the three track importers, the run-file
# reader (what report, video and explore read), the command
# line's parser, weighted coverage on scenes the bytes choose, and the Python environments'
# native stepping (EpisodeStepper). The corpus starts from tests/fuzz/seeds, every scene of
# scenes/ and tests/data/ and the track extracts of tests/data/tracks (copied at run time into
# the build folder, never into the repository).
# A crash leaves its input in build-asan/artifacts/; replay it with
#   build-asan/tests/fuzz/fuzz_<target> build-asan/artifacts/<file>
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
budget=${1:-30000}
only=("${@:2}")
case "$budget" in
  *s) limit=(-max_total_time="${budget%s}" -seed=0) ;;
  *) limit=(-runs="$budget" -seed=1) ;;
esac

dir=$("$repo/scripts/build.sh" sanitize fuzz_scene fuzz_visibility fuzz_lastrow fuzz_ethucy \
  fuzz_csv_tracks fuzz_run_file fuzz_command_line fuzz_weighted_scene fuzz_episode_stepper | tail -n 1)

corpus="$dir/corpus"
rm -rf "$corpus"
mkdir -p "$corpus"/{scene,visibility,lastrow,ethucy,csv_tracks,run_file,command_line,weighted_scene,episode_stepper} "$dir/artifacts"
cp "$repo"/tests/fuzz/seeds/scene/*.json "$corpus/scene/"
find "$repo/scenes" "$repo/tests/data" -name '*.json' -size -64k |
  while read -r f; do cp "$f" "$corpus/scene/$(echo "${f#"$repo"/}" | tr / _)"; done
# The importers' seeds are the repository's track extracts; an ETH/UCY input is obsmat.txt, a
# NUL byte, then map.xml (tests/fuzz/ethucy_fuzzer.cpp).
tracks="$repo/tests/data/tracks"
cp "$tracks/lastrow_extract.csv" "$corpus/lastrow/"
cp "$tracks/ethucy_extract/obsmat.txt" "$corpus/ethucy/obsmat_only"
{ cat "$tracks/ethucy_extract/obsmat.txt"; printf '\0'; cat "$tracks/ethucy_extract/map.xml"; } \
  >"$corpus/ethucy/with_map"
cp "$repo"/tests/fuzz/seeds/command_line/* "$corpus/command_line/"
cp "$repo"/tests/fuzz/seeds/csv_tracks/* "$corpus/csv_tracks/"
cp "$repo"/tests/fuzz/seeds/run_file/* "$corpus/run_file/"

run() {
  local target=$1 log="$dir/fuzz_$1.log" code=0
  shift
  if [ ${#only[@]} -gt 0 ] && [[ " ${only[*]} " != *" $target "* ]]; then return 0; fi
  echo "== fuzz_$target ${limit[*]}"
  "$dir/tests/fuzz/fuzz_$target" "$corpus/$target" "${limit[@]}" -timeout=20 -rss_limit_mb=4096 \
    -print_final_stats=1 -artifact_prefix="$dir/artifacts/$target-" "$@" >"$log" 2>&1 || code=$?
  if [ "$code" -eq 0 ]; then
    grep -E '^(Done|stat::new_units_added)' "$log"
  else
    tail -n 60 "$log"  # the failing check or the sanitizer's report, and the artifact's name
  fi
  return "$code"
}
status=0
run scene -max_len=8192 -dict="$repo/tests/fuzz/scene.dict" || status=1
# Without length control every input may use all 1024 bytes from the start: a World with
# several objects and cameras needs a few hundred.
run visibility -max_len=1024 -len_control=0 || status=1
run lastrow -max_len=8192 || status=1
run ethucy -max_len=8192 || status=1
run csv_tracks -max_len=8192 || status=1
# A short run's file (tests/fuzz/seeds/run_file), a few kilobytes.
run run_file -max_len=16384 || status=1
run command_line -max_len=512 || status=1
# Bytes choose a weighted scene (tests/fuzz/weighted_scene_fuzzer.cpp): a few hundred do.
run weighted_scene -max_len=512 -len_control=0 || status=1
# Bytes choose episodes, threads and commands (tests/fuzz/episode_stepper_fuzzer.cpp).
run episode_stepper -max_len=1024 || status=1
[ "$status" -eq 0 ] && echo "fuzz: no failures" || echo "fuzz: FAILED, inputs in $dir/artifacts"
exit "$status"
