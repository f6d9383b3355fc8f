#!/usr/bin/python3
"""Print one .vtu file as ParaView reads it, as plain text for the tests (tests/vtu_reader.h).

    /usr/bin/python3 tests/vtu_dump.py <file.vtu>

Reads the file with VTK's XML reader (vtkXMLUnstructuredGridReader, the reader ParaView uses),
through the Python package vtkmodules, which Debian's python3-vtk9 and ParaView's own
python3-paraview both provide (the two conflict; either will do). Prints:

    points <n>
    <x> <y> <z>                         one line per point
    cells <m>
    <k> <id_1> ... <id_k>               one line per cell: its number of points, their ids
    array <components> <tuples> <name>  one block per point-data array, in the file's order
    <v_1> ... <v_components>            one line per tuple

Numbers are Python's shortest round-trip form of the values read (nan and inf as such).
Exit status 1 with a message on stderr when the file cannot be read.
"""
import os
import sys

try:
    from vtkmodules.vtkCommonCore import vtkIdList
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
except ImportError:
    sys.exit("vtu_dump.py: needs VTK's Python package vtkmodules "
             "(Debian: python3-vtk9, or python3-paraview with ParaView)")


def read(file_name):
    """The unstructured grid in file_name, or exit 1 when it cannot be read."""
    if not os.path.isfile(file_name):
        sys.exit(f"vtu_dump.py: {file_name}: no such file")
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(file_name)
    reader.Update()
    if reader.GetErrorCode() != 0 or reader.GetOutput() is None:
        sys.exit(f"vtu_dump.py: {file_name}: VTK cannot read it")
    return reader.GetOutput()


def dump(grid, out):
    """Write points, cells and point-data arrays of grid to out in the form above."""
    n_points = grid.GetNumberOfPoints()
    out.write(f"points {n_points}\n")
    for k in range(n_points):
        out.write(" ".join(map(repr, grid.GetPoint(k))) + "\n")

    n_cells = grid.GetNumberOfCells()
    out.write(f"cells {n_cells}\n")
    ids = vtkIdList()
    for k in range(n_cells):
        grid.GetCellPoints(k, ids)
        n = ids.GetNumberOfIds()
        out.write(" ".join([str(n)] + [str(ids.GetId(v)) for v in range(n)]) + "\n")

    data = grid.GetPointData()
    for a in range(data.GetNumberOfArrays()):
        array = data.GetArray(a)
        if array is None:  # not a numeric array (a string array): the tests read none
            continue
        n_components = array.GetNumberOfComponents()
        n_tuples = array.GetNumberOfTuples()
        out.write(f"array {n_components} {n_tuples} {array.GetName()}\n")
        for i in range(n_tuples):
            out.write(" ".join(map(repr, array.GetTuple(i))) + "\n")


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: vtu_dump.py <file.vtu>")
    dump(read(sys.argv[1]), sys.stdout)


if __name__ == "__main__":
    main()
