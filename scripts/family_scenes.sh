#!/usr/bin/env bash
# Writes the first COUNT scenes of every family's tune or test seeds into OUT_DIR (docs/
# families.md, docs/method.md "Beyond the published scenes"): how our method's defaults are
# decided (tune) and then reported once (test).
#
#   scripts/family_scenes.sh tune|test COUNT OUT_DIR [CAMCOV]
#   scripts/family_scenes.sh tune 8 tune && camcov bench --scenes tune --seeds 5 --out tuned
#
# The bench groups the scenes by family (the table after the totals, and the report's "By
# family or folder").
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
usage="usage: scripts/family_scenes.sh tune|test COUNT OUT_DIR [CAMCOV]"
[ $# -ge 3 ] || { echo "$usage" >&2; exit 2; }
split=$1 count=$2 out=$3
camcov=${4:-$repo/build/src/cli/camcov}
case $split in tune) column=2 ;; test) column=3 ;; *) echo "$usage" >&2; exit 2 ;; esac
[ -x "$camcov" ] || { echo "family_scenes.sh: build camcov first (scripts/build.sh)" >&2; exit 2; }
# `--family list`: a heading line, then per family a line "NAME TUNE TEST what..." followed by
# indented lines of its ranges.
"$camcov" generate --family list | awk -v c=$column 'NR > 1 && /^[a-z]/ { split($c, r, "-"); print $1, r[1] }' |
  while read -r family first; do
    "$camcov" generate --family "$family" --count "$count" --seed "$first" -o "$out" >/dev/null
  done
echo "wrote $count $split scenes of every family to $out"
