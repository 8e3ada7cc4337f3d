"""The peer of `selfsim preview FILE` (bench/README.md, "Previews"): ParaView's own way to a picture of one
file, through pvbatch: open it, colour it by a field, fit the camera, save a 1200 x 600 screenshot.
usage: scripts/pvbatch-selfsim bench/paraview_one_file.py --png OUT.png FILE FIELD"""
import sys

from paraview.simple import ColorBy, GetActiveViewOrCreate, OpenDataFile, ResetCamera, SaveScreenshot, Show

args = sys.argv[1:]
out = args[args.index("--png") + 1]
rest = [a for i, a in enumerate(args) if a != "--png" and (i == 0 or args[i - 1] != "--png")]
source, field = rest[0], rest[1]
view = GetActiveViewOrCreate("RenderView")
display = Show(OpenDataFile(source), view)
ColorBy(display, ("CELLS", field))
display.SetScalarBarVisibility(view, True)
ResetCamera(view)
SaveScreenshot(out, view, ImageResolution=[1200, 600])
