#!/usr/bin/env bash
# Breakage through the command line: a small drop-weight run writes the event log, ledger, size
# distribution and model curves (and the plot script turns them into PNGs); bad breakage input
# stops with exit code 2 and a message naming the key.
set -euo pipefail
bin="$1"
src="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# 20 particles, impact only (1.0 ms): enough for breakages at 200 J/kg.
sed -e 's/^count = 200/count = 20/' -e 's/^end_time = 0.003 /end_time = 0.001 /' \
  -e 's/hi = \[0.3, 0.3, 0.018\]/hi = [0.1, 0.1, 0.018]/' \
  "$src/examples/breakage/drop_weight.toml" > "$work/drop.toml"
"$bin" run "$work/drop.toml" -o "$work/out" --threads 1 > "$work/log" 2>&1
for f in breakage_events.csv breakage_fragments.csv breakage_ledger.csv size_distribution.csv \
  breakage_model.csv; do
  [ -s "$work/out/$f" ] || { echo "missing $f"; cat "$work/log"; exit 1; }
done
head -1 "$work/out/breakage_events.csv" | grep -q '^time \[s\],parent_id \[-\],.*,broken \[-\],' ||
  { echo "breakage_events.csv header"; head -1 "$work/out/breakage_events.csv"; exit 1; }
broken=$(awk -F, 'NR == 1 {for (i = 1; i <= NF; i++) if ($i == "broken [-]") c = i; next} $c == 1' \
  "$work/out/breakage_events.csv" | wc -l)
[ "$broken" -gt 0 ] || { echo "no breakage in the drop-weight run"; exit 1; }
# Mass: particles + fines booked as mass equal the initial 20 x 1.41372 g (to 1e-9 relative;
# the CSV prints every double in full, columns 6 and 7 are particle_mass [kg] and fines_mass [kg];
# row 2 is the sample at the start, the last row the one at the run's end time).
awk -F, 'NR == 2 {m0 = $6 + $7} END {m = $6 + $7; d = (m - m0) / m0; if (d < 0) d = -d;
  if (d > 1e-9) {print "mass changed by", d; exit 1}}' "$work/out/breakage_ledger.csv"
/usr/bin/python3 "$src/scripts/plot_breakage.py" "$work/out" -o "$work/png" > /dev/null
for f in size_distribution t10_vs_energy breakage_probability breakage_ledger; do
  [ -s "$work/png/$f.png" ] || { echo "missing $f.png"; exit 1; }
done

# Bad input: unknown criterion, missing minimum sizes -> exit 2 naming the key.
sed 's/criterion = "tavares"/criterion = "tavaress"/' "$work/drop.toml" > "$work/bad1.toml"
set +e
"$bin" check "$work/bad1.toml" > "$work/bad1.log" 2>&1
rc=$?
set -e
[ "$rc" -eq 2 ] || { echo "unknown criterion: exit $rc"; cat "$work/bad1.log"; exit 1; }
grep -q "materials.ore.breakage.criterion" "$work/bad1.log" || { cat "$work/bad1.log"; exit 1; }
sed -e '/^min_breakable_size/d' -e '/^min_fragment_ratio/d' -e '/^min_fragment_size/d' "$work/drop.toml" \
  > "$work/bad2.toml"
set +e
"$bin" check "$work/bad2.toml" > "$work/bad2.log" 2>&1
rc=$?
set -e
[ "$rc" -eq 2 ] || { echo "no minimum size: exit $rc"; cat "$work/bad2.log"; exit 1; }
grep -q "min_fragment_size" "$work/bad2.log" || { cat "$work/bad2.log"; exit 1; }
sed 's/^alpha = .*/alpha = [1.0, 1.0]/' "$work/drop.toml" > "$work/bad3.toml"
set +e
"$bin" check "$work/bad3.toml" > "$work/bad3.log" 2>&1
rc=$?
set -e
[ "$rc" -eq 2 ] || { echo "short alpha: exit $rc"; cat "$work/bad3.log"; exit 1; }
grep -q "progeny.alpha" "$work/bad3.log" || { cat "$work/bad3.log"; exit 1; }
echo "breakage CLI: ok ($broken breakages)"
