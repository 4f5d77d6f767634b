#!/usr/bin/env bash
# The HPGR texture study (examples/hpgr_texture, issue 12 point 6): the sweep driver writes its 8
# cases from the template, each with the criterion's and the phases' relative strengths set to
# the case's values (f_rel of the target in {0.5, 1, 2, 4, 6, 13.21} against the matrix, and two
# homogeneous controls at the mean phase weight 0.767 + 0.233 f_rel of f_rel = 4 and 13.21), and
# `comminute check` accepts every one (it refuses a criterion list that differs from the phases').
set -euo pipefail
bin="$1"
src="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

/usr/bin/python3 "$src/examples/hpgr_texture/sweep.py" --write-only --out "$work" > "$work/log" ||
  { cat "$work/log"; exit 1; }
expect() {  # case, criterion list, matrix value, target value
  local f="$work/$1/case.toml"
  grep -q "^relative_strength = \[$2\] " "$f" || { echo "$1: criterion list not [$2]"; exit 1; }
  [ "$(grep -c "^relative_strength = $3 .*@sweep matrix" "$f")" = 1 ] ||
    { echo "$1: matrix not $3"; exit 1; }
  [ "$(grep -c "^relative_strength = $4 .*@sweep target" "$f")" = 1 ] ||
    { echo "$1: target not $4"; exit 1; }
}
expect frel_0.5 "1.0, 0.5" 1.0 0.5
expect frel_1 "1.0, 1.0" 1.0 1.0
expect frel_13.21 "1.0, 13.21" 1.0 13.21
# 0.767 + 0.233 * 4 = 1.699 and 0.767 + 0.233 * 13.21 = 3.84493 (Python's repr of the sums)
expect homogeneous_4 "1.699, 1.699" 1.699 1.699
grep -q '^relative_strength = \[3.8449[0-9]*, 3.8449[0-9]*\]' "$work/homogeneous_13.21/case.toml" ||
  { echo "homogeneous_13.21: criterion list wrong"; exit 1; }
n=0
for c in "$work"/*/case.toml; do
  "$bin" check "$c" > "$work/check.log" 2>&1 || { cat "$work/check.log"; exit 1; }
  n=$((n + 1))
done
[ "$n" = 8 ] || { echo "$n cases written, expected 8"; exit 1; }
# the check does refuse a case whose criterion and phases disagree (exit code 2)
sed -e 's/^relative_strength = 4.0 /relative_strength = 5.0 /' \
  "$src/examples/hpgr_texture/hpgr_texture.toml" > "$work/bad.toml"
set +e
"$bin" check "$work/bad.toml" > "$work/bad.log" 2>&1
rc=$?
set -e
[ "$rc" = 2 ] || { echo "mismatched strengths: exit code $rc"; cat "$work/bad.log"; exit 1; }
echo "8 cases written and checked"
