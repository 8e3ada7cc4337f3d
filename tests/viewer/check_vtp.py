"""Opens every golden .vtp with VTK's Python reader, as ParaView would, checks its point count against the
count in the case's points.txt (derived from the closed forms, not from selfsim), and renders it offscreen
to a PNG that must not be blank. Run under xvfb: Debian's VTK renders through X."""
import pathlib
import sys

import vtk

golden, pictures = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
pictures.mkdir(parents=True, exist_ok=True)
failures, checked = [], 0

for case in sorted(p for p in golden.iterdir() if p.is_dir()):
    counts, boundaries = {}, set()
    listing = case / "points.txt"
    if listing.exists():
        for line in listing.read_text().splitlines():
            if line.strip() and not line.startswith("#"):
                # "name count", or "name count boundary" for a surface no level made (a volume's boundary, a
                # solid meshed again from a distance grid)
                name, count, *kind = line.split()
                counts[name] = int(count)
                if kind == ["boundary"]:
                    boundaries.add(name)
    for vtp in sorted(case.glob("*.vtp")):
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(str(vtp))
        reader.Update()
        poly = reader.GetOutput()
        n = poly.GetNumberOfPoints()
        if vtp.name not in counts:
            failures.append(f"{vtp}: no expected count in {listing}")
        elif n != counts[vtp.name]:
            failures.append(f"{vtp}: {n} points, expected {counts[vtp.name]}")
        # Curves carry their arclength; surfaces (polygons) do not.
        if poly.GetNumberOfPolys() == 0 and poly.GetPointData().GetArray("arclength") is None:
            failures.append(f"{vtp}: no point field 'arclength'")
        # Every kernel records what made the points: an L-system or substitution level, a hoisting generation.
        if vtp.name not in boundaries and all(poly.GetPointData().GetArray(f) is None for f in ("level", "generation")):
            failures.append(f"{vtp}: neither a 'level' nor a 'generation' point field")

        mapper = vtk.vtkPolyDataMapper()
        mapper.SetInputData(poly)
        actor = vtk.vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(0, 0, 0)
        renderer = vtk.vtkRenderer()
        renderer.SetBackground(1, 1, 1)
        renderer.AddActor(actor)
        window = vtk.vtkRenderWindow()
        window.SetOffScreenRendering(1)
        window.SetSize(200, 200)
        window.AddRenderer(renderer)
        renderer.ResetCamera()
        window.Render()
        grab = vtk.vtkWindowToImageFilter()
        grab.SetInput(window)
        grab.Update()
        image = grab.GetOutput()
        scalars = image.GetPointData().GetScalars()
        drawn = sum(1 for i in range(scalars.GetNumberOfTuples()) if min(scalars.GetTuple(i)[:3]) < 240)
        if drawn < 50:
            failures.append(f"{vtp}: rendered picture is blank ({drawn} non-background pixels)")
        writer = vtk.vtkPNGWriter()
        writer.SetFileName(str(pictures / f"{case.name}_{vtp.stem}.png"))
        writer.SetInputData(image)
        writer.Write()
        checked += 1

for f in failures:
    print(f)
print(f"{checked} files opened, {len(failures)} problems")
sys.exit(1 if failures or checked == 0 else 0)
