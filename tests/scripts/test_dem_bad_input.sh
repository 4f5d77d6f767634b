#!/usr/bin/env bash
# Bad DEM case files: `comminute check` exits with 2 and names the file, line, key path and value.
# Each case edits the settle example with sed (one mistake per case).
# usage: test_dem_bad_input.sh <comminute> <source-dir>
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
status=0
count=0
line_of() { grep -n -- "$1" "$src/examples/settle/settle.toml" | head -1 | cut -d: -f1; }
expect() {  # expect <message part> <sed expression>
  local want=$1 edit=$2
  sed -e 's/^count = 3000/count = 10/' -e "$edit" "$src/examples/settle/settle.toml" > "$tmp/case.toml"
  local rc=0
  "$bin" check "$tmp/case.toml" > "$tmp/out" 2>&1 || rc=$?
  count=$((count + 1))
  if [ $rc -ne 2 ] || ! grep -qF -- "$want" "$tmp/out"; then
    echo "FAIL (exit $rc): wanted '$want' after: $edit"
    cat "$tmp/out"
    status=1
  fi
}
l=$(line_of '^density = 2500')
expect "case.toml:$l: key 'materials.glass.densty': unknown key (did you mean 'density'? it is required)" 's/^density = 2500.0/densty = 2500.0/'
l=$(line_of '^youngs_modulus = 5.0e6')
expect "case.toml:$l: key 'materials.glass.youngs_modulus': value nan is not a finite number" '0,/^youngs_modulus = 5.0e6/s//youngs_modulus = nan/'
expect "key 'materials.glass.youngs_modulus': value -5000000 out of range: must be > 0" '0,/^youngs_modulus = 5.0e6/s//youngs_modulus = -5.0e6/'
l=$(line_of '^size = ')
expect "case.toml:$l: key 'insert[0].size.min': value -0.0018 out of range: must be > 0" 's/min = 0.0018/min = -0.0018/'
expect "key 'insert[0].size.max': max (0.001) must exceed min (0.0018)" 's/max = 0.0026/max = 0.001/'
l=$(line_of '^end_time')
expect "case.toml:$l: key 'simulation.end_time': expected a number, got string" 's/^end_time = 0.5 /end_time = "long" /'
expect "key 'simulation': missing required key 'end_time'" '/^end_time/d'
l=$(line_of '^model = ')
expect "case.toml:$l: key 'contact.model': unknown value \"hertz\": expected one of" 's/^model = "hertz_mindlin"/model = "hertz"/'
l=$(line_of '^material = "steel"')
expect "case.toml:$l: key 'walls[0].material': unknown value \"stee\"" 's/^material = "steel"/material = "stee"/'
l=$(line_of '^restitution')
expect "case.toml:$l: key 'interaction.restitution': value 1.5 out of range" 's/^restitution = 0.5/restitution = 1.5/'
l=$(line_of '^open = ')
expect "case.toml:$l: key 'walls[0].open': unknown face \"top\"" 's/^open = \["+z"\]/open = ["top"]/'
expect "key 'walls[0].angular_velocity': a box wall can translate but not rotate" 's/^open = \["+z"\]/open = ["+z"]\nangular_velocity = [0.0, 0.0, 1.0]/'
expect "TOML syntax error" 's/^friction = 0.5/friction = = 0.5/'
expect "key 'insert[0].file'" 's/^type = "fill"/type = "data_file"\nfile = 3/'
expect "key 'insert[0].file': no such file" 's/^type = "fill"/type = "data_file"\nfile = "no-such.data"/'
l=$(line_of '^rolling_friction')
expect "case.toml:$l: key 'interaction.rolling_fricton': unknown key (did you mean 'rolling_friction'?)" 's/^rolling_friction = 0.05/rolling_fricton = 0.05/'
[ $status -eq 0 ] && echo "ok: $count bad DEM case files rejected with exit 2, file:line, key path and value"
exit $status
