#!/usr/bin/env bash
# Periodic boundaries through the command line: the periodic drum-slice example (shortened) runs,
# keeps its 600 particles, and a run continued from its checkpoint (ghosts planned at the save)
# ends with the same state as the uninterrupted run (bit for bit: same thread count).
set -euo pipefail
bin="$1"
src="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

sed -e 's/^end_time = 0.5 .*/end_time = 0.06/' -e 's/^particles_interval = .*/particles_interval = 1.0/' \
  "$src/examples/periodic/drum_slice.toml" > "$work/full.toml"
"$bin" run "$work/full.toml" -o "$work/full" --threads 1 > "$work/log" 2>&1 ||
  { cat "$work/log"; exit 1; }
awk -F, 'NR == 1 {for (k = 1; k <= NF; ++k) if ($k == "particles [-]") c = k; next}
  $c != 600 {print "particle count", $c, "at t =", $1; exit 1}' \
  "$work/full/timeseries.csv"
# the same run stopped at 0.03 s, then continued to 0.06 s from its checkpoint
sed -e 's/^end_time = 0.06/end_time = 0.03/' "$work/full.toml" > "$work/half.toml"
"$bin" run "$work/half.toml" -o "$work/half" --threads 1 > "$work/log" 2>&1 ||
  { cat "$work/log"; exit 1; }
"$bin" run "$work/full.toml" -o "$work/cont" --threads 1 --restart "$work/half/checkpoint.h5" \
  > "$work/log" 2>&1 || { cat "$work/log"; exit 1; }
a=$(tail -1 "$work/full/timeseries.csv")
b=$(tail -1 "$work/cont/timeseries.csv")
[ "$a" = "$b" ] || { echo "restart differs:"; echo "$a"; echo "$b"; exit 1; }
echo "ok: periodic slice runs, keeps its particles and restarts exactly"
