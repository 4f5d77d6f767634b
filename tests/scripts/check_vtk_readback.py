#!/usr/bin/env python3
"""Reads comminute's ParaView output back with VTK's own XML reader and compares every value
with what the writer was given (expected.json, written by the producer with 17 significant
digits so that the comparison is exact).

usage: check_vtk_readback.py <output-dir> <expected.json>
exit 0: all equal; 1: a mismatch (printed); 77: python3-vtk9 missing (skip)."""
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

failures = []


def check(cond, what):
    if not cond:
        failures.append(what)


class ErrorObserver:
    """Collects VTK error events (a reader that fails only prints otherwise)."""

    def __init__(self):
        self.errors = []

    def __call__(self, obj, event):
        self.errors.append(event)


def read_vtp(path):
    reader = vtk.vtkXMLPolyDataReader()
    obs = ErrorObserver()
    reader.AddObserver("ErrorEvent", obs)
    reader.GetExecutive().AddObserver("ErrorEvent", obs)
    reader.SetFileName(path)
    reader.Update()
    check(not obs.errors, f"{path}: VTK reported errors")
    return reader.GetOutput()


def read_pvd(path):
    root = ET.parse(path).getroot()
    check(root.get("type") == "Collection", f"{path}: not a Collection")
    base = os.path.dirname(path)
    return [(float(d.get("timestep")), os.path.join(base, d.get("file")))
            for d in root.iter("DataSet")]


def array(data, name):
    a = data.GetArray(name)
    check(a is not None, f"array '{name}' missing")
    return None if a is None else vtk_to_numpy(a)


def check_particles(series, expected):
    check(len(series) == len(expected), f"particles.pvd lists {len(series)} files, expected {len(expected)}")
    for (t, path), exp in zip(series, expected):
        check(t == exp["time"], f"{path}: time {t!r} != {exp['time']!r}")
        pd = read_vtp(path)
        n = len(exp["id"])
        check(pd.GetNumberOfPoints() == n, f"{path}: {pd.GetNumberOfPoints()} points, expected {n}")
        check(pd.GetNumberOfVerts() == n, f"{path}: {pd.GetNumberOfVerts()} vertex cells, expected {n}")
        if pd.GetNumberOfPoints() != n:
            continue
        pts = vtk_to_numpy(pd.GetPoints().GetData())
        check(pts.tolist() == exp["position"], f"{path}: positions differ")
        point_data = pd.GetPointData()
        ids = array(point_data, "id")
        check(ids is not None and [int(i) for i in ids] == exp["id"], f"{path}: ids differ")
        for name in ("radius", "diameter", "mass", "velocity", "angular_velocity", "force",
                     "material"):
            a = array(point_data, name)
            check(a is not None and a.tolist() == exp[name], f"{path}: '{name}' differs")
        for name, values in exp["fields"].items():
            a = array(point_data, name)
            check(a is not None and a.tolist() == values, f"{path}: field '{name}' differs")
        check(point_data.GetNumberOfArrays() == 8 + len(exp["fields"]),
              f"{path}: {point_data.GetNumberOfArrays()} point arrays")
        tv = array(pd.GetFieldData(), "TimeValue")
        check(tv is not None and tv.tolist() == [exp["time"]], f"{path}: TimeValue differs")


def check_walls(series, expected):
    check(len(series) == len(expected), f"walls.pvd lists {len(series)} files, expected {len(expected)}")
    for (t, path), exp in zip(series, expected):
        check(t == exp["time"], f"{path}: time {t!r} != {exp['time']!r}")
        pd = read_vtp(path)
        check(pd.GetNumberOfPoints() == exp["points"], f"{path}: {pd.GetNumberOfPoints()} points")
        check(pd.GetNumberOfPolys() == exp["triangles"], f"{path}: {pd.GetNumberOfPolys()} triangles")
        fd = pd.GetFieldData()
        names = fd.GetAbstractArray("wall_name")
        got = [names.GetValue(i) for i in range(names.GetNumberOfValues())] if names else None
        check(got == exp["names"], f"{path}: wall names {got} != {exp['names']}")
        for name in ("wall_force", "wall_torque"):
            a = array(fd, name)
            check(a is not None and a.tolist() == exp[name], f"{path}: '{name}' differs")
        cell_index = array(pd.GetCellData(), "wall_index")
        check(cell_index is not None and cell_index.tolist() == exp["cell_wall_index"],
              f"{path}: cell wall_index differs")
        cell_force = array(pd.GetCellData(), "force")
        check(cell_force is not None and
              cell_force.tolist() == [exp["wall_force"][k] for k in exp["cell_wall_index"]],
              f"{path}: cell force differs")


def main():
    out, expected_path = sys.argv[1], sys.argv[2]
    with open(expected_path) as f:
        expected = json.load(f)
    check_particles(read_pvd(os.path.join(out, "particles.pvd")), expected["particles"])
    if "walls" in expected:
        check_walls(read_pvd(os.path.join(out, "walls.pvd")), expected["walls"])
    for f in failures:
        print("MISMATCH:", f)
    if not failures:
        n = sum(len(e["id"]) for e in expected["particles"])
        print(f"ok: {len(expected['particles'])} particle snapshots ({n} particles), "
              f"{len(expected.get('walls', []))} wall snapshots read back exactly")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
