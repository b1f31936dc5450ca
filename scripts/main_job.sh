#!/usr/bin/env bash
# Installs what is missing, builds, and runs camcov's main job on the project's own scenes.
# Extra arguments are passed on to the command.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$repo/scripts/install_deps.sh"
"$repo/scripts/build.sh" release >/dev/null
camcov="$repo/build/src/cli/camcov"
cd "$repo"
# Until the batch (`camcov bench`) exists, the main job checks every scene and prints the
# world of each at t = 0 and t = 10 s.
"$camcov" validate scenes/*.json "$@"
for scene in scenes/*.json; do
  "$camcov" state "$scene" --time 10 >/dev/null
done
echo "main job: $(ls scenes/*.json | wc -l) scenes validated and stepped to t = 10 s"
