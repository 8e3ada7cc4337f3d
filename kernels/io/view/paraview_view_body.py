
# ---------------------------------------------------------------------------------------------------------
# The fixed part of every view.py selfsim writes: everything below reads SELFSIM_VIEW (the header above) and
# builds the scene with paraview.simple only, so the same file opens in the GUI (paraview --script=view.py)
# and renders without a window (pvbatch view.py --png view.png).
# ---------------------------------------------------------------------------------------------------------
import colorsys
import math
import os
import sys

from paraview.simple import (AssignViewToLayout, Calculator, ColorBy, CreateLayout, CreateView,
                             GetActiveViewOrCreate, GetAnimationScene, GetColorTransferFunction, GetLayout,
                             GetOpacityTransferFunction, GetScalarBar, OpenDataFile, Render, RenameSource,
                             SaveScreenshot, Show, Tube)

BACKGROUND = [1.0, 1.0, 1.0]
TEXT = [0.12, 0.12, 0.15]            # dark text: ParaView's default white labels vanish on a white background
REGION_COLOUR = [0.62, 0.74, 0.86]   # pale blue, drawn see-through so what grew inside shows
SOLID_COLOURS = [[0.25, 0.40, 0.65], [0.80, 0.45, 0.20], [0.30, 0.60, 0.35], [0.55, 0.35, 0.60]]
# The frame a 3D drawing stands in, by its up axis (the dataset's "up", kernels/io/view/up_axis.h): right,
# up, and back (towards the front view's eye), as selfsim preview's views use them.
FRAMES = {0: ([0, 1, 0], [1, 0, 0], [0, 0, -1]), 1: ([1, 0, 0], [0, 1, 0], [0, 0, 1]),
          2: ([1, 0, 0], [0, 0, 1], [0, -1, 0])}


def view_folder():
    """The folder the datasets are in: the one this file sits in. pvbatch defines __file__; ParaView 5.11's
    GUI runs --script files through exec() with no __file__ (and sys.argv == ['']), so there the folder the
    file was written to, recorded in the header, is used. If that folder was moved away since, the working
    folder is the last guess."""
    here = globals().get("__file__")
    if here:
        return os.path.dirname(os.path.abspath(here))
    folder = SELFSIM_VIEW["folder"]
    if os.path.isdir(folder):
        return folder
    return os.getcwd()


def screenshot_path():
    """PATH from '--png PATH' or '--png=PATH' on the command line (pvbatch passes its script's arguments
    through in sys.argv), else None: then this is the GUI, which renders by itself."""
    args = sys.argv[1:]
    for i, a in enumerate(args):
        if a == "--png" and i + 1 < len(args):
            return args[i + 1]
        if a.startswith("--png="):
            return a[len("--png="):]
    return None


def category_colours(n):
    """n colours that stay apart even for neighbouring classes: each hue is the golden angle (about 137.5
    degrees) from the previous one, so consecutive classes never get similar hues and the hues never repeat
    in a cycle, and lightness and saturation step through three levels out of phase with the hue, so even
    two classes whose hues come close again (every 8 or 13 steps) differ in lightness. With 131 tile
    classes a smooth ramp would read as bands; this reads as distinct patches."""
    return [category_colour(i) for i in range(n)]


