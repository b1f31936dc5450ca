#!/usr/bin/env bash
# Rewrites tests/data/golden_runs.json with the fingerprints of the current code's runs. Use it
# only when a change is meant to change results, and say in the commit what changed and why.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
dir=$("$repo/scripts/build.sh" release | tail -n 1)
CAMCOV_UPDATE_GOLDEN_RUNS=1 CAMCOV_BINARY="$dir/src/cli/camcov" \
  "$dir/tests/cli/test_cli" --gtest_filter='GoldenRuns.*' >/dev/null
git -C "$repo" diff --stat -- tests/data/golden_runs.json
