#!/usr/bin/env bash
# Instructions the DEM step executes, counted by valgrind's callgrind: a number that, unlike a
# timing, is the same on a busy machine and on a quiet one (the same binary, case and steps give
# the same count), so a change to the contact loops can be judged on one run. It is not a speed:
# on the Intel machine of bench/RESULTS.md ("Twelfth stop") 18 % fewer instructions ran only about 4 %
# faster. Prints the instructions inside Simulation::run (set-up excluded), per particle-step, and
# the functions that execute the most.
#
#   bench/instruction_count.sh                                  # dense 100k, 20 steps, build/
#   BUILD=build STEPS=20 CASE=bench/cases/drum_20000.toml bench/instruction_count.sh
#
# One thread; about 45 s for 20 steps of the dense bed (valgrind runs ~50x slower than native).
# Installs valgrind if missing (scripts/install-deps); the dense case needs
# bench/data/dense_N100000.data (bench/make_dense_state.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
COMMINUTE_PEERS=1 scripts/install-deps
BUILD=${BUILD:-build}
STEPS=${STEPS:-20}
CASE=${CASE:-bench/cases/dense_100000.toml}
OUT=$(mktemp /tmp/callgrind.XXXXXX)
trap 'rm -f "$OUT"' EXIT
bin="$BUILD/bench/bench_dem_throughput"
[ -x "$bin" ] || {
  echo "instruction_count.sh: $bin not built (ninja -C $BUILD bench_dem_throughput)" >&2
  exit 1
}
line=$(OMP_NUM_THREADS=1 valgrind --tool=callgrind --callgrind-out-file="$OUT" --collect-atstart=no \
  "--toggle-collect=comminute::Simulation::run(*" "$bin" "$CASE" 0 "$STEPS" 2>/dev/null | tail -1)
n=$(sed -n 's/.*N=\([0-9]*\).*/\1/p' <<<"$line")
total=$(callgrind_annotate "$OUT" 2>/dev/null | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1}')
echo "case=$CASE steps=$STEPS N=$n instructions=$total per_particle_step=$((total / (n * STEPS)))"
# the functions: "count (share) file:name(arguments) ..." -> "count share name"
callgrind_annotate --inclusive=no "$OUT" 2>/dev/null | grep -E '^ *[0-9,]+ \(' | grep -v 'PROGRAM TOTALS' |
  head -8 | sed -E -e 's/\(anonymous namespace\)/{anonymous}/g' \
    -e 's/^ *([0-9,]+) \(([^)]*)\) +([^ :]*:)?([^:][^(]*).*/\1 \2 \4/'
