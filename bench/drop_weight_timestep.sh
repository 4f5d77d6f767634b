#!/usr/bin/env bash
# Wall-clock and CPU-time A/B of the drop-weight example between two builds of `comminute`, run
# back to back in one sitting: BASE (e.g. main's HEAD built in another worktree, running
# BASE_CASE) and NEW (running NEW_CASE, by default the same case); REPS rounds, alternating, one
# thread each. Prints one line per run (wall and user+system CPU seconds, steps, the load
# average) and the medians; the outputs stay in $OUT/<label><k>/. On a shared machine the CPU
# time is the steadier measure.
#   bench/drop_weight_timestep.sh BASE_BIN NEW_BIN [BASE_CASE [NEW_CASE]]      (REPS=3 default)
# Used for bench/RESULTS.md, "Time step of breakage runs".
set -euo pipefail
base=$1
new=$2
base_case=${3:-examples/breakage/drop_weight.toml}
new_case=${4:-$base_case}
reps=${REPS:-3}
out=${OUT:-/tmp/drop_weight_timestep}
mkdir -p "$out"
run_one() {  # label binary case k
  local dir="$out/$1$4"
  rm -rf "$dir"
  local t0 t1
  t0=$(date +%s.%N)
  OMP_NUM_THREADS=1 /usr/bin/time -f "%U %S" -o "$dir.cpu" "$2" run "$3" -o "$dir" --threads 1 \
    >"$dir.log" 2>&1
  t1=$(date +%s.%N)
  local wall cpu steps
  wall=$(echo "$t1 - $t0" | bc -l)
  cpu=$(awk '{print $1 + $2}' "$dir.cpu")
  steps=$(tail -1 "$dir/timeseries.csv" | cut -d, -f2)
  printf '%s %d wall_s %.2f cpu_s %.2f steps %s load %s\n' "$1" "$4" "$wall" "$cpu" "$steps" \
    "$(cut -d' ' -f1 /proc/loadavg)" | tee -a "$out/times.txt"
}
median() {  # label column
  grep "^$1 " "$out/times.txt" | awk -v c="$2" '{print $c}' | sort -g |
    awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'
}
: >"$out/times.txt"
for k in $(seq 1 "$reps"); do
  run_one base "$base" "$base_case" "$k"
  run_one new "$new" "$new_case" "$k"
done
for label in base new; do
  printf '%s median wall_s %s cpu_s %s\n' "$label" "$(median "$label" 4)" "$(median "$label" 6)"
done
