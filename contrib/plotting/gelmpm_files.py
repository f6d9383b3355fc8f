"""Reading GelMPM's output from Python: statistics.csv, events.csv and the other CSV tables, the
surface profiles, the .pvd time series and the .vtu files they list (with VTK's XML reader, the
library ParaView uses).

Shared by the scripts in contrib/plotting and contrib/benchmarks (gelmpm_plot.py, gelmpm_sweep.py
among them); run them with /usr/bin/python3, which sees Debian's packages. The CSV readers need
nothing beyond Python (read_csv numpy: python3-numpy); read_vtu needs VTK's module vtkmodules, from
python3-vtk9 or ParaView's python3-paraview (`bash contrib/setup.sh --plotting` installs numpy and
matplotlib, and python3-vtk9 unless ParaView's is there). Each is imported where it is needed, so
that a script reading CSV files runs without VTK or numpy.
"""
import csv
import glob
import math
import os
import re
import sys
import xml.etree.ElementTree as ElementTree


def output_directory_problem(directory):
    """Why @p directory is not a GelMPM output directory (one that holds a statistics.csv), or
    None. A body-fitted peer's directory (statistics.csv without parameters.prm) counts as one."""
    if not os.path.exists(directory):
        return f"'{directory}' does not exist"
    if not os.path.isdir(directory):
        return f"'{directory}' is not a directory"
    if not os.path.isfile(os.path.join(directory, "statistics.csv")):
        return (f"'{directory}' is not a GelMPM output directory: it holds no statistics.csv (a run"
                " writes one into its 'Output/Directory')")
    return None


def read_rows(file_name):
    """The rows of a CSV file with a header row, each a dict of strings (for tables with text
    columns, such as events.csv). Lines whose first cell starts with '#' are comments."""
    if not os.path.isfile(file_name):
        sys.exit(f"missing {file_name}")
    with open(file_name, newline="") as stream:
        lines = (line for line in stream if not line.startswith("#"))
        return [row for row in csv.DictReader(lines)]


def number(text):
    """A cell as a float; an empty or non-numeric cell is NaN."""
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


def read_columns(file_name):
    """Columns of a CSV file with a header row, as a dict of lists of floats (empty cells: NaN),
    in the order of the header. Needs no numpy."""
    if not os.path.isfile(file_name):
        sys.exit(f"missing {file_name}")
    with open(file_name, newline="") as stream:
        rows = [row for row in csv.reader(stream) if row and not row[0].startswith("#")]
    if not rows:
        sys.exit(f"{file_name} is empty (no header row)")
    header = [name.strip() for name in rows[0]]
    columns = {name: [] for name in header}
    for row in rows[1:]:
        for k, name in enumerate(header):
            columns[name].append(number(row[k]) if k < len(row) else math.nan)
    return columns


def read_csv(file_name):
    """Columns of a CSV file with a header row, as a dict of float arrays (empty cells: NaN)."""
    import numpy as np
    return {name: np.array(values, dtype=float)
            for name, values in read_columns(file_name).items()}


def output_times(directory, series="particles"):
    """{output number: time in tau_d} of <series>.pvd in an output directory ({} without one).
    The surface profiles surface_<piece>-NNNNN.csv share the numbers of particles-NNNNN.vtu."""
    pvd = os.path.join(directory, series + ".pvd")
    if not os.path.isfile(pvd):
        return {}
    times = {}
    for data_set in ElementTree.parse(pvd).getroot().iter("DataSet"):
        found = re.search(r"-(\d+)\.p?vtu$", data_set.get("file", ""))
        if found:
            times[int(found.group(1))] = float(data_set.get("timestep"))
    return dict(sorted(times.items()))


def surface_profiles(directory, piece):
    """[(output number, path)] of the surface profiles surface_<piece>-NNNNN.csv, by number."""
    found = []
    for path in glob.glob(os.path.join(directory, f"surface_{glob.escape(piece)}-*.csv")):
        match = re.search(r"-(\d+)\.csv$", path)
        if match:
            found.append((int(match.group(1)), path))
    return sorted(found)


def surface_pieces(directory):
    """The pieces that have surface profiles in @p directory."""
    names = set()
    for path in glob.glob(os.path.join(directory, "surface_*-*.csv")):
        match = re.match(r"surface_(.+)-\d+\.csv$", os.path.basename(path))
        if match:
            names.add(match.group(1))
    return sorted(names)


def read_pvd(directory, series="particles"):
    """(time, path) of every data set of <series>.pvd in a GelMPM output directory, by time."""
    pvd = os.path.join(directory, series + ".pvd")
    if not os.path.isfile(pvd):
        switch = {"particles": "Output/Write particles", "grid": "Output/Write grid",
                  "mode": "Stability/Write mode"}.get(series, "the output")
        sys.exit(f"missing {pvd} (run with {switch} = true)")
    return sorted((float(data_set.get("timestep")), os.path.join(directory, data_set.get("file")))
                  for data_set in ElementTree.parse(pvd).getroot().iter("DataSet"))


def vtk_reader():
    """VTK's XML reader of unstructured grids and its conversion to numpy, imported on first use."""
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
    return vtkXMLUnstructuredGridReader, vtk_to_numpy


def read_vtu(file_name, with_cells=False):
    """(points (n x 3), {point array name: array}[, cells as arrays of point ids]) of a .vtu file."""
    import numpy as np
    vtkXMLUnstructuredGridReader, vtk_to_numpy = vtk_reader()
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
