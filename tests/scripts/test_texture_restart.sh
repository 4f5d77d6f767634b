#!/usr/bin/env bash
# Per-particle textures are checkpointed: a textured drop-weight run (composition criterion,
# texture inheritance, liberation observer) stopped at its end time in the middle of the breakage
# and continued with --restart ends bit-for-bit where an uninterrupted run ends: identical texture,
# liberation, fragment and time-series tables and final particle snapshot.
# usage: test_texture_restart.sh <comminute> <source-dir>
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
[ -n "${KEEP:-}" ] && echo "$tmp"
trap '[ -n "${KEEP:-}" ] || rm -rf "$tmp"' EXIT
make_case() {  # make_case <end_time> <output-dir> <file>
  sed -e 's/^count = 200$/count = 30/' -e "s/^end_time = 0.003 /end_time = $1 /" \
    -e 's/^interval = 0.0005 /interval = 0.0001 /' \
    "$src/examples/texture/drop_weight_texture.toml" > "$3"
  grep -q '^count = 30$' "$3" && grep -q "^end_time = $1 " "$3" && grep -q '^interval = 0.0001 ' "$3" \
    || { echo "case template changed: edit this test"; exit 1; }
  printf '\n[output]\ndirectory = "%s"\nparticles_interval = 0.0002\ntimeseries_interval = 0.0001\n' \
    "$2" >> "$3"
}
make_case 0.0004 out "$tmp/first.toml"
make_case 0.0008 out "$tmp/second.toml"
make_case 0.0008 ref "$tmp/ref.toml"
"$bin" run "$tmp/first.toml" --threads 1 2> "$tmp/log1" || { cat "$tmp/log1"; exit 1; }
[ -f "$tmp/out/checkpoint.h5" ] || { echo "FAIL: no checkpoint"; exit 1; }
"$bin" run "$tmp/second.toml" --threads 1 --restart "$tmp/out/checkpoint.h5" 2> "$tmp/log2" \
  || { cat "$tmp/log2"; exit 1; }
"$bin" run "$tmp/ref.toml" --threads 1 2> "$tmp/log3" || { cat "$tmp/log3"; exit 1; }
status=0
last=$(ls "$tmp/ref/particles" | tail -1)
cmp -s "$tmp/out/particles/$last" "$tmp/ref/particles/$last" \
  || { echo "FAIL: the final snapshot differs from the uninterrupted run"; status=1; }
# Tables: the rows after the restart are identical (the first run adds a row at its end time).
/usr/bin/python3 - "$tmp/out" "$tmp/ref" <<'PY' || status=1
import csv, sys
out, ref = sys.argv[1], sys.argv[2]
def rows(d, name):
    with open(f"{d}/{name}") as f:
        return [r for r in csv.DictReader(f) if float(r["time [s]"]) > 0.00041]
bad = 0
for name in ("texture.csv", "liberation.csv", "liberation_spectrum.csv", "grade_recovery.csv",
             "breakage_fragments.csv", "timeseries.csv"):
    a, b = rows(out, name), rows(ref, name)
    if not b or a != b:
        print(f"FAIL: {name}: {len(a)} rows after the restart, {len(b)} uninterrupted, differ")
        bad = 1
first = [r for r in csv.DictReader(open(f"{out}/texture.csv")) if float(r["time [s]"]) < 0.00041]
final = list(csv.DictReader(open(f"{ref}/texture.csv")))[-1]
before, after = int(first[-1]["inherited [-]"]), int(final["inherited [-]"])
if not 0 < before < after:
    print(f"FAIL: fragments textured before / after the restart: {before} / {after}")
    bad = 1
else:
    print(f"ok: {before} fragments textured before the restart at 0.0004 s, {after} at 0.0008 s; "
          "rows after the restart and the final snapshot identical")
sys.exit(bad)
PY
exit $status
