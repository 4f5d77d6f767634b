#!/usr/bin/env bash
# Single-grain compression through the command line (examples/grain_calibration): `calibrate
# --evaluate` runs the compression once at the case's values and writes compression.csv and
# fit.csv with their documented headers; the example's own values (3e12 Pa/m, 1e7 Pa) are far
# from the measured curve's (1e12, 6e6), so its objective is large; --evaluate on a population
# balance case and a missing platen are refused with exit code 2.
set -euo pipefail
bin="$1"
src="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cp "$src"/examples/grain_calibration/{grain_compression.toml,grain.data,measured.csv} "$work/"
"$bin" calibrate "$work/grain_compression.toml" --evaluate > "$work/log" 2>&1 ||
  { cat "$work/log"; exit 1; }
for f in compression.csv fit.csv; do
  [ -f "$work/output/$f" ] || { echo "missing $f"; cat "$work/log"; exit 1; }
done
[ "$(head -1 "$work/output/compression.csv")" = 'displacement [m],force [N]' ] ||
  { echo "compression.csv header: $(head -1 "$work/output/compression.csv")"; exit 1; }
[ "$(head -1 "$work/output/fit.csv")" = 'displacement [m],measured [N],simulated [N]' ] ||
  { echo "fit.csv header: $(head -1 "$work/output/fit.csv")"; exit 1; }
# one fit row per measured point (the measured file: 2 comment lines, a header, 49 points)
rows=$(($(wc -l < "$work/output/fit.csv") - 1))
[ "$rows" -eq 49 ] || { echo "fit.csv has $rows rows"; exit 1; }
grep -q "objective" "$work/log" || { cat "$work/log"; exit 1; }

# `comminute check` reads the fit as `calibrate` does: the compression at the case's values runs
# once and must reach the end of the measured curve
"$bin" check "$work/grain_compression.toml" > "$work/log" 2>&1 || { cat "$work/log"; exit 1; }
grep -q "valid grain compression calibration" "$work/log" || { cat "$work/log"; exit 1; }
grep -q "2 free parameter(s), 49 measured point(s)" "$work/log" || { cat "$work/log"; exit 1; }

refused() {  # refused KEY FILE [ARGS]: the case is refused with exit code 2 naming KEY
  local key="$1" file="$2" rc=0
  shift 2
  "$bin" calibrate "$file" "$@" > "$work/msg" 2>&1 || rc=$?
  [ "$rc" -eq 2 ] && grep -q "$key" "$work/msg" || { echo "$key: rc $rc"; cat "$work/msg"; exit 1; }
}
refused "calibration" "$src/examples/pbm/calibrate_carbon_black.toml" --evaluate
sed -e 's/^platen = "platen"/platen = "lid"/' "$work/grain_compression.toml" > "$work/bad.toml"
refused "calibration.compression.platen" "$work/bad.toml" --evaluate
rc=0
"$bin" check "$work/bad.toml" > "$work/msg" 2>&1 || rc=$?
[ "$rc" -eq 2 ] && grep -q "calibration.compression.platen" "$work/msg" ||
  { echo "check of a missing platen: rc $rc"; cat "$work/msg"; exit 1; }
echo "grain calibration CLI: ok"
