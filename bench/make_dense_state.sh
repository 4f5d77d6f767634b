#!/usr/bin/env bash
# Makes bench/data/dense_N100000.data: the peers' 100k settle lattice run by comminute until the bed
# is at rest (kinetic energy < 1e-10 J per particle), written as a LAMMPS-style data file that all
# codes read. Deterministic for a given thread count; ~5 min on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p bench/data
build/bench/bench_make_dense_state bench/cases/settle_100000.toml bench/data/dense_N100000.data 40000 1e-10
