#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite: once in the Release build,
# then again under AddressSanitizer + UndefinedBehaviorSanitizer, then a short libFuzzer run
# (skip both with --fast).
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$repo/scripts/install_deps.sh"

# The published benchmark is read from where it lives, never copied into the repository.
if [ -z "${COVERAGE_SCENES_DIR:-}" ] && [ -d "$repo/../shared/coverage_scenes" ]; then
  export COVERAGE_SCENES_DIR="$repo/../shared/coverage_scenes"
fi
[ -n "${COVERAGE_SCENES_DIR:-}" ] && export COVERAGE_SCENES_DIR=$(cd "$COVERAGE_SCENES_DIR" && pwd)
echo "COVERAGE_SCENES_DIR=${COVERAGE_SCENES_DIR:-<unset: tests on the published scenes are skipped>}"

kinds=(release sanitize)
[ "${1:-}" = "--fast" ] && kinds=(release)
for kind in "${kinds[@]}"; do
  echo "== $kind build (at ${SECONDS} s)"
  dir=$("$repo/scripts/build.sh" "$kind" | tail -n 1)
  echo "== $kind tests (at ${SECONDS} s)"
  ctest --test-dir "$dir" --parallel "$(nproc)" --output-on-failure --timeout 900
done
# A short fuzz of every target, the same inputs every time.
if [ "${1:-}" != "--fast" ]; then
  echo "== fuzz (at ${SECONDS} s)"
  "$repo/scripts/fuzz.sh" 30000
fi
echo "== done in ${SECONDS} s"
