#!/bin/sh
# Renders a view.py that selfsim wrote with ParaView (scripts/pvbatch-selfsim, i.e. pvbatch, under xvfb when
# there is no display) and checks the picture shows something coloured: at least 1% of the pixels differ
# from the background and they hold at least 3 distinct hues (a coloured field or several datasets,
# not one flat silhouette).
# usage: check_view.sh VIEW_PY OUT_PNG
# Exit: 0 pass; 1 fail, with a one-line reason; 77 skip, only when pvbatch cannot be found.
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
view=$1 png=$2

if ! command -v pvbatch >/dev/null 2>&1; then
  echo "SKIP: pvbatch not found (Debian package paraview; make deps installs it)"
  exit 77
fi
python=$("$here/vtk_python.sh") || { echo "FAIL: no Python that imports vtkmodules to read the PNG"; exit 1; }

rm -f "$png"
log=$(mktemp)
# One retry: under a full parallel ctest pvbatch has (rarely) exited non-zero with nothing in its log, and
# passed when run again; a view that cannot render fails both times, with pvbatch's status and last line.
"$root/scripts/pvbatch-selfsim" "$view" --png "$png" >"$log" 2>&1 ||
  "$root/scripts/pvbatch-selfsim" "$view" --png "$png" >"$log" 2>&1
status=$?
if [ $status != 0 ]; then
  echo "FAIL: pvbatch could not render $view (exit $status): $(grep -v '^\s*$' "$log" | tail -n 1)"
  rm -f "$log"
  exit 1
fi
rm -f "$log"
[ -s "$png" ] || { echo "FAIL: pvbatch ran but wrote no $png"; exit 1; }

# $python is unquoted on purpose: it may be "env PYTHONPATH=... /usr/bin/python3".
$python - "$png" <<'EOF'
import colorsys
import sys
from collections import Counter
from vtkmodules.vtkIOImage import vtkPNGReader

def fail(reason):
    print("FAIL: " + reason)
    sys.exit(1)


reader = vtkPNGReader()
reader.SetFileName(sys.argv[1])
reader.Update()
image = reader.GetOutput()
scalars = image.GetPointData().GetScalars()
if scalars is None:
    fail(f"{sys.argv[1]} is not a readable PNG")
nc = scalars.GetNumberOfComponents()
data = bytes(memoryview(scalars))
rgb = list(zip(data[0::nc], data[1::nc], data[2::nc]))
total = len(rgb)
background = rgb[0]                      # the corner: view.py keeps the corners clear of data and bars
def far(c):                              # beyond anti-aliasing noise of the background
    return max(abs(a - b) for a, b in zip(c, background)) > 24
drawn = [c for c in rgb if far(c)]
# Distinct colours by hue: shading makes many shades of one colour, which must not count as several. Each
# drawn pixel goes to one of 12 hue bins, or to a grey bin when it has little saturation; a bin counts when
# it holds at least 1/2000 of the picture.
bins = Counter()
for (r, g, b), n in Counter(drawn).items():
    h, s, v = colorsys.rgb_to_hsv(r / 255, g / 255, b / 255)
    bins["grey" if s < 0.2 or v < 0.15 else int(h * 12) % 12] += n
distinct = sum(1 for n in bins.values() if n >= max(20, total // 2000))
share = len(drawn) / total
if share < 0.01:
    fail(f"{sys.argv[1]} is blank: {100 * share:.2f}% of pixels differ from the background {background}")
if distinct < 3:
    fail(f"{sys.argv[1]} shows {distinct} colour(s) apart from the background, expected at least 3")
print(f"ok: {sys.argv[1]}: {100 * share:.1f}% drawn, {distinct} distinct colours, {image.GetDimensions()[:2]}")
EOF
