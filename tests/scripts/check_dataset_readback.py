#!/usr/bin/env python3
"""Reads a dataset comminute wrote for ParaView (.vts structured grid or .vtp lines) back with
VTK's own XML reader and compares every value with expected.json (17 significant digits, so the
comparison is exact): points, cell counts or line connectivity, every cell array, TimeValue.

usage: check_dataset_readback.py <file.vts|file.vtp> <expected.json>
exit 0: all equal; 1: a mismatch (printed); 77: python3-vtk9 missing (skip)."""
import json
import sys

try:
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:
    print("python3-vtk9 is not installed")
    sys.exit(77)

path, expected_path = sys.argv[1], sys.argv[2]
with open(expected_path) as f:
    exp = json.load(f)
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)


errors = []
reader = vtk.vtkXMLStructuredGridReader() if path.endswith(".vts") else vtk.vtkXMLPolyDataReader()
reader.AddObserver("ErrorEvent", lambda o, e: errors.append(e))
reader.SetFileName(path)
reader.Update()
check(not errors, f"reader reported errors: {errors}")
data = reader.GetOutput()
pts = vtk_to_numpy(data.GetPoints().GetData()).tolist() if data.GetPoints() else []
check(pts == exp["points"], "points differ")
if path.endswith(".vts"):
    dims = list(data.GetDimensions())
    check(dims == [c + 1 for c in exp["cells"]], f"dimensions {dims} vs cells {exp['cells']}")
    check(data.GetNumberOfCells() == exp["cells"][0] * exp["cells"][1] * exp["cells"][2],
          "cell count differs")
else:
    lines = []
    ids = vtk.vtkIdList()
    for c in range(data.GetNumberOfCells()):
        check(data.GetCellType(c) == vtk.VTK_LINE, f"cell {c} is not a line")
        data.GetCellPoints(c, ids)
        lines.append([ids.GetId(k) for k in range(ids.GetNumberOfIds())])
    check(lines == exp["lines"], "lines differ")
cd = data.GetCellData()
for name, values in exp["arrays"].items():
    arr = cd.GetArray(name)
    check(arr is not None, f"cell array {name} missing")
    if arr is not None:
        got = vtk_to_numpy(arr).ravel().tolist()
        check(got == values, f"cell array {name} differs: {got[:6]} vs {values[:6]}")
t = data.GetFieldData().GetArray("TimeValue")
check(t is not None and t.GetValue(0) == exp["time"], "TimeValue differs")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
