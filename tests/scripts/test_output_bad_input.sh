#!/usr/bin/env bash
# Bad [output] tables: `comminute check` and `comminute run` exit with 2 and name the file, line
# and key path of the mistake.
# usage: test_output_bad_input.sh <comminute> <source-dir>
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
status=0
expect() {  # expect <command> <message part> <toml lines...>
  local cmd=$1 want=$2
  shift 2
  sed -e 's/^count = 3000/count = 10/' -e 's/^end_time = 0.5 /end_time = 0.001 /' \
    "$src/examples/settle/settle.toml" > "$tmp/case.toml"
  printf '\n[output]\ndirectory = "out"\n' >> "$tmp/case.toml"
  printf '%s\n' "$@" >> "$tmp/case.toml"
  local rc=0
  "$bin" "$cmd" "$tmp/case.toml" > "$tmp/log" 2>&1 || rc=$?
  if [ $rc -ne 2 ] || ! grep -qF -- "$want" "$tmp/log"; then
    echo "FAIL ($cmd, exit $rc): wanted '$want' for: $*"
    cat "$tmp/log"
    status=1
  fi
}
n=$(( $(wc -l < "$src/examples/settle/settle.toml") + 4 ))  # line of the first added key
expect check "case.toml:$((n + 1)): key 'output.particles_every': give either output.particles_interval or output.particles_every, not both" \
  "particles_interval = 0.1" "particles_every = 10"
expect check "case.toml:$n: key 'output.timeseries_interval'" "timeseries_interval = -0.5"
expect check "case.toml:$n: key 'output.checkpoint_every'" "checkpoint_every = 1.5"
expect check "case.toml:$n: key 'output.walls'" 'walls = "yes"'
expect check "case.toml:$n: key 'output.fields'" 'fields = "damage"'
expect check "case.toml:$n: key 'output.particle_interval': unknown key" "particle_interval = 0.1"
expect run "case.toml:$n: key 'output.fields': 'damage' is not a per-particle field" 'fields = ["damage"]'
# what run refuses, check refuses too
expect check "case.toml:$n: key 'output.fields': 'damage' is not a per-particle field" 'fields = ["damage"]'
touch "$tmp/out"  # the output folder is a file
expect check "case.toml:$((n - 1)): key 'output.directory': output folder '$tmp/out' is a file" ''
rm -f "$tmp/out"
[ $status -eq 0 ] && echo "ok: 9 bad [output] tables rejected with exit 2, file:line and key path"
exit $status
