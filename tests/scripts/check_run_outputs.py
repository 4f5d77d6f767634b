#!/usr/bin/env python3
"""Checks the outputs of a `comminute run` by reading them back with VTK's own reader:
every collection entry is a complete, readable file; the last particle snapshot equals the
final checkpoint's particle state exactly (ids, positions, radii, masses, velocities, angular
velocities, forces, materials); the snapshot agrees with the time-series row of the same time
(particle count exactly, kinetic energy to round-off) and the wall snapshot's forces equal the
row's wall-force columns exactly.

usage: check_run_outputs.py <output-dir> <expected-snapshot-count>
       check_run_outputs.py <output-dir> killed
The second form checks what a run killed with SIGKILL left: every listed snapshot complete and
readable, every complete CSV row consistent (no checkpoint comparison, any snapshot count).
exit 0 ok, 1 mismatch, 77 python3-vtk9 or python3-h5py missing (skip)."""
import csv
import os
import sys
import xml.etree.ElementTree as ET

try:
    import h5py
    import numpy as np
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError as e:
    print(f"skip: {e}")
    sys.exit(77)

failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
    return cond


def read_vtp(path):
    errors = []
    reader = vtk.vtkXMLPolyDataReader()
    reader.AddObserver("ErrorEvent", lambda o, e: errors.append(e))
    reader.GetExecutive().AddObserver("ErrorEvent", lambda o, e: errors.append(e))
    reader.SetFileName(path)
    reader.Update()
    check(not errors, f"{path}: VTK reported errors")
    return reader.GetOutput()


def collection(path):
    root = ET.parse(path).getroot()
    base = os.path.dirname(path)
    return [(float(d.get("timestep")), os.path.join(base, d.get("file"))) for d in root.iter("DataSet")]


def checkpoint_entries(path):
    """Archive entries by name -> raw bytes (see io/checkpoint.hpp)."""
    out = {}
    with h5py.File(path, "r") as f:
        for ds in f["entries"].values():
            name = ds.attrs["name"]
            name = name.decode() if isinstance(name, bytes) else str(name)
            out[name] = ds[()].tobytes()
        info = {k: f.attrs[k] for k in ("time", "step", "threads")}
    return out, info


def main():
    out, killed = sys.argv[1], sys.argv[2] == "killed"
    particles = collection(os.path.join(out, "particles.pvd"))
    walls = collection(os.path.join(out, "walls.pvd"))
    if not killed:
        n_expected = int(sys.argv[2])
        check(len(particles) == n_expected, f"particles.pvd lists {len(particles)} snapshots, expected {n_expected}")
    check(len(particles) > 0, "no snapshot listed")
    # A kill between the particle and the wall snapshot of one time leaves one wall entry less.
    check(len(particles) - len(walls) in ((0, 1) if killed else (0,)),
          "walls.pvd and particles.pvd differ in length")
    times = [t for t, _ in particles]
    check(times == sorted(times) and len(set(times)) == len(times), "snapshot times not increasing")
    with open(os.path.join(out, "timeseries.csv")) as f:
        text = f.read()
    if killed and not text.endswith("\n"):
        text = text[: text.rfind("\n") + 1]  # the row being written when the run was killed
    rows = list(csv.reader(text.splitlines()))
    header, rows = rows[0], [[float(x) for x in r] for r in rows[1:]]
    check(all(len(r) == len(header) for r in rows), "a complete CSV row has a wrong column count")
    col = {name: k for k, name in enumerate(header)}
    by_time = {r[0]: r for r in rows}
    check([r[0] for r in rows] == sorted(r[0] for r in rows), "CSV times not increasing")

    for t, path in particles:
        pd = read_vtp(path)
        check(pd.GetNumberOfPoints() > 0, f"{path}: no points")
        row = by_time.get(t)
        if row is None:  # cadences that do not coincide (the killed-run case) compare nothing
            check(killed, f"no CSV row at snapshot time {t!r}")
            continue
        check(pd.GetNumberOfPoints() == row[col["particles [-]"]], f"{path}: count differs from CSV")
        pdat = pd.GetPointData()
        m = vtk_to_numpy(pdat.GetArray("mass"))
        v = vtk_to_numpy(pdat.GetArray("velocity"))
        ke = 0.5 * float(np.sum(m * np.sum(v * v, axis=1)))
        csv_ke = row[col["kinetic_translational [J]"]]
        # Same terms summed in another order: agreement to ~N ulp, 1e-12 relative is ample.
        check(abs(ke - csv_ke) <= 1e-12 * max(abs(csv_ke), 1e-300),
              f"{path}: kinetic energy {ke!r} vs CSV {csv_ke!r}")
        ids = vtk_to_numpy(pdat.GetArray("id"))
        check(len(set(ids.tolist())) == len(ids), f"{path}: repeated ids")

    for (t, path) in walls:
        wd = read_vtp(path)
        fd = wd.GetFieldData()
        names = fd.GetAbstractArray("wall_name")
        names = [names.GetValue(i) for i in range(names.GetNumberOfValues())]
        forces = vtk_to_numpy(fd.GetArray("wall_force"))
        row = by_time.get(t)
        if row is None:
            continue
        for k, name in enumerate(names):
            csv_f = [row[col[f"{name}_F{a} [N]"]] for a in "xyz"]
            check(forces[k].tolist() == csv_f, f"{path}: force of wall '{name}' {forces[k]} != CSV {csv_f}")

    if killed:
        return report(particles, rows, None)
    # The last snapshot is the final state, which is also the final checkpoint.
    entries, info = checkpoint_entries(os.path.join(out, "checkpoint.h5"))
    t_last, last = particles[-1]
    check(float(info["time"]) == t_last, f"checkpoint time {info['time']!r} != last snapshot {t_last!r}")
    pdat = read_vtp(last).GetPointData()
    pts = vtk_to_numpy(read_vtp(last).GetPoints().GetData())

    def state(name, dtype, comps):
        a = np.frombuffer(entries["particles/" + name], dtype=dtype)
        return a.reshape(-1, comps) if comps > 1 else a

    pairs = [("id", "id", "<u8", 1), ("radius", "radius", "<f8", 1), ("mass", "mass", "<f8", 1),
             ("v", "velocity", "<f8", 3), ("w", "angular_velocity", "<f8", 3),
             ("f", "force", "<f8", 3), ("material", "material", "<u2", 1)]
    check(np.array_equal(pts, state("x", "<f8", 3)), f"{last}: positions differ from the checkpoint")
    for entry, array, dtype, comps in pairs:
        got = vtk_to_numpy(pdat.GetArray(array))
        check(np.array_equal(got, state(entry, dtype, comps)), f"{last}: '{array}' differs from the checkpoint")
    check(np.array_equal(vtk_to_numpy(pdat.GetArray("diameter")), 2 * state("radius", "<f8", 1)),
          f"{last}: diameter is not 2 radius")

    return report(particles, rows, f"last snapshot ({pts.shape[0]} particles) equals the checkpoint at t = {t_last!r} s")


def report(particles, rows, extra):
    for f in failures:
        print("MISMATCH:", f)
    if not failures:
        print(f"ok: {len(particles)} particle snapshots, {len(rows)} CSV rows read back and consistent"
              + (f"; {extra}" if extra else ""))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
