#!/usr/bin/env bash
# Hardening from the command line (issue 9): command-line values that mean nothing are refused;
# a checkpoint of another case, a crafted checkpoint (valid checksums) or one with nothing left
# to run is refused with exit 2 naming it; malformed calibration data is refused naming file,
# line and key.   usage: test_hardening_cli.sh <comminute> <source-dir>
set -uo pipefail
bin=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
fail=0
expect() {  # expect <description> <exit code> <text> <command...>
  local what=$1 code=$2 text=$3
  shift 3
  local out rc=0
  out=$("$@" 2>&1) || rc=$?
  if [ "$rc" -ne "$code" ] || ! grep -qF -- "$text" <<<"$out"; then
    echo "FAIL: $what: exit $rc (wanted $code), wanted '$text' in:"
    echo "$out" | tail -5
    fail=1
  else
    echo "ok: $what"
  fi
}

sed -e 's/^count = 3000/count = 10/' -e 's/^end_time = 0.5 /end_time = 0.002 /' \
  "$src/examples/settle/settle.toml" > case.toml

# --- command line
expect "--threads 0" 2 "key '--threads': 0 threads: must be in [1, 1024]" "$bin" run case.toml --threads 0
expect "--threads -1" 2 "must be in [1, 1024]" "$bin" run case.toml --threads=-1
expect "--threads 100000" 2 "must be in [1, 1024]" "$bin" run case.toml --threads 100000
expect "-o ''" 2 "key '--output': the path is empty" "$bin" run case.toml -o ''
expect "--restart ''" 2 "key '--restart': the path is empty" "$bin" run case.toml --restart ''
expect "-o onto a file" 2 "key '--output': output folder 'case.toml' is a file" "$bin" run case.toml -o case.toml

# --- checkpoints
expect "a run writes its final checkpoint" 0 "done" "$bin" run case.toml -o out --threads 1
cp out/checkpoint.h5 end.h5
expect "restart at the end time" 2 "nothing to continue" "$bin" run case.toml -o out2 --restart end.h5
sed -e 's/^end_time = 0.002 /end_time = 0.003 /' case.toml > longer.toml
sed -e 's/^end_time = 0.002 /end_time = 0.003 /' -e 's/^density = 2500.0/density = 2600.0/' \
  case.toml > other.toml
expect "restart with a later end time" 0 "continuing from end.h5" "$bin" run longer.toml -o out3 --restart end.h5 --threads 1
expect "restart with another case" 2 "end.h5: the checkpoint belongs to another case" "$bin" run other.toml -o out4 --restart end.h5
expect "... names what differs" 2 "the checkpoint belongs to another case: [materials] differs" "$bin" run other.toml -o out4 --restart end.h5
# a crafted checkpoint: a pair slot far out of range, the entry's checksum recomputed
cp end.h5 crafted.h5
/usr/bin/python3 - <<'PY'
import h5py, numpy as np
def fnv(b):
    h = 0xcbf29ce484222325
    for c in b:
        h = ((h ^ c) * 0x100000001b3) & 0xffffffffffffffff
    return h
with h5py.File("crafted.h5", "r+") as f:
    for ds in f["entries"].values():
        label = ds.attrs["name"]
        label = label.decode() if isinstance(label, bytes) else label
        if label == "particles/material":
            data = np.frombuffer(np.full(ds.shape[0] // 2, 999, dtype=np.uint16).tobytes(), np.uint8)
            ds[...] = data
            ds.attrs.modify("fnv1a64", np.uint64(fnv(bytes(data))))
PY
expect "crafted checkpoint" 2 "crafted.h5: key '--restart': checkpoint entry 'particles/material'" "$bin" run longer.toml -o out5 --restart crafted.h5
head -c 1000 end.h5 > truncated.h5
expect "truncated checkpoint" 2 "truncated.h5: key '--restart'" "$bin" run longer.toml -o out6 --restart truncated.h5

# --- calibration data
cp "$src"/examples/pbm/*.toml "$src"/examples/pbm/*.csv .
awk '/^\[\[calibration.parameter\]\]/ && !done {print; print "key = \"rate.lambda\""; print "min = 1e-3"; print "max = 0.1"; print ""; print; done=1; next} {print}' \
  calibrate_carbon_black.toml > dup_param.toml
line=$(grep -n '^key = "rate.lambda"' dup_param.toml | tail -1 | cut -d: -f1)
expect "duplicate free parameter" 2 "dup_param.toml:$line: key 'calibration.parameter[5].key': 'rate.lambda' is already a free parameter" "$bin" calibrate dup_param.toml
sed -e '5s/,[0-9.]*$/,0.9/' measured_10s.csv > falling.csv
sed -e 's/"measured_10s.csv"/"falling.csv"/' calibrate_carbon_black.toml > falling.toml
expect "cumulative passing falling with size" 2 "falling.csv:6: key 'calibration.data[0].file': cumulative_passing" "$bin" calibrate falling.toml
sed -e 's/^size_m,cumulative_passing/size_m,size_m/' measured_10s.csv > twice.csv
sed -e 's/"measured_10s.csv"/"twice.csv"/' calibrate_carbon_black.toml > twice.toml
expect "duplicate CSV column" 2 "twice.csv:2: key 'calibration.data[0].file': column name 'size_m' appears twice" "$bin" calibrate twice.toml
sed -e 's/^2500,/-2500,/' mixer_contact_frequency.csv > negative.csv
sed -e 's/"mixer_contact_frequency.csv"/"negative.csv"/' carbon_black.toml > negative.toml
expect "negative stress" 2 "negative.csv:4: key 'rate.frequency_file': negative stress -2500 Pa" "$bin" pbm --no-plots negative.toml

# --- PBM time steps
sed -e 's/^integrator = "adaptive"/integrator = "rk4"\ntime_step = 90.0/' batch_grinding.toml > rk4_big.toml
line=$(grep -n '^time_step' rk4_big.toml | cut -d: -f1)
expect "RK4 step above the smallest output interval" 2 "rk4_big.toml:$line: key 'solver.time_step': the RK4 step 90 s exceeds the smallest output interval 60 s" "$bin" pbm --no-plots rk4_big.toml
sed -e 's/^integrator = "adaptive"/integrator = "rk4"\ntime_step = 1e-6/' batch_grinding.toml > rk4_many.toml
expect "RK4 step count beyond the cap" 2 "RK4 steps, more than the cap of 1000000 steps" "$bin" pbm --no-plots rk4_many.toml
exit $fail