def category_colour(i):
    """The i-th class colour (category_colours; kernels/io/text/palette.cpp computes the same)."""
    golden = (3.0 - math.sqrt(5.0)) / 2.0   # the golden angle as a fraction of a turn
    lightness = [0.50, 0.68, 0.36]
    saturation = [0.75, 0.55, 0.90]
    hue = (0.58 + i * golden) % 1.0          # start at a blue so a few classes look calm
    r, g, b = colorsys.hls_to_rgb(hue, lightness[i % 3], saturation[(i // 3) % 3])
    return [r, g, b]


def value_label(v):
    """Annotation text for a category value: integers without '.0' (tile classes are whole numbers)."""
    return str(int(v)) if float(v).is_integer() else repr(float(v))


def colour_continuous(display, lut, field, low, high):
    """A perceptual map with the range fixed to the whole run's range, so that a time series does not
    rescale at each step (a level 2 in step 1 has the same colour as a level 2 in step 5)."""
    if high <= low:                           # a constant field: give the map some width
        low, high = low - 0.5, high + 0.5
    lut.ApplyPreset("Viridis (matplotlib)", True)
    lut.AutomaticRescaleRangeMode = "Never"
    lut.RescaleTransferFunction(low, high)
    opacity = GetOpacityTransferFunction(field, display, separate=True)
    opacity.RescaleTransferFunction(low, high)


def colour_categorical(lut, categories, by_value=False):
    """One annotation and one colour per category: ParaView draws each value in its own colour and the
    scalar bar lists the classes instead of a ramp. `by_value` (a grammar's colour index `color`): each
    value takes the colour of its magnitude, as the SVG the grammar strokes does, not the colour of its rank
    (natural_field.h, category_colour)."""
    annotations, colours = [], []
    if by_value:
        chosen = [category_colour(abs(int(v))) for v in categories]
    else:
        chosen = category_colours(len(categories))
    for value, rgb in zip(categories, chosen):
        annotations += [value_label(value), value_label(value)]
        colours += rgb
    # Annotations first, then the switch: the GUI, seeing a categorical map with no annotations, would
    # otherwise stop the script with a dialog offering to make them from the data.
    lut.Annotations = annotations
    lut.IndexedColors = colours
    lut.AnnotationsInitialized = 1
    lut.InterpretValuesAsCategories = 1


def style_scalar_bar(bar, title, index, count, categories, below):
    """Dark text, the field's name as the title; bars stacked along the right edge, or (`below`: a view
    sharing the window with others, too narrow for a bar beside what it shows) one across the bottom."""
    bar.Title = title
    bar.ComponentTitle = ""
    bar.TitleColor = TEXT
    bar.LabelColor = TEXT
    bar.TitleFontSize = 16
    bar.LabelFontSize = 14
    bar.RangeLabelFormat = "%.4g"        # 256 rather than ParaView's 2.6e+02 at the ends
    bar.WindowLocation = "Any Location"
    if below:
        bar.Orientation = "Horizontal"
        bar.ScalarBarLength = 0.7 / count
        bar.Position = [0.15 + index * 0.7 / count, 0.03]
    else:
        bar.Orientation = "Vertical"
        bar.ScalarBarLength = 0.8 if count == 1 else max(0.25, 0.85 / count)
        bar.Position = [0.90, 0.1] if count == 1 else [0.90, 0.05 + (count - 1 - index) * 0.9 / count]
    if categories and len(categories) > 40:
        # Every class would get a label too small to read; the colours still tell the classes apart.
        bar.DrawAnnotations = 0
    bar.Visibility = 1


def open_dataset(folder, d):
    """The dataset's reader, named as the recipe named its file. OpenDataFile picks the reader from the
    name: .vtp, .pvd (a Collection) and .vtp.series (JSON)."""
    path = os.path.join(folder, d["file"])
    reader = OpenDataFile(path)
    if reader is None:
        raise RuntimeError("ParaView cannot open " + path)
    RenameSource(d["name"], reader)
    return reader


def last_bounds(reader):
    """The dataset's bounds at its last time step (a series' grown result): [xmin, xmax, ymin, ...]."""
    times = list(getattr(reader, "TimestepValues", None) or [])
    reader.UpdatePipeline(times[-1] if times else 0.0)
    return reader.GetDataInformation().GetBounds()


def inside(inner, outer):
    """Whether bounds `inner` lie within `outer`, give or take a hundredth of outer's size."""
    size = max(outer[1] - outer[0], outer[3] - outer[2], outer[5] - outer[4])
    slack = 0.01 * size
    return all(inner[2 * a] >= outer[2 * a] - slack and inner[2 * a + 1] <= outer[2 * a + 1] + slack
               for a in range(3))


def union(boxes):
    """The bounds holding every one of `boxes`."""
    return [min(b[a] for b in boxes) if a % 2 == 0 else max(b[a] for b in boxes) for a in range(6)]


def scenes_of(datasets, bounds):
    """Which datasets share a view. Each result (curve, surface, series) gets a view of its own, so that
    outputs that all start at the origin - a curve from (0,0) to (1,0), a surface grown in the unit sphere -
    do not draw over one another; a region joins the views of the results that lie inside it (the volume
    a surface grew in), and is shown alone only when nothing lies inside it."""
    results = [i for i, d in enumerate(datasets) if d["role"] != "region"]
    regions = [i for i, d in enumerate(datasets) if d["role"] == "region"]
    scenes = [[i] for i in results]
    for r in regions:
        homes = [scene for scene in scenes if inside(bounds[scene[0]], bounds[r]) and not datasets[scene[0]]["flat"]]
        for scene in homes:
            scene.insert(0, r)
        if not homes:
            scenes.append([r])
    return scenes


def with_tubes(reader, bounds):
    """A curve with a point field `width` (a grammar's '!') as tubes of radius proportional to it, the widest
    1.2% of the drawing's diagonal, none thinner than a tenth of that: every picture's rule
    (kernels/io/drawn_width.h); other sources as they are."""
    if "width" not in reader.PointData.keys():
        return reader
    low, high = reader.PointData["width"].GetRange()
    widest = max(abs(low), abs(high))
    diagonal = math.sqrt(sum((bounds[2 * a + 1] - bounds[2 * a]) ** 2 for a in range(3)))
    if not widest > 0 or not diagonal > 0:
        return reader
    radius = Calculator(Input=reader)
    radius.AttributeType = "Point Data"
    radius.ResultArrayName = "tube_radius"
    # None thinner than a tenth of the widest, as the preview draws them: a width lowered to 0 would vanish.
    radius.Function = "max(abs(width),%.17g)*%.17g" % (0.1 * widest, 0.012 * diagonal / widest)
    tubes = Tube(Input=radius)
    tubes.Scalars = ["POINTS", "tube_radius"]
    tubes.VaryRadius = "By Absolute Scalar"
    tubes.NumberofSides = 8
    tubes.Capping = 1
    return tubes


def show_dataset(d, reader, view, bar_index, bar_count, solid, named, bounds):
    """Shows one dataset in a view, coloured as its header says; returns whether it drew a scalar bar."""
    if d["role"] == "curve":
        reader = with_tubes(reader, bounds)
    display = Show(reader, view)
    display.Representation = "Surface"
    if d["role"] == "region":
        # The volume a surface grew in: a pale see-through shell, one colour, no scalar bar.
        # No field. (ColorBy(display, None) fails on a file with no arrays at all, as a region's is.)
        display.ColorArrayName = ["POINTS", ""]
        display.AmbientColor = REGION_COLOUR
        display.DiffuseColor = REGION_COLOUR
        display.Opacity = 0.2
        display.Specular = 0.0
        return False
    if d["role"] == "curve":
        display.LineWidth = 2.5       # one-pixel lines are hard to see at 1200 pixels across
    if d["field"] is None:
        display.ColorArrayName = ["POINTS", ""]
        colour = SOLID_COLOURS[solid % len(SOLID_COLOURS)]
        display.AmbientColor = colour
        display.DiffuseColor = colour
        return False
    # A map of its own for each dataset: two datasets with a field of the same name ('level') but
    # different ranges or kinds must not share one.
    ColorBy(display, (d["association"], d["field"]), separate=True)
    lut = GetColorTransferFunction(d["field"], display, separate=True)
    # No range: the field's values overflowed (the writer keeps non-finite numbers out of this file).
    low, high = d["range"] if d["range"] is not None else (0.0, 1.0)
    if d["categorical"]:
        colour_categorical(lut, d["categories"], d["field"] == "color")
    else:
        colour_continuous(display, lut, d["field"], low, high)
    display.SetScalarBarVisibility(view, True)
    title = d["name"] + ": " + d["field"] if named or bar_count > 1 else d["field"]
    style_scalar_bar(GetScalarBar(lut, view), title, bar_index, bar_count, d["categories"], named)
    return True


def fit_flat(view, bounds, below):
    """A top view that shows all of `bounds` whatever the view's shape: ParaView's own fit scales to the
    view's height, which cuts a wide drawing in a narrow view. A small margin all round, and the right edge
    (a scalar bar beside) or the bottom (`below`: a bar across it) left free."""
    width, height = [max(1, int(x)) for x in view.ViewSize]
    margin = 0.04
    left, right = margin, (margin if below else 0.15)
    bottom, top = (0.22 if below else margin), margin
    usable_w, usable_h = 1.0 - left - right, 1.0 - bottom - top
    dx, dy = bounds[1] - bounds[0], bounds[3] - bounds[2]
    half = 0.5 * max(dy / usable_h, dx * height / (width * usable_w), 1e-12)  # half the visible height
    seen_w, seen_h = 2.0 * half * width / height, 2.0 * half
    # The drawing's centre goes to the centre of the free part of the view.
    cx = 0.5 * (bounds[0] + bounds[1]) - (left + 0.5 * usable_w - 0.5) * seen_w
    cy = 0.5 * (bounds[2] + bounds[3]) - (bottom + 0.5 * usable_h - 0.5) * seen_h
    view.CameraFocalPoint = [cx, cy, 0.0]
    view.CameraPosition = [cx, cy, 1.0]
    view.CameraParallelScale = half


def place_camera(view, flat, bounds, below, up=1):
    if flat:
        # Everything lies in z = 0: look straight down, without perspective, and keep the GUI's mouse from
        # tilting it out of the plane.
        view.InteractionMode = "2D"
        view.CameraPosition = [0.0, 0.0, 1.0]
        view.CameraFocalPoint = [0.0, 0.0, 0.0]
        view.CameraViewUp = [0.0, 1.0, 0.0]
        view.CameraParallelProjection = 1
        view.OrientationAxesVisibility = 0
    else:
        # The preview's oblique view, from the front right and above with the dataset's up axis up (+y for a
        # plant, the axis a growth's level follows): depth reads without hiding the top.
        right, upward, back = FRAMES.get(up, FRAMES[1])
        view.InteractionMode = "3D"
        view.CameraPosition = [back[a] + 0.8 * right[a] + 0.55 * upward[a] for a in range(3)]
        view.CameraFocalPoint = [0.0, 0.0, 0.0]
        view.CameraViewUp = upward
        view.CameraParallelProjection = 0
        view.OrientationAxesVisibility = 1
    # Keep that direction, move and zoom to fit what is shown at the current (last) time.
    view.ResetCamera(False)
    if flat:
        fit_flat(view, bounds, below)
    elif below:
        # A bar across the bottom: step back a little so the shape clears it.
        view.GetActiveCamera().Dolly(0.8)


def place_views(layout, cell, views, across, size, sizes):
    """Puts the views into the layout's cell as a balanced grid: the cell is split in two (across, then
    down, alternately) in proportion to the views on each side. Splitting a cell moves the view it holds
    to the first half, where views[0], the view already in the layout, belongs. `sizes` gets each view's
    share of `size` (the cell's width and height in pixels)."""
    if len(views) == 1:
        if layout.GetViewLocation(views[0]) != cell:
            layout.AssignView(cell, views[0])
        sizes.append(size)
        return
    half = (len(views) + 1) // 2
    fraction = half / float(len(views))
    if across:
        layout.SplitHorizontal(cell, fraction)
        first, second = [int(size[0] * fraction), size[1]], [size[0] - int(size[0] * fraction), size[1]]
    else:
        layout.SplitVertical(cell, fraction)
        first, second = [size[0], int(size[1] * fraction)], [size[0], size[1] - int(size[1] * fraction)]
    place_views(layout, 2 * cell + 1, views[:half], not across, first, sizes)
    place_views(layout, 2 * cell + 2, views[half:], not across, second, sizes)


def main():
    folder = view_folder()
    png = screenshot_path()
    datasets = SELFSIM_VIEW["datasets"]
    readers = [open_dataset(folder, d) for d in datasets]
    bounds = [last_bounds(r) for r in readers]
    scenes = scenes_of(datasets, bounds)
    # The views side by side in one layout (a grid of about equal rows and columns); the first is the
    # GUI's own view.
    first = GetActiveViewOrCreate("RenderView")
    layout = GetLayout(first)
    if layout is None:  # pvbatch: a view outside any layout
        layout = CreateLayout("selfsim")
        AssignViewToLayout(view=first, layout=layout, hint=0)
    if png:
        # pvbatch: lay the views out at the picture's size, so fonts and bars are placed for that size and
        # not magnified from a small default window.
        layout.SetSize(1200, 800)
    views = [first] + [CreateView("RenderView") for _ in scenes[1:]]
    sizes = []
    place_views(layout, 0, views, True, [1200, 800], sizes)
    if png:
        # pvbatch: each view at its share of the picture, so fonts, bars and the camera's fit are made for
        # that size (the GUI sizes its views itself).
        for view, size in zip(views, sizes):
            view.ViewSize = size
    shown = []
    for view, scene in zip(views, scenes):
        # A light background of this view only (not ParaView's global palette, which the GUI user owns).
        view.UseColorPaletteForBackground = 0
        view.Background = BACKGROUND
        view.OrientationAxesLabelColor = TEXT
        coloured = [i for i in scene if datasets[i]["field"] is not None and datasets[i]["role"] != "region"]
        bars = 0
        for k, i in enumerate(scene):
            # With several views, each bar names its dataset: the views do not say what they show.
            bars += show_dataset(datasets[i], readers[i], view, bars, len(coloured), k, len(scenes) > 1, bounds[i])
        ups = [datasets[i].get("up", 1) for i in scene if datasets[i]["role"] != "region"]
        shown.append((view, all(datasets[i]["flat"] for i in scene), union([bounds[i] for i in scene]),
                      ups[0] if ups else 1))

    # Time series: the animation (the VCR controls in the GUI) steps through the data's own time steps, and
    # the views open on the last one, the grown result.
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.GoToLast()
    for view, flat, box, up in shown:
        place_camera(view, flat, box, len(scenes) > 1, up)
        Render(view)
    if png:
        SaveScreenshot(png, layout, ImageResolution=[1200, 800])
        print("wrote " + png)


main()
