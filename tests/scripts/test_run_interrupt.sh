#!/usr/bin/env bash
# Ctrl-C during `comminute run`: the run writes a checkpoint, says so and exits with 130; a run
# continued from that checkpoint with --restart ends bit-for-bit where an uninterrupted run ends
# (same thread count): identical time-series CSV, collections and final snapshot files.
# usage: test_run_interrupt.sh <comminute> <source-dir>
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
pid=
trap '[ -n "$pid" ] && kill -KILL "$pid" 2>/dev/null; rm -rf "$tmp"' EXIT
make_case() {  # make_case <end_time> <output-dir> <file>
  sed -e 's/^count = 3000/count = 300/' -e "s/^end_time = 0.5 /end_time = $1 /" \
    "$src/examples/settle/settle.toml" > "$3"
  grep -q '^count = 300' "$3" && grep -q "^end_time = $1 " "$3" \
    || { echo "case template changed: edit this test"; exit 1; }
  printf '\n[output]\ndirectory = "%s"\nparticles_interval = 0.01\ntimeseries_interval = 0.001\n' \
    "$2" >> "$3"
}

# 1. A long run (10 s simulated), interrupted once it has written 30 rows (t >= 0.03 s).
make_case 10.0 out "$tmp/long.toml"
"$bin" run "$tmp/long.toml" --threads 1 2> "$tmp/log" &
pid=$!
for _ in $(seq 600); do
  [ -f "$tmp/out/timeseries.csv" ] && [ "$(wc -l < "$tmp/out/timeseries.csv")" -gt 30 ] && break
  sleep 0.1
done
kill -INT "$pid"
rc=0; wait "$pid" || rc=$?
pid=
cat "$tmp/log"
[ "$rc" -eq 130 ] || { echo "FAIL: exit code $rc, expected 130"; exit 1; }
grep -q "stopped by SIGINT" "$tmp/log" || { echo "FAIL: no stop message"; exit 1; }
[ -f "$tmp/out/checkpoint.h5" ] || { echo "FAIL: no checkpoint"; exit 1; }

# 2. Continue to 0.02 s after the stop; 3. the same span without interruption.
t_end=$(/usr/bin/python3 -c "import h5py; print(round(float(h5py.File('$tmp/out/checkpoint.h5')['/'].attrs['time']) + 0.02, 3))")
make_case "$t_end" out "$tmp/short.toml"
make_case "$t_end" ref "$tmp/ref.toml"
"$bin" run "$tmp/short.toml" --threads 1 --restart "$tmp/out/checkpoint.h5" 2> "$tmp/log2" \
  || { cat "$tmp/log2"; exit 1; }
grep -q "continuing from" "$tmp/log2"
"$bin" run "$tmp/ref.toml" --threads 1 2> "$tmp/log3" || { cat "$tmp/log3"; exit 1; }

status=0
last=$(ls "$tmp/ref/particles" | tail -1)
for f in timeseries.csv particles.pvd walls.pvd "particles/$last" "walls/${last/particles/walls}"; do
  cmp -s "$tmp/out/$f" "$tmp/ref/$f" || { echo "FAIL: $f differs from the uninterrupted run"; status=1; }
done
rows=$(wc -l < "$tmp/ref/timeseries.csv")
# 4. SIGKILL (no chance to clean up) while snapshots are written every 5 steps: the collections
#    list only complete, readable files and the CSV's complete rows are consistent.
sed -e 's/^particles_interval = 0.01$/particles_every = 5/' "$tmp/long.toml" > "$tmp/kill.toml"
sed -i 's/^directory = "out"$/directory = "killed"/' "$tmp/kill.toml"
grep -q '^particles_every = 5' "$tmp/kill.toml" && grep -q '^directory = "killed"' "$tmp/kill.toml" \
  || { echo "kill case not made: edit this test"; exit 1; }
"$bin" run "$tmp/kill.toml" --threads 1 2> /dev/null &
pid=$!
for _ in $(seq 600); do
  [ -f "$tmp/killed/timeseries.csv" ] && [ "$(wc -l < "$tmp/killed/timeseries.csv")" -gt 20 ] && break
  sleep 0.1
done
kill -KILL "$pid"
wait "$pid" 2>/dev/null || true
pid=
/usr/bin/python3 "$src/tests/scripts/check_run_outputs.py" "$tmp/killed" killed || status=1

[ $status -eq 0 ] && echo "ok: stopped at $(grep -o 't = [0-9.e-]* s (step [0-9]*)' "$tmp/log"), continued to $t_end s; $rows CSV lines and the final snapshot identical to the uninterrupted run"
exit $status
