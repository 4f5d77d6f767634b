#!/usr/bin/env bash
# Cost of texture on the HPGR texture example (issue 12, Performance): the template
# examples/hpgr_texture/hpgr_texture.toml with equal phase strengths (f_rel = 1, 1) and
# density_from_phases = false, so that texture changes no force and no mass, run WITH its texture
# and liberation observer (resolution N, default 16) and WITHOUT them ([texture] and [liberation]
# removed; the criterion then sees composition (1, 0) and the same F_CS), same seed, REPS rounds
# (default 3) alternating, one thread each, one binary. Prints user+system CPU seconds, wall
# seconds, steps, breakage events and the load average per run, then the medians and their
# ratio; with texture also the pool's bytes per particle (texture.csv, last row).
#   bench/hpgr_texture_cost.sh BIN [N]          (REPS=3, OUT=/tmp/hpgr_texture_cost)
# Used for bench/RESULTS.md, "Texture cost on the HPGR example".
set -euo pipefail
bin=$1
n=${2:-16}
reps=${REPS:-3}
out=${OUT:-/tmp/hpgr_texture_cost}
src=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
/usr/bin/python3 - "$src/examples/hpgr_texture/hpgr_texture.toml" "$out" "$n" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
text = re.sub(r"^relative_strength = \[[^\]]*\]", "relative_strength = [1.0, 1.0]", text, flags=re.M)
text = re.sub(r"^relative_strength = [0-9.]+ ", "relative_strength = 1.0 ", text, flags=re.M)
text = re.sub(r"^resolution = 16 ", f"resolution = {sys.argv[3]} ", text, flags=re.M)
with_t = text.replace("[texture]\n", "[texture]\ndensity_from_phases = false\n", 1)
a, b = text.index("[texture]\n"), text.index("[[walls]]")
open(f"{sys.argv[2]}/with.toml", "w").write(with_t)
open(f"{sys.argv[2]}/without.toml", "w").write(text[:a] + text[b:])
PY
run_one() {  # label k
  local dir="$out/$1$2"
  rm -rf "$dir"
  local t0 t1
  t0=$(date +%s.%N)
  OMP_NUM_THREADS=1 /usr/bin/time -f "%U %S" -o "$dir.cpu" "$bin" run "$out/$1.toml" -o "$dir" \
    --threads 1 >"$dir.log" 2>&1
  t1=$(date +%s.%N)
  local steps events bytes=""
  steps=$(tail -1 "$dir/timeseries.csv" | cut -d, -f2)
  events=$(($(wc -l <"$dir/breakage_events.csv") - 1))
  if [ -f "$dir/texture.csv" ]; then
    bytes=" bytes_per_particle $(tail -1 "$dir/texture.csv" | cut -d, -f5)"
  fi
  printf '%s %d cpu_s %.2f wall_s %.2f steps %s events %s load %s%s\n' "$1" "$2" \
    "$(awk '{print $1 + $2}' "$dir.cpu")" "$(echo "$t1 - $t0" | bc -l)" "$steps" "$events" \
    "$(cut -d' ' -f1 /proc/loadavg)" "$bytes" | tee -a "$out/times.txt"
}
median() {  # label
  grep "^$1 " "$out/times.txt" | awk '{print $4}' | sort -g |
    awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'
}
: >"$out/times.txt"
for k in $(seq 1 "$reps"); do
  run_one without "$k"
  run_one with "$k"
done
a=$(median without)
b=$(median with)
echo "median CPU s: without $a, with $b (N = $n), ratio $(echo "$b / $a" | bc -l | cut -c1-5)"
