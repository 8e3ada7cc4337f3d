"""What a preview PNG shows, measured from its pixels, for tests/cli/check_preview_views.sh. Run by a Python
that imports VTK (tests/viewer/vtk_python.sh): its PNG reader and numpy.

  upright PNG [W]         the front view (left half, between the title and legend strips) of a 3D preview
                          holds a drawing taller than wide whose bottom rows (the trunk) sit in its middle
                          and run straight up for a sixth of its height, alone (and at least W pixels wide)
  upright_view PNG        the same for the picture of a run's ParaView view (pvbatch view.py --png)
  frames APNG DIR         checks the APNG's chunks and writes each frame as DIR/frame_N.png; prints the count
  same_camera A B [drawing]  every pixel A's views draw is drawn in B too (A's drawing lies inside B's, as a
                          step inside a later step does), and A's legend strip is B's (unless `drawing`:
                          pictures antialiased differently)
  same_views A B          the views of A and B are the same pixels (a still and its series' last frame)
  differ A B              A and B are not the same picture
  colour PNG R G B        pixels near that colour are drawn (at least 200)
  drawing PNG SHARE       at least SHARE (0..1) of the views' pixels are drawn
  title_shorter A B       A's title is drawn much shorter than B's
"""
import os
import struct
import sys
import zlib

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

TITLE, LEGEND = 0.07, 0.13  # the strips above and below the views, as fractions of the height


def pixels(path):
    """The picture as rows top-down of RGB."""
    r = vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    img = r.GetOutput()
    w, h, _ = img.GetDimensions()
    if w == 0:
        sys.exit(f"{path}: not a PNG VTK reads")
    a = vtk_to_numpy(img.GetPointData().GetScalars())[:, :3].reshape(h, w, 3)
    return a[::-1].astype(int)


def drawn(a):
    return a.min(axis=2) < 215


