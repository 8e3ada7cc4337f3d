#!/usr/bin/env bash
# Every golden .eps run through Ghostscript, a real PostScript interpreter: it must run without an error,
# and what it draws (its bbox device) must lie inside the declared %%BoundingBox and fill it to the margin
# (at least 90% of its width and height: the curve spans the box less a 2% margin on each side).
# usage: check_eps.sh GOLDEN_DIR
set -uo pipefail
golden=$1
failures=0 files=0
for eps in "$golden"/*/*.eps; do
  [ -e "$eps" ] || continue
  files=$((files + 1))
  read -r _ _ _ bw bh < <(grep -m1 '^%%BoundingBox:' "$eps")
  if ! drawn=$(gs -q -dSAFER -dBATCH -dNOPAUSE -sDEVICE=bbox "$eps" 2>&1 >/dev/null | grep -m1 '^%%HiResBoundingBox:'); then
    echo "FAIL: $eps: Ghostscript drew nothing or failed"
    failures=$((failures + 1))
    continue
  fi
  read -r _ x0 y0 x1 y1 <<<"$drawn"
  if ! awk -v x0="$x0" -v y0="$y0" -v x1="$x1" -v y1="$y1" -v w="$bw" -v h="$bh" \
      'BEGIN { exit !(x0 >= -1 && y0 >= -1 && x1 <= w + 1 && y1 <= h + 1 && x1 - x0 >= 0.9 * w && y1 - y0 >= 0.9 * h) }'; then
    echo "FAIL: $eps: drawn box $x0 $y0 $x1 $y1 does not fill the declared 0 0 $bw $bh"
    failures=$((failures + 1))
  fi
done
[ "$files" -gt 0 ] || { echo "FAIL: no .eps files in $golden"; exit 1; }
[ $failures = 0 ] && echo "$files EPS files drawn by Ghostscript inside their bounding boxes"
exit $((failures > 0))
