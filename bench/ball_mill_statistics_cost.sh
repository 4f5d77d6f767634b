#!/usr/bin/env bash
# Cost of the collision log and grid statistics together on the ball-mill rig (issue 13, <= 15 %):
# examples/ball_mill/ball_mill.toml shortened to 1.5 s without particle snapshots, run without
# [collisions] and with [collisions] + a [grid_statistics] cylinder (10 x 72 x 8 cells turning
# with the mill), alternated; prints user CPU seconds of each run.
#   bench/ball_mill_statistics_cost.sh [BIN] [PAIRS]     default build/bin/comminute, 7 pairs
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build/bin/comminute}
pairs=${2:-7}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 - "$work" <<'PY'
import re, sys
work = sys.argv[1]
s = open('examples/ball_mill/ball_mill.toml').read()
s = s.replace('end_time = 4.0', 'end_time = 1.5')
s = s.replace('[output]\n', '[output]\nparticles = false\n', 1)
s = s.replace('stl_file = "output/mill.stl"', f'stl_file = "{work}/mill.stl"')
grid = '''
[grid_statistics]
shape = "cylinder"
origin = [0.0, -0.1525, 0.0]
axis = [0.0, 1.0, 0.0]
radius = 0.1525
inner_radius = 0.0
z_min = 0.0
z_max = 0.305
cells = [10, 72, 8]
rotate_with = "mill"
start = 0.5
every = 10
'''
open(f'{work}/with.toml', 'w').write(s.replace('[output]\n', grid + '\n[output]\n', 1))
open(f'{work}/without.toml', 'w').write(re.sub(r'\[collisions\]\n(.*?\n)\n', '', s, flags=re.S))
PY
for i in $(seq 1 "$pairs"); do
  for v in without with; do
    /usr/bin/time -f "$v user_s=%U wall_s=%e" "$bin" run --threads 1 "$work/$v.toml" >/dev/null 2>"$work/err"
    tail -1 "$work/err"
  done
done
