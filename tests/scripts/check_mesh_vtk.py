#!/usr/bin/env python3
"""Reads the walls.pvd series of a mesh wall back with VTK's XML reader and compares the points
(the moved mesh) and the wear_depth cell field with expected.json (17 significant digits: exact).

usage: check_mesh_vtk.py <output-dir> <expected.json>; exit 0 equal, 1 mismatch, 77 no VTK."""
import json
import os
import sys
import xml.etree.ElementTree as ET

try:
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:
    print("python3-vtk9 is not installed")
    sys.exit(77)

out, expected_path = sys.argv[1], sys.argv[2]
expected = json.load(open(expected_path))
root = ET.parse(os.path.join(out, "walls.pvd")).getroot()
sets = [(float(d.get("timestep")), os.path.join(out, d.get("file"))) for d in root.iter("DataSet")]
bad = []
if len(sets) != len(expected):
    bad.append(f"{len(sets)} snapshots, expected {len(expected)}")
for (t, path), e in zip(sets, expected):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    if t != e["time"]:
        bad.append(f"{path}: time {t} != {e['time']}")
    pts = vtk_to_numpy(data.GetPoints().GetData()).tolist()
    if pts != e["points"]:
        bad.append(f"{path}: points differ: {pts} != {e['points']}")
    wear = data.GetCellData().GetArray("wear_depth")
    if wear is None:
        bad.append(f"{path}: no wear_depth cell array")
    elif vtk_to_numpy(wear).tolist() != e["wear"]:
        bad.append(f"{path}: wear_depth {vtk_to_numpy(wear).tolist()} != {e['wear']}")
for b in bad:
    print(b)
sys.exit(1 if bad else 0)
