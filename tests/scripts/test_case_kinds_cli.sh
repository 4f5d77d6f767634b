#!/usr/bin/env bash
# Each command refuses a case that another command runs (exit code 2), naming the file, the line
# and the table that marks the case's kind and the command to use (apps/comminute/case_kind.hpp);
# a table looked at to tell the kind still counts as unknown where the command does not read it.
#   usage: test_case_kinds_cli.sh <comminute> <source-dir>
set -uo pipefail
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$src"/examples/settle/settle.toml "$src"/examples/pbm/batch_grinding.toml \
   "$src"/examples/pbm/calibrate_carbon_black.toml "$src"/examples/pbm/*.csv \
   "$src"/examples/grain_calibration/{grain_compression.toml,grain.data,measured.csv} \
   "$src"/examples/ball_mill/couple.toml "$work"/
cd "$work"
fail=0
refused() {  # refused <command> <case> <table> <command named in the message>
  local cmd=$1 case=$2 table=$3 use=$4 out rc line
  out=$("$bin" $cmd "$case" 2>&1)
  rc=$?
  line=$(grep -n "^\[$table\]" "$case" | head -1 | cut -d: -f1)
  if [ $rc -eq 2 ] && grep -qF "$case:$line: key '$table':" <<<"$out" &&
     grep -qF "\`comminute $use\`" <<<"$out"; then
    echo "ok: $cmd $case refused, names [$table] at line $line and '$use'"
  else
    echo "FAIL: $cmd $case (rc $rc): $out"
    fail=1
  fi
}
refused pbm settle.toml simulation run
refused couple settle.toml simulation run
refused calibrate settle.toml simulation run
refused run batch_grinding.toml grid pbm
refused couple batch_grinding.toml grid pbm
refused pbm calibrate_carbon_black.toml calibration calibrate
refused run calibrate_carbon_black.toml calibration calibrate
refused run grain_compression.toml calibration calibrate
refused pbm grain_compression.toml calibration calibrate
refused run couple.toml couple couple
refused pbm couple.toml couple couple
refused calibrate couple.toml couple couple

expect_refusal() {  # expect_refusal <description> <text that must appear> <comminute args...>
  local what=$1 text=$2 out rc
  shift 2
  out=$("$bin" "$@" 2>&1)
  rc=$?
  if [ $rc -eq 2 ] && grep -qF -- "$text" <<<"$out"; then
    echo "ok: $what"
  else
    echo "FAIL: $what (rc $rc): $out"
    fail=1
  fi
}
# a DEM case with a [calibration] table that is not a grain compression: still an unknown key
{ cat settle.toml; printf '\n[calibration]\nstarts = 3\n'; } > stray.toml
line=$(grep -n '^\[calibration\]' stray.toml | cut -d: -f1)
expect_refusal "run refuses a stray [calibration] as unknown" \
  "stray.toml:$line: key 'calibration': unknown key" run stray.toml -o out
expect_refusal "check refuses a stray [calibration] as unknown" \
  "stray.toml:$line: key 'calibration': unknown key" check stray.toml
# a population balance without [calibration] given to calibrate: its reader names what is missing
expect_refusal "calibrate of a plain population balance asks for [calibration]" \
  "missing required key 'calibration'" calibrate batch_grinding.toml
# the kinds each command runs still run or check
for c in settle.toml batch_grinding.toml calibrate_carbon_black.toml grain_compression.toml; do
  "$bin" check "$c" > /dev/null 2>&1 || { echo "FAIL: check $c"; fail=1; }
done
exit $fail
