#!/usr/bin/env bash
# `comminute run` outputs read back with VTK's own reader (see check_run_outputs.py): a small
# pour into a box, 300 spheres, 0.04 s.
# usage: test_vtk_readback.sh <comminute> <source-dir>
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sed -e 's/^count = 3000/count = 300/' -e 's/^end_time = 0.5 /end_time = 0.04/' \
  "$src/examples/settle/settle.toml" > "$tmp/case.toml"
cat >> "$tmp/case.toml" <<'TOML'

[output]
directory = "out"
particles_interval = 0.01     # s: snapshots at 0, 0.01, ..., 0.04
timeseries_interval = 0.001   # s
checkpoint_interval = 0.015   # s
TOML
grep -q '^count = 300' "$tmp/case.toml" && grep -q '^end_time = 0.04' "$tmp/case.toml" \
  || { echo "case template changed: edit this test"; exit 1; }
"$bin" run "$tmp/case.toml" --threads 1 2> "$tmp/log" || { cat "$tmp/log"; exit 1; }
grep -q "outputs in" "$tmp/log"
rc=0
/usr/bin/python3 "$src/tests/scripts/check_run_outputs.py" "$tmp/out" 5 || rc=$?
if [ $rc -eq 77 ]; then echo "SKIP: python3-vtk9/h5py missing"; exit 0; fi
exit $rc
