#!/usr/bin/env bash
# Pouring bonded grains through the command line: `comminute check` accepts the poured rice case
# (examples/rice_compression/rice_pour.toml) and refuses bad pour keys with exit code 2, naming
# the file, the line and the key.
set -euo pipefail
bin="$1"
src="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

case_file="$src/examples/rice_compression/rice_pour.toml"
"$bin" check "$case_file" > "$work/log" 2>&1 || { cat "$work/log"; exit 1; }

refused() {  # refused KEY: bad.toml is refused with exit code 2 and a message naming KEY
  local rc=0
  "$bin" check "$work/bad.toml" > "$work/msg" 2>&1 || rc=$?
  [ "$rc" -eq 2 ] && grep -q "$1" "$work/msg" && grep -q "bad.toml" "$work/msg" ||
    { echo "$1: rc $rc"; cat "$work/msg"; exit 1; }
}
# both targets
sed -e 's/^count = 200 /count = 200\nmass = 0.01\n/' "$case_file" > "$work/bad.toml"
refused 'insert\[0\]'
# layers as time windows without an end
grep -v '^end = 0.1 ' "$case_file" > "$work/bad.toml"
refused 'insert\[0\].layers'
# a negative rate
sed -e 's/^rate = 2000.0 /rate = -5.0 /' "$case_file" > "$work/bad.toml"
refused 'insert\[0\].rate'
# an unknown mode
sed -e 's/^mode = "pour" /mode = "drip" /' "$case_file" > "$work/bad.toml"
refused 'insert\[0\].mode'
# a misspelt key
sed -e 's/^interval = /intervall = /' "$case_file" > "$work/bad.toml"
refused 'intervall'
echo ok
