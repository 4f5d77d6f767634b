#!/usr/bin/python3
"""Writes the 8 cases of the HPGR texture study from the template hpgr_texture.toml and runs
them with `comminute run`, one after another (issue 12 point 6; README.md).

Cases: relative grain strength f_rel of the target phase in {0.5, 1, 2, 4, 6, 13.21} against the
matrix (1), at the mean target composition 0.233 of the texture; and two homogeneous controls
whose matrix and grains have one strength, the mean phase weight (1 - 0.233) + 0.233 f_rel of the
f_rel = 4 and of the f_rel = 13.21 case. Each case goes to OUT/<name>/case.toml and its outputs
to OUT/<name>/output.

usage: examples/hpgr_texture/sweep.py [--out out/hpgr_texture] [--comminute comminute]
       [--threads 1] [--write-only] [--cases NAME ...]"""
import argparse
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
TEMPLATE = os.path.join(HERE, "hpgr_texture.toml")
MEAN_TARGET = 0.233  # mean target composition of the study (the texture's volume fraction)


def cases():
    """(name, matrix strength, target strength) of the 8 cases."""
    out = [(f"frel_{f:g}", 1.0, f) for f in (0.5, 1.0, 2.0, 4.0, 6.0, 13.21)]
    for f in (4.0, 13.21):
        w = (1 - MEAN_TARGET) * 1.0 + MEAN_TARGET * f  # eq. C2 at the mean composition
        out.append((f"homogeneous_{f:g}", w, w))
    return out


def case_text(template, matrix, target):
    """The template with its three '@sweep' lines set to the given phase strengths."""
    rules = [(r"^relative_strength = \[[^\]]*\]( *# @sweep criterion.*)$",
              f"relative_strength = [{matrix!r}, {target!r}]\\1"),
             (r"^relative_strength = [0-9.eE+-]+( *# @sweep matrix.*)$",
              f"relative_strength = {matrix!r}\\1"),
             (r"^relative_strength = [0-9.eE+-]+( *# @sweep target.*)$",
              f"relative_strength = {target!r}\\1")]
    text = template
    for pattern, repl in rules:
        text, n = re.subn(pattern, repl, text, flags=re.M)
        if n != 1:
            sys.exit(f"{TEMPLATE}: expected one line matching {pattern!r}, found {n}")
    return text


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="out/hpgr_texture", help="folder of the cases")
    ap.add_argument("--comminute", default="comminute", help="the comminute executable")
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--write-only", action="store_true", help="write the cases, run nothing")
    ap.add_argument("--cases", nargs="*", help="run only these (names as in the list)")
    args = ap.parse_args()
    with open(TEMPLATE) as f:
        template = f.read()
    selected = cases()
    if args.cases:
        names = [c[0] for c in selected]
        unknown = [n for n in args.cases if n not in names]
        if unknown:
            sys.exit(f"unknown case(s) {unknown}; the cases are {names}")
        selected = [c for c in selected if c[0] in args.cases]
    for name, matrix, target in selected:
        folder = os.path.join(args.out, name)
        os.makedirs(folder, exist_ok=True)
        path = os.path.join(folder, "case.toml")
        with open(path, "w") as f:
            f.write(case_text(template, matrix, target))
        print(f"{name}: matrix {matrix:g}, target {target:g} -> {path}", flush=True)
        if args.write_only:
            continue
        cmd = [args.comminute, "run", path, "-o", os.path.join(folder, "output"),
               "--threads", str(args.threads)]
        t0 = time.time()
        start = os.times()
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
        end = os.times()
        print(f"  {time.time() - t0:.1f} s wall, "
              f"{end.children_user - start.children_user:.1f} s user CPU", flush=True)


if __name__ == "__main__":
    main()
