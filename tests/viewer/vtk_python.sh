#!/bin/sh
# Prints the command that runs a Python able to `import vtk` / `vtkmodules`, for the viewer tests:
#   $(tests/viewer/vtk_python.sh) tests/viewer/check_vtp.py GOLDEN PICTURES
# (unquoted on purpose: it may be a command with a PYTHONPATH= setting in front).
#   1. /usr/bin/python3 when it imports vtkmodules: python3-vtk9 (what libvtk9-dev brings), or
#      python3-paraview installed as a package (its VTK lives in the same dist-packages folder);
#   2. ParaView's pvpython, where there is one;
#   3. /usr/bin/python3 with the ParaView modules make deps unpacked (/opt/selfsim/paraview-python) on
#      PYTHONPATH: their VTK loads into Debian's Python 3.11 as well.
# Exits 1, printing nothing on stdout, when none of them works.
modules=${SELFSIM_PARAVIEW_PYTHON:-/opt/selfsim/paraview-python}
if /usr/bin/python3 -c "import vtkmodules.vtkIOXML" >/dev/null 2>&1; then
  echo /usr/bin/python3
elif command -v pvpython >/dev/null 2>&1 && pvpython -c "import vtkmodules.vtkIOXML" >/dev/null 2>&1; then
  command -v pvpython
elif [ -d "$modules/vtkmodules" ] &&
     PYTHONPATH="$modules" /usr/bin/python3 -c "import vtkmodules.vtkIOXML" >/dev/null 2>&1; then
  echo "env PYTHONPATH=$modules /usr/bin/python3"
else
  echo "$0: no Python here imports vtkmodules (install python3-vtk9 or python3-paraview)" >&2
  exit 1
fi
