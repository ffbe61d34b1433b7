#!/usr/bin/python3
"""Report what VTK itself and Python's json module read from sphFoam output.

The unit tests (tests/unit/io/vtk*.C) run this with /usr/bin/python3, whose
python3-vtk9 is an independent reader: if it reports the numbers the C++
side wrote, ParaView (same VTK readers) will show them.

    vtkInspect.py vtp    FILE      a .vtp file, read by vtkXMLPolyDataReader
    vtkInspect.py series FILE      a .series file, read by json.load

Output is one record per line, whitespace-separated, keyword first.  Floats
are printed with repr(), the shortest text that reads back to the same
double, so the tests can compare exactly.

vtp:
    points N / verts N / lines N
    point I X Y Z              for every point
    line I A B                 for every line cell
    time T                     FieldData TimeValue ("time none" if absent)
    pointarray NAME TYPE NCOMP NTUPLES, then value NAME I C0 [C1 C2] per tuple
    cellarray  NAME TYPE NCOMP NTUPLES, then value NAME I ... per tuple
series:
    version V / files N
    file NAME TIME EXISTS      EXISTS: 1 if NAME exists beside the series file
"""

import json
import os
import sys


def xml_type(array):
    """The VTK XML type name of an array (Float64, Int32, ...)."""
    import vtkmodules.vtkCommonCore as core

    bits = 8 * array.GetDataTypeSize()
    kind = array.GetDataType()
    if kind in (core.VTK_FLOAT, core.VTK_DOUBLE):
        return "Float%d" % bits
    unsigned = (core.VTK_UNSIGNED_CHAR, core.VTK_UNSIGNED_SHORT,
                core.VTK_UNSIGNED_INT, core.VTK_UNSIGNED_LONG,
                core.VTK_UNSIGNED_LONG_LONG)
    return ("UInt%d" if kind in unsigned else "Int%d") % bits


def number(value):
    return repr(float(value))


def print_arrays(keyword, data):
    for a in range(data.GetNumberOfArrays()):
        array = data.GetArray(a)
        if array is None:
            continue
        name = array.GetName()
        ncomp = array.GetNumberOfComponents()
        ntuples = array.GetNumberOfTuples()
        print(keyword, name, xml_type(array), ncomp, ntuples)
        for i in range(ntuples):
            values = [number(array.GetComponent(i, c)) for c in range(ncomp)]
            print("value", name, i, *values)


def inspect_vtp(path):
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

    if not os.path.isfile(path):
        sys.exit("no such file: " + path)

    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    if reader.GetErrorCode() != 0:
        sys.exit("vtkXMLPolyDataReader failed on " + path)
    poly = reader.GetOutput()

    print("points", poly.GetNumberOfPoints())
    print("verts", poly.GetNumberOfVerts())
    print("lines", poly.GetNumberOfLines())

    for i in range(poly.GetNumberOfPoints()):
        print("point", i, *[number(x) for x in poly.GetPoint(i)])

    lines = poly.GetLines()
    ids = None
    if lines is not None:
        from vtkmodules.vtkCommonCore import vtkIdList
        ids = vtkIdList()
        for i in range(lines.GetNumberOfCells()):
            lines.GetCellAtId(i, ids)
            print("line", i, *[ids.GetId(k) for k in range(ids.GetNumberOfIds())])

    time = poly.GetFieldData().GetArray("TimeValue")
    if time is None:
        print("time none")
    else:
        print("time", number(time.GetComponent(0, 0)))

    print_arrays("pointarray", poly.GetPointData())
    print_arrays("cellarray", poly.GetCellData())


def inspect_series(path):
    with open(path) as f:
        series = json.load(f)   # raises, so exits non-zero, on invalid JSON

    folder = os.path.dirname(path)
    print("version", series["file-series-version"])
    print("files", len(series["files"]))
    for entry in series["files"]:
        exists = os.path.isfile(os.path.join(folder, entry["name"]))
        print("file", entry["name"], number(entry["time"]), int(exists))


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in ("vtp", "series"):
        sys.exit(__doc__)
    if sys.argv[1] == "vtp":
        inspect_vtp(sys.argv[2])
    else:
        inspect_series(sys.argv[2])


if __name__ == "__main__":
    main()
