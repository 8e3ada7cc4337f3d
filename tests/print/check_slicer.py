#!/usr/bin/env python3
"""Every print example's .3mf sliced by a real slicer: PrusaSlicer's command line (Debian's prusa-slicer).

usage: check_slicer.py SELFSIM SOURCE_DIR

The print examples are the recipes examples/*.lua that save a .3mf (their text names a "....3mf" file), so a
new one is covered without listing it. Each runs at its defaults (SETS below says where not, and why) into a
temporary folder, and each .3mf it writes must:
  - load without needing repair: `prusa-slicer --info` says `manifold = yes` and none of the counts admesh
    reports when it fixes a mesh (open edges, degenerate facets, edges fixed, facets removed or reversed,
    backwards edges). PrusaSlicer 2.5 reads a .3mf as it is (an open one then reads `manifold = no` with its
    `open_edges`) and repairs an .stl as it loads it (a reversed facet then reads `facets_reversed = 1`):
    either way --info says what was wrong. The .stl files the examples save are read the same way.
  - slice: `prusa-slicer --export-gcode` with 0.2 mm layers (first layer too) exits 0;
  - reach the solid's height: the G-code's last layer (its last `;Z:` comment) lies within one layer (0.2
    mm, to the micrometre PrusaSlicer writes z in) of the .3mf's z extent, read here from the file's own
    XML (PrusaSlicer drops a part onto the bed, so its top layer is the height, whatever z the solid was
    made at). A flat top comes within half a layer (each layer is sliced at its middle); a rounded one can
    be nearly a layer short, where the last layer's slice is too narrow to extrude (print_surface's tip:
    top layer 70.0 mm for a solid 70.2002 mm high).
print_fails.lua is checked like the others: its finding is walls too thin for a nozzle, which is no defect of
the mesh; its .3mf is a closed solid a slicer reads without repair (and slices silently: that is why selfsim
has its own check).
First, controls written here: a 10 mm cube must pass with its top layer at 10 mm, and the same cube with one
triangle turned over, and with one triangle missing, must each be reported as needing repair; otherwise the
test cannot tell a good mesh from a bad one with this slicer, and fails.
Exit 0 when all pass, 1 with each failure named, 77 (skipped) when prusa-slicer is not installed.
"""

import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import zipfile

LAYER = 0.2  # mm: --layer-height and --first-layer-height
# Heights compared to the micrometre: PrusaSlicer reads a mesh in single precision (70.200218 mm for the
# 70.2002 mm of print_surface's six decimals), and writes its layers' z to three decimals at most.
GCODE_RESOLUTION = 0.001  # mm
# Counts `prusa-slicer --info` prints for a mesh that is open or that admesh repaired (TriangleMesh stats).
REPAIR_FIELDS = ("open_edges", "degenerate_facets", "edges_fixed", "facets_removed", "facets_added",
                 "facets_reversed", "backwards_edges")
# Recipes run with other parameters than their defaults, for time: none so far. (print_surface.lua's quick
# draft, levels=3 smooth=1, is no quicker to thicken and rests on a point: "There is an object with no
# extrusions in the first layer".)
SETS = {}
RUN_TIMEOUT = 600  # s, for one recipe or one slicing: a hang fails the test instead of stalling it


def slicer_command(slicer, datadir, *args):
    # --datadir: a folder of the test's own, so a user's PrusaSlicer settings change nothing here.
    return [slicer, "--datadir", datadir, "--loglevel", "1", *args]


def slicer_output(text):
    # PrusaSlicer prints "[trace] Initializing StaticPrintConfigs" before it reads --loglevel.
    return "\n".join(line for line in text.splitlines() if "[trace]" not in line)


def run(command):
    return subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          timeout=RUN_TIMEOUT)


def z_extent(path):
    """The .3mf's height in mm, from its model's vertices (selfsim writes one object and no transform)."""
    with zipfile.ZipFile(path) as archive:
        model = archive.read("3D/3dmodel.model").decode("utf-8")
    unit = re.search(r'<model[^>]*\sunit="([^"]+)"', model)
    if unit and unit.group(1) != "millimeter":
        raise ValueError(f"unit {unit.group(1)}, not millimeter")
    zs = [float(z) for z in re.findall(r'<vertex\s[^>]*\bz="([^"]+)"', model)]
    if not zs:
        raise ValueError("no vertices")
    return max(zs) - min(zs)


