#!/usr/bin/env bash
# Wall-clock A/B of the drop-weight example (examples/breakage/drop_weight.toml) between two
# builds of `comminute`, run back to back in one sitting: BASE (e.g. main's HEAD built in another
# worktree) and NEW; REPS rounds, alternating, one thread each. Prints one line per run (wall
# seconds, steps, particles at the end) and the medians; the outputs stay in $OUT/<label><k>/.
#   bench/drop_weight_timestep.sh BASE_BIN NEW_BIN [CASE]      (REPS=3 by default)
# Used for bench/RESULTS.md, "Time step of breakage runs".
set -euo pipefail
base=$1
new=$2
case_file=${3:-examples/breakage/drop_weight.toml}
reps=${REPS:-3}
out=${OUT:-/tmp/drop_weight_timestep}
mkdir -p "$out"
run_one() {  # label binary k
  local dir="$out/$1$3"
  rm -rf "$dir"
  local t0 t1
  t0=$(date +%s.%N)
  OMP_NUM_THREADS=1 "$2" run "$case_file" -o "$dir" --threads 1 >"$dir.log" 2>&1
  t1=$(date +%s.%N)
  local wall steps
  wall=$(echo "$t1 - $t0" | bc -l)
  steps=$(tail -1 "$dir/timeseries.csv" | cut -d, -f2)
  printf '%s %d wall_s %.2f steps %s load %s\n' "$1" "$3" "$wall" "$steps" \
    "$(cut -d' ' -f1 /proc/loadavg)" | tee -a "$out/times.txt"
}
: >"$out/times.txt"
for k in $(seq 1 "$reps"); do
  run_one base "$base" "$k"
  run_one new "$new" "$k"
done
for label in base new; do
  printf '%s median wall_s %s\n' "$label" \
    "$(grep "^$label " "$out/times.txt" | awk '{print $4}' | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')"
done
