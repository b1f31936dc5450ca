#!/usr/bin/env bash
# Installs what is missing, builds, and runs camcov's main job: `camcov bench` on the
# project's own scenes (scenes/, and scenes/real/ made from ../shared/tracks when it is there),
# the paper's method, the baseline, ours and the learned policy, 5 seeds each, on all cores.
# Results, summary and logs land in bench-results/; a second run resumes instead of starting
# over. Extra arguments are passed on, e.g. `--seeds 20`, `--methods paper,local` or
# `--scenes ../shared/coverage_scenes`.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$repo/scripts/install_deps.sh"
# Only the program it runs: the tests are the test command's to build.
"$repo/scripts/build.sh" release camcov >/dev/null
cd "$repo"
scenes=(scenes)
if [ -d "$repo/../shared/tracks" ]; then
  "$repo/scripts/make_real_scenes.sh" "$repo/../shared/tracks" >/dev/null 2>&1
  scenes+=(scenes/real)
fi
# The learned policy beside the default methods, unless the caller names the methods.
methods=(--methods paper,local,camcov,learned)
for argument in "$@"; do
  case "$argument" in --methods|--methods=*) methods=() ;; esac
done
exec "$repo/build/src/cli/camcov" bench --scenes "${scenes[@]}" "${methods[@]}" --out bench-results "$@"