def check(path, slicer, datadir, slice_it=True):
    """The problems PrusaSlicer finds with the mesh file at path, and a line saying what it made of it."""
    problems = []
    name = os.path.basename(path)
    info = run(slicer_command(slicer, datadir, "--info", path))
    fields = dict(re.findall(r"^(\w+) = +(\S+)", info.stdout, re.M))
    if info.returncode != 0 or "manifold" not in fields:
        return [f"{name}: prusa-slicer --info exited {info.returncode}:\n{slicer_output(info.stdout)}"], ""
    repaired = [f"{key} = {fields[key]}" for key in REPAIR_FIELDS if fields.get(key, "0") != "0"]
    if fields["manifold"] != "yes" or repaired:
        problems.append(f"{name}: needs repair: manifold = {fields['manifold']}"
                        + "".join(", " + r for r in repaired))
    if not slice_it:
        return problems, f"{name}: manifold, {fields['number_of_facets']} facets, not sliced"
    try:
        height = z_extent(path)
    except (KeyError, ValueError, zipfile.BadZipFile) as error:
        return problems + [f"{name}: its height cannot be read: {error}"], ""
    if abs(float(fields["size_z"]) - height) > 1e-3:
        problems.append(f"{name}: PrusaSlicer reads it {fields['size_z']} mm high, the file says {height:.6f}")
    gcode = path + ".gcode"
    start = time.monotonic()
    sliced = run(slicer_command(slicer, datadir, "--export-gcode", "--layer-height", str(LAYER),
                                "--first-layer-height", str(LAYER), "--output", gcode, path))
    seconds = time.monotonic() - start
    if sliced.returncode != 0 or not os.path.exists(gcode):
        problems.append(f"{name}: prusa-slicer --export-gcode exited {sliced.returncode}:\n"
                        + slicer_output(sliced.stdout))
        return problems, ""
    with open(gcode) as f:
        layers = [float(z) for z in re.findall(r"^;Z:([-0-9.]+)", f.read(), re.M)]
    os.remove(gcode)
    if not layers:
        problems.append(f"{name}: the G-code has no layers (no ';Z:' comment)")
        return problems, ""
    top = layers[-1]
    if abs(top - height) > LAYER + GCODE_RESOLUTION:
        problems.append(f"{name}: top layer at {top} mm, the solid is {height:.3f} mm high (more than a "
                        f"{LAYER} mm layer apart)")
    return problems, (f"{name}: {height:.3f} mm high, {len(layers)} layers, top layer {top} mm, "
                      f"{fields['number_of_facets']} facets, manifold, {fields.get('number_of_parts')} part(s); "
                      f"sliced in {seconds:.1f} s")


def cube(turn=False, drop=False):
    """A 10 mm cube's corners and outward-facing triangles, one triangle turned over (turn) or missing (drop)."""
    corners = [(x, y, z) for z in (0, 10) for y in (0, 10) for x in (0, 10)]
    # Corner index = x + 2y + 4z.
    triangles = [(0, 2, 1), (1, 2, 3), (4, 5, 6), (5, 7, 6), (0, 1, 4), (1, 5, 4),
                 (2, 6, 3), (3, 6, 7), (0, 4, 2), (2, 4, 6), (1, 3, 5), (3, 7, 5)]
    if turn:
        a, b, c = triangles[0]
        triangles[0] = (a, c, b)
    if drop:
        triangles.pop(0)
    return corners, triangles


def write_cube_stl(path, **broken):
    corners, triangles = cube(**broken)
    with open(path, "w") as f:
        f.write("solid cube\n")
        for triangle in triangles:
            f.write(" facet normal 0 0 0\n  outer loop\n")
            f.writelines("   vertex %g %g %g\n" % corners[i] for i in triangle)
            f.write("  endloop\n endfacet\n")
        f.write("endsolid cube\n")


