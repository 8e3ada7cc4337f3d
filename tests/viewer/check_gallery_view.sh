#!/bin/sh
# The ParaView view a real run writes: the gallery (every kind of dataset: curves, a categorical develop
# mesh, time series of a curve and a surface, a region) at a small size, its view.py rendered by pvbatch and
# checked by check_view.sh.
# usage: check_gallery_view.sh SELFSIM SOURCE_DIR WORK_DIR
set -u
selfsim=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
"$selfsim" run "$src/examples/gallery.lua" -o "$work/out" -q --set detail=-4 >/dev/null || {
  echo "FAIL: the gallery did not run"
  exit 1
}
exec "$src/tests/viewer/check_view.sh" "$work/out/view.py" "$work/view.png"