def views(a):
    h = a.shape[0]
    v = a[int(h * TITLE) + 2:int(h * (1 - LEGEND)) - 2].copy()
    if a.shape[1] > a.shape[0]:  # a 3D preview's two views: leave out each one's name in its lower left corner
        for x0 in (0, a.shape[1] // 2):
            v[-24:, x0:x0 + 170] = 255
    return v


def legend(a):
    return a[int(h_of(a) * (1 - LEGEND)) + 2:]


def h_of(a):
    return a.shape[0]


def upright(path, trunk_width="0", region=None):
    a = pixels(path)
    front = drawn(views(a)[:, :a.shape[1] // 2]) if region is None else region(a)
    rows = front.any(axis=1).nonzero()[0]
    cols = front.any(axis=0).nonzero()[0]
    if len(rows) == 0:
        sys.exit(f"{path}: the front view is blank")
    height, width = rows[-1] - rows[0] + 1, cols[-1] - cols[0] + 1
    if not height > 1.2 * width:
        sys.exit(f"{path}: the front view's drawing is {width} wide and {height} tall: not upright")
    bottom = front[rows[-1] - max(2, height // 30):rows[-1] + 1]
    xs = bottom.any(axis=0).nonzero()[0]
    centre, middle = (xs[0] + xs[-1]) / 2, (cols[0] + cols[-1]) / 2
    if xs[-1] - xs[0] > 0.25 * width or abs(centre - middle) > 0.2 * width:
        sys.exit(f"{path}: the bottom of the drawing spans x {xs[0]}..{xs[-1]}, the drawing {cols[0]}..{cols[-1]}:"
                 " not a trunk in the middle")
    # The trunk is a vertical run: its column is drawn all along the bottom sixth of the drawing.
    # The trunk is a vertical run: its column is drawn all along the bottom sixth of the drawing, and nothing
    # else is (a tree seen from below has branches there).
    sixth = front[rows[-1] - height // 6:rows[-1] + 1]
    column = sixth[:, int(xs[0]):int(xs[-1]) + 1].any(axis=1)
    if not column.all():
        sys.exit(f"{path}: no vertical trunk along the bottom sixth of the drawing ({column.mean():.0%} of its rows)")
    spread = sixth.any(axis=0).nonzero()[0]
    if spread[-1] - spread[0] > 0.25 * width:
        sys.exit(f"{path}: the bottom sixth of the drawing spans {spread[-1] - spread[0] + 1} of {width} columns:"
                 " more than a trunk")
    if xs[-1] - xs[0] + 1 < int(trunk_width):
        sys.exit(f"{path}: the trunk is {xs[-1] - xs[0] + 1} pixels wide, expected at least {trunk_width}")
    print(f"upright: {width}x{height}, trunk {xs[-1] - xs[0] + 1} wide at {centre:.0f} of {cols[0]}..{cols[-1]}")


def upright_view(path):
    """A ParaView view.py's picture (pvbatch, one view): the drawing between the orientation axes at the
    left and the scalar bar at the right."""
    upright(path, "0", lambda a: drawn(a[:, int(a.shape[1] * 0.15):int(a.shape[1] * 0.85)]))


def chunks(data):
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit("not a PNG signature")
    i = 8
    while i < len(data):
        n, kind = struct.unpack(">I4s", data[i:i + 8])
        body = data[i + 8:i + 8 + n]
        if zlib.crc32(kind + body) != struct.unpack(">I", data[i + 8 + n:i + 12 + n])[0]:
            sys.exit(f"bad CRC in a {kind!r} chunk")
        yield kind, body
        i += 12 + n


def chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))


def frames(path, folder):
    data = open(path, "rb").read()
    listed = list(chunks(data))
    kinds = [k for k, _ in listed]
    if kinds[0] != b"IHDR" or b"acTL" not in kinds or kinds.index(b"acTL") > kinds.index(b"IDAT"):
        sys.exit(f"{path}: no acTL before the image data: not an APNG")
    count = struct.unpack(">I", listed[kinds.index(b"acTL")][1][:4])[0]
    ihdr = listed[0][1]
    out, current, sequence = [], None, []
    for kind, body in listed:
        if kind in (b"fcTL",):
            sequence.append(struct.unpack(">I", body[:4])[0])
            if current is not None:
                out.append(current)
            current = b""
        elif kind == b"IDAT" and current is not None:
            current += body
        elif kind == b"fdAT":
            sequence.append(struct.unpack(">I", body[:4])[0])
            current += body[4:]
    if current is not None:
        out.append(current)
    if sequence != list(range(len(sequence))):
        sys.exit(f"{path}: sequence numbers {sequence[:8]}... do not count up from 0")
    if len(out) != count:
        sys.exit(f"{path}: acTL says {count} frames, {len(out)} fcTL")
    os.makedirs(folder, exist_ok=True)
    for n, idat in enumerate(out):
        with open(os.path.join(folder, f"frame_{n}.png"), "wb") as f:
            f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", idat) + chunk(b"IEND", b""))
    print(count)


def same_camera(a_path, b_path, what="all"):
    a, b = pixels(a_path), pixels(b_path)
    if a.shape != b.shape:
        sys.exit(f"{a_path} and {b_path} differ in size")
    da, db = drawn(views(a)), drawn(views(b))
    if da.sum() < 50:
        sys.exit(f"{a_path}: its views are blank")
    # A pixel of A's drawing counts as found in B when B draws within one pixel of it (antialiasing).
    near = db.copy()
    near[1:, :] |= db[:-1, :]
    near[:-1, :] |= db[1:, :]
    near[:, 1:] |= db[:, :-1]
    near[:, :-1] |= db[:, 1:]
    found = (da & near).sum() / da.sum()
    if found < 0.97:
        sys.exit(f"only {found:.1%} of what {a_path} draws is drawn at the same place in {b_path}")
    if what != "drawing" and not (legend(a) == legend(b)).all():
        sys.exit(f"the legends of {a_path} and {b_path} differ")
    print(f"same camera: {found:.1%} of A's drawing in B, legends equal")


def same_views(a_path, b_path):
    a, b = pixels(a_path), pixels(b_path)
    if a.shape != b.shape or not (views(a) == views(b)).all():
        sys.exit(f"the views of {a_path} and {b_path} differ")


def differ(a_path, b_path):
    a, b = pixels(a_path), pixels(b_path)
    if a.shape == b.shape and (a == b).all():
        sys.exit(f"{a_path} and {b_path} are the same picture")


def drawing(path, share):
    """At least `share` of the views' pixels are drawn (not a blank picture)."""
    d = drawn(views(pixels(path)))
    if d.mean() < float(share):
        sys.exit(f"{path}: {d.mean():.2%} of the views drawn, expected at least {float(share):.0%}")


def title_extent(a):
    """How far right the title (the top strip's left part) is drawn, in pixels."""
    strip = drawn(a[:int(a.shape[0] * TITLE)])[:, :int(a.shape[1] * 0.4)]  # left of a frame's caption
    cols = strip.any(axis=0).nonzero()[0]
    return cols[-1] if len(cols) else 0


def title_shorter(a_path, b_path):
    """A's title is drawn much shorter than B's ("growth.pvd" against "growth.pvd (last of 2 steps)")."""
    a, b = title_extent(pixels(a_path)), title_extent(pixels(b_path))
    if not 0 < a < 0.7 * b:
        sys.exit(f"the title of {a_path} reaches x {a}, that of {b_path} x {b}")


def colour(path, r, g, b):
    a = pixels(path)
    near = (abs(a - [int(r), int(g), int(b)]).max(axis=2) < 40).sum()
    if near < 200:
        sys.exit(f"{path}: {near} pixels near ({r}, {g}, {b})")


commands = {"upright": upright, "upright_view": upright_view, "frames": frames, "same_camera": same_camera, "same_views": same_views,
            "differ": differ, "colour": colour, "drawing": drawing, "title_shorter": title_shorter}
commands[sys.argv[1]](*sys.argv[2:])
