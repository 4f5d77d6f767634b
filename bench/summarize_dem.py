#!/usr/bin/env python3
"""Table of bench/run_benchmarks.sh logs: median particle-steps/s per code, case, threads/ranks,
and the ratio comminute / peer. usage: summarize_dem.py LOGDIR"""
import glob, os, re, statistics, sys
from collections import defaultdict

logdir = sys.argv[1]
rows = defaultdict(list)  # (case, code, np) -> [(pps, contacts, rss_mb, repetition)]
for path in glob.glob(os.path.join(logdir, "*.log")):
    m = re.match(r"(comminute|liggghts|lammps)_(\w+?)_p(\d+)_r(\d+)\.log$", os.path.basename(path))
    if not m:
        continue
    code, case, np_, rep = m.group(1), m.group(2), int(m.group(3)), int(m.group(4))
    txt = open(path, errors="replace").read()
    if code == "comminute":
        mm = re.search(r"N=(\d+) .*particle_steps_per_s=([0-9.e+]+) contacts=(\d+).*peak_rss_MB=(\d+)", txt)
        if not mm:
            continue
        rows[(case, code, np_)].append((float(mm.group(2)), int(mm.group(3)), float(mm.group(4)), rep))
    else:
        loops = re.findall(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms", txt)
        if len(loops) < 2:
            continue
        t, _, s, n = loops[-1]
        th = [l.split() for l in txt.splitlines() if re.match(r"^\s+\d+\s+\d+\s+\S+\s+\S+\s*$", l)]
        contacts = int(float(th[-1][3])) if th else -1
        rss = -1.0
        if os.path.exists(path + ".time"):
            r = re.search(r"Maximum resident set size \(kbytes\): (\d+)", open(path + ".time").read())
            rss = int(r.group(1)) / 1024 if r else -1.0
        rows[(case, code, np_)].append((int(n) * int(s) / float(t), contacts, rss, rep))

def med(key):
    v = rows.get(key)
    return statistics.median(x[0] for x in v) if v else None

def per_rep(a, b):
    """rate a / rate b repetition by repetition (a median of three can hide a spread across a floor)"""
    ra, rb = ({x[3]: x[0] for x in rows.get(k, [])} for k in (a, b))
    return ", ".join(f"{ra[k] / rb[k]:.2f}" for k in sorted(ra) if k in rb) or "–"

machine = os.path.join(logdir, "machine.txt")
if os.path.exists(machine):
    model, cores, when, load = (open(machine).read().splitlines() + ["?"] * 4)[:4]
    print(f"Machine: {model}, {cores} cores; started {when}, load average {load}.\n")
print("| case | threads/ranks | comminute M p-steps/s | LIGGGHTS | LAMMPS | comminute / LIGGGHTS | comminute / LAMMPS | contacts at end (comminute / LIGGGHTS / LAMMPS) | peak RSS MB (comminute / LIGGGHTS / LAMMPS) |")
print("|---|---|---|---|---|---|---|---|---|")
for case in ("settle20k", "settle100k", "dense100k", "drum20k"):
    for np_ in (1, 2):
        c, l, a = med((case, "comminute", np_)), med((case, "liggghts", np_)), med((case, "lammps", np_))
        if c is None:
            continue
        f = lambda x: f"{x / 1e6:.2f}" if x else "–"
        r = lambda x: f"{c / x:.2f}" if x else "–"
        def last(code, i):
            v = rows.get((case, code, np_))
            return f"{v[-1][i]:.0f}" if v else "–"
        print(f"| {case} | {np_} | {f(c)} | {f(l)} | {f(a)} | {r(l)} | {r(a)} | "
              f"{last('comminute', 1)} / {last('liggghts', 1)} / {last('lammps', 1)} | "
              f"{last('comminute', 2)} / {last('liggghts', 2)} / {last('lammps', 2)} |")
for case in ("settle20k", "settle100k", "dense100k", "drum20k"):
    one, two = med((case, "comminute", 1)), med((case, "comminute", 2))
    if one and two:
        print(f"\ncomminute {case}: two threads / one thread = {two / one:.2f}")
    if one:
        print(f"comminute {case} by repetition: one thread / LIGGGHTS {per_rep((case, 'comminute', 1), (case, 'liggghts', 1))}; "
              f"/ LAMMPS {per_rep((case, 'comminute', 1), (case, 'lammps', 1))}; "
              f"two threads / one thread {per_rep((case, 'comminute', 2), (case, 'comminute', 1))}")