def write_cube(path, **broken):
    """A 10 mm cube as a .3mf (see cube)."""
    corners, triangles = cube(**broken)
    vertices = "".join(f'<vertex x="{x}" y="{y}" z="{z}"/>' for x, y, z in corners)
    faces = "".join(f'<triangle v1="{a}" v2="{b}" v3="{c}"/>' for a, b, c in triangles)
    model = ('<?xml version="1.0" encoding="UTF-8"?>\n'
             '<model unit="millimeter" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02">'
             f'<resources><object id="1" type="model"><mesh><vertices>{vertices}</vertices>'
             f'<triangles>{faces}</triangles></mesh></object></resources>'
             '<build><item objectid="1"/></build></model>\n')
    types = ('<?xml version="1.0" encoding="UTF-8"?>\n'
             '<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">'
             '<Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/>'
             '<Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/>'
             '</Types>\n')
    rels = ('<?xml version="1.0" encoding="UTF-8"?>\n'
            '<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">'
            '<Relationship Target="/3D/3dmodel.model" Id="rel0" '
            'Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/></Relationships>\n')
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as archive:
        archive.writestr("[Content_Types].xml", types)
        archive.writestr("_rels/.rels", rels)
        archive.writestr("3D/3dmodel.model", model)


def controls(tmp, slicer, datadir):
    """The closed cube passes (its .3mf sliced to 10 mm), the broken ones are found, as .3mf and as .stl."""
    failures = []
    for suffix, write in ((".3mf", write_cube), (".stl", write_cube_stl)):
        closed = os.path.join(tmp, "cube" + suffix)
        write(closed)
        problems, line = check(closed, slicer, datadir, slice_it=suffix == ".3mf")
        failures += [f"control: {p} (a closed 10 mm cube)" for p in problems]
        if line:
            print("control " + line)
        for kind, options in (("a triangle turned over", {"turn": True}), ("a triangle missing", {"drop": True})):
            broken = os.path.join(tmp, f"cube_{next(iter(options))}{suffix}")
            write(broken, **options)
            problems, _ = check(broken, slicer, datadir, slice_it=False)
            if any("needs repair" in p for p in problems):
                print(f"control: cube{suffix} with {kind} is found: " + problems[0].split(": ", 1)[1])
            else:
                failures.append(f"control: cube{suffix} with {kind} is not reported as needing repair: {problems}")
    return failures


def main():
    selfsim, source = sys.argv[1], sys.argv[2]
    slicer = shutil.which("prusa-slicer")
    if not slicer:
        print("skipped: prusa-slicer not installed (Debian: prusa-slicer; `make test` installs it)")
        return 77
    version = next((line for line in run([slicer, "--help"]).stdout.splitlines() if "[trace]" not in line), "")
    print(version)
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        datadir = os.path.join(tmp, "prusa-slicer")
        os.mkdir(datadir)
        failures += controls(tmp, slicer, datadir)
        recipes = [path for path in sorted(glob.glob(os.path.join(source, "examples", "*.lua")))
                   if re.search(r"\.3mf[\"']", open(path).read())]
        if not recipes:
            failures.append("no print examples found (examples/*.lua saving a .3mf)")
        for recipe in recipes:
            name = os.path.splitext(os.path.basename(recipe))[0]
            out = os.path.join(tmp, name)
            sets = [arg for value in SETS.get(name, []) for arg in ("--set", value)]
            start = time.monotonic()
            ran = run([selfsim, "run", recipe, "-o", out, "-q", *sets])
            print(f"{' '.join([name + '.lua', *sets])}: ran in {time.monotonic() - start:.1f} s")
            if ran.returncode != 0:
                failures.append(f"{name}.lua: selfsim run exited {ran.returncode}:\n{ran.stdout[-2000:]}")
                continue
            meshes = sorted(glob.glob(os.path.join(out, "**", "*.3mf"), recursive=True))
            if not meshes:
                failures.append(f"{name}.lua: wrote no .3mf")
            for path in meshes + sorted(glob.glob(os.path.join(out, "**", "*.stl"), recursive=True)):
                problems, line = check(path, slicer, datadir, slice_it=path.endswith(".3mf"))
                failures += [f"{name}.lua: {p}" for p in problems]
                if line:
                    print("  " + line)
            shutil.rmtree(out)
    for failure in failures:
        print("FAIL: " + failure)
    print(f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
