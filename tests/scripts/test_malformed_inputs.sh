#!/usr/bin/env bash
# The malformed-input corpus tests/malformed/*.toml: `comminute check` must refuse every file with
# exit 2 and the message its first line announces (`# expect: <text>`), which names the file (or
# the data file), the line and the key. The valid base the families are cut from must pass.
# usage: test_malformed_inputs.sh <comminute> <source-dir>
set -euo pipefail
bin=$1 src=$2
dir="$src/tests/malformed"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
status=0 count=0
base="$tmp/valid_base.toml"
cp "$dir/valid_base.toml.in" "$base"
if ! "$bin" check "$base" > "$tmp/out" 2>&1; then
  echo "FAIL: the valid base case is refused"; cat "$tmp/out"; status=1
fi
for f in "$dir"/*.toml; do
  name=$(basename "$f")
  want=$(head -1 "$f" | sed -n 's/^# expect: //p')
  rc=0
  (cd "$tmp" && "$bin" check "$f") > "$tmp/out" 2>&1 || rc=$?
  count=$((count + 1))
  if [ -z "$want" ]; then
    echo "FAIL: $name has no '# expect:' first line"; status=1; continue
  fi
  # the message names the case file (or the data file it refers to) with a line number
  if [ $rc -ne 2 ] || ! grep -qF -- "$want" "$tmp/out" ||
     ! grep -qE -- "($name|\.data):[0-9]+: " "$tmp/out"; then
    echo "FAIL (exit $rc): $name: wanted '$want'"
    cat "$tmp/out"
    status=1
  fi
done
[ $status -eq 0 ] && echo "ok: $count malformed case files refused with exit 2, file, line and key"
exit $status
