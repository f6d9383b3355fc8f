"""Reading GelMPM's output from Python: statistics.csv and other CSV tables, the .pvd time series
and the .vtu files they list (with VTK's XML reader, the library ParaView uses).

Shared by the scripts in contrib/plotting and contrib/benchmarks; run them with /usr/bin/python3,
which sees Debian's python3-numpy and VTK's module vtkmodules, from python3-vtk9 or ParaView's
python3-paraview (`bash contrib/setup.sh --plotting` installs the first unless the second is there).
"""
import os
import sys
import xml.etree.ElementTree as ElementTree

import numpy as np

try:
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
except ImportError:  # older VTK layout
    try:
        from vtk import vtkXMLUnstructuredGridReader
        from vtk.util.numpy_support import vtk_to_numpy
    except ImportError:
        sys.exit("needs VTK's Python module (Debian: python3-vtk9, or ParaView's python3-paraview);"
                 " run with /usr/bin/python3")


def read_csv(file_name):
    """Columns of a CSV file with a header row, as a dict of float arrays (empty cells: NaN)."""
    if not os.path.isfile(file_name):
        sys.exit(f"missing {file_name}")
    data = np.genfromtxt(file_name, delimiter=",", names=True, dtype=float)
    return {name: np.atleast_1d(data[name]) for name in data.dtype.names}


def read_pvd(directory, series="particles"):
    """(time, path) of every data set of <series>.pvd in a GelMPM output directory, by time."""
    pvd = os.path.join(directory, series + ".pvd")
    if not os.path.isfile(pvd):
        switch = {"particles": "Output/Write particles", "grid": "Output/Write grid",
                  "mode": "Stability/Write mode"}.get(series, "the output")
        sys.exit(f"missing {pvd} (run with {switch} = true)")
    return sorted((float(data_set.get("timestep")), os.path.join(directory, data_set.get("file")))
                  for data_set in ElementTree.parse(pvd).getroot().iter("DataSet"))


def read_vtu(file_name, with_cells=False):
    """(points (n x 3), {point array name: array}[, cells as arrays of point ids]) of a .vtu file."""
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(file_name)
    reader.Update()
    grid = reader.GetOutput()
    if grid.GetNumberOfPoints() == 0:
        sys.exit(f"no points in {file_name}")
    points = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
    data = grid.GetPointData()
    arrays = {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i))
              for i in range(data.GetNumberOfArrays())}
    if not with_cells:
        return points, arrays
    cells = [[grid.GetCell(k).GetPointId(v) for v in range(grid.GetCell(k).GetNumberOfPoints())]
             for k in range(grid.GetNumberOfCells())]
    return points, arrays, np.array(cells)
