#!/usr/bin/env bash
# `comminute pbm` and `comminute calibrate` from the command line: the examples run and write
# their CSV files; bad input fails with exit code 2 and names the key (or file and column) and
# the line.   usage: test_pbm_cli.sh <comminute> <source-dir>
set -uo pipefail
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$src"/examples/pbm/*.toml "$src"/examples/pbm/*.csv "$work"/
cd "$work"
fail=0
check() {  # check <description> <condition...>
  local what=$1
  shift
  if "$@"; then echo "ok: $what"; else echo "FAIL: $what"; fail=1; fi
}

# --- the examples run, conserve mass and write complete CSV files (plots skipped: speed)
for c in batch_grinding carbon_black ball_mill_spectrum ball_mill_ufrj; do
  out=$("$bin" pbm --no-plots $c.toml 2>&1)
  rc=$?
  check "$c runs (rc $rc)" test $rc -eq 0
  drift=$(echo "$out" | sed -n 's/.*relative change of total mass \([-0-9.e+]*\).*/\1/p')
  check "$c mass drift $drift below 1e-12" python3 -c "import sys; sys.exit(abs(float('$drift')) >= 1e-12)"
  check "$c distributions.csv header" grep -q '^time \[s\],class \[-\],size_lower \[m\],size_upper \[m\]' ${c}_out/distributions.csv
  check "$c no partial files" test -z "$(ls ${c}_out/*.part 2>/dev/null)"
done

# --- bad input: exit code 2 and a message naming key/file, and line
expect_error() {  # expect_error <description> <case> <text that must appear>
  local what=$1 case=$2 text=$3
  out=$("$bin" pbm --no-plots "$case" 2>&1)
  rc=$?
  check "$what: exit code 2 (got $rc)" test $rc -eq 2
  check "$what: message names '$text' ($out)" grep -qF -- "$text" <<<"$out"
}

sed -e 's/^spacing = "geometric".*/spacing = "edges"\nedges = [1e-4, 3e-4, 2e-4, 1e-3, 2.36e-3]/' \
    -e '/^top = /d' -e '/^ratio = /d' -e '/^classes = /d' -e 's/^size = 1.4e-3.*/size = 2e-3/' \
    batch_grinding.toml > bad_grid.toml
line=$(grep -n '^edges' bad_grid.toml | cut -d: -f1)
expect_error "non-monotone grid" bad_grid.toml "bad_grid.toml:$line: key 'grid.edges'"

sed -e 's/^kind = "monodisperse".*/kind = "fractions"/' \
    -e 's/^size = 1.4e-3.*/fractions = [0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.05, 0.05, 0.05, 0.05, 0.05, 0.05, 0.05, 0.05, 0.05, 0.05]/' \
    batch_grinding.toml > bad_sum.toml
line=$(grep -n '^fractions' bad_sum.toml | cut -d: -f1)
expect_error "fractions not summing to one" bad_sum.toml "bad_sum.toml:$line: key 'initial.fractions': fractions sum to 1.5"

sed -e 's/^nu = 27.6/nu = 1.5/' carbon_black.toml > bad_nu.toml
line=$(grep -n '^nu = 1.5' bad_nu.toml | cut -d: -f1)
expect_error "nu below 2" bad_nu.toml "bad_nu.toml:$line: key 'breakage.population[1].nu': value 1.5 out of range: must be >= 2"

sed -e 's/^k = 0.012 .*/k = -0.012/' batch_grinding.toml > bad_rate.toml
line=$(grep -n '^k = ' bad_rate.toml | cut -d: -f1)
expect_error "negative rate" bad_rate.toml "bad_rate.toml:$line: key 'rate.k': value -0.012 out of range"

printf 'size_m,passing\n1e-4,0.2\n1e-3,1.0\n' > feed.csv
sed -e 's/^kind = "monodisperse".*/kind = "table"/' -e 's/^size = 1.4e-3.*/file = "feed.csv"/' \
    batch_grinding.toml > bad_csv.toml
expect_error "CSV without a needed column" bad_csv.toml "feed.csv:1: key 'initial.file': missing column 'cumulative_passing' (header has: size_m, passing)"

printf 'size_m,cumulative_passing\n1e-4,0.2\n2e-4,oops\n' > feed2.csv
sed -e 's/feed.csv/feed2.csv/' bad_csv.toml > bad_value.toml
expect_error "CSV with a non-number" bad_value.toml "feed2.csv:3: key 'initial.file': column 'cumulative_passing': 'oops'"

sed -e 's/^spacing = "geometric".*/spacing = "geometric"\nratioo = 2.0/' batch_grinding.toml > bad_key.toml
expect_error "unknown key" bad_key.toml "key 'grid.ratioo': unknown key (did you mean 'ratio'?)"

# --- `comminute check` reads a population balance as `pbm` does (no run, no output folder), a
# fit as `calibrate` does, and refuses what they refuse, with the same message
for c in batch_grinding carbon_black ball_mill_spectrum ball_mill_ufrj calibrate_carbon_black; do
  out=$("$bin" check $c.toml 2>&1)
  rc=$?
  check "check $c (rc $rc)" test $rc -eq 0
  check "check $c says what it is ($out)" grep -qF "$c.toml: valid population-balance case" <<<"$out"
done
mkdir fresh && cp batch_grinding.toml fresh/
"$bin" check fresh/batch_grinding.toml > /dev/null 2>&1
check "check writes no output folder" test -z "$(ls -A fresh | grep -v '^batch_grinding.toml$')"
out=$("$bin" check calibrate_carbon_black.toml 2>&1)
check "check of a fit names its command and free parameters ($out)" \
  grep -qF "(comminute calibrate)" <<<"$out"
check "check of a fit counts its free parameters" grep -qF "6 free parameter(s)" <<<"$out"
check_refuses() {  # check_refuses <description> <case> <text that must appear>
  out=$("$bin" check "$2" 2>&1)
  rc=$?
  check "check, $1: exit code 2 (got $rc)" test $rc -eq 2
  check "check, $1: message names '$3' ($out)" grep -qF -- "$3" <<<"$out"
}
check_refuses "non-monotone grid" bad_grid.toml \
  "bad_grid.toml:$(grep -n '^edges' bad_grid.toml | cut -d: -f1): key 'grid.edges'"
check_refuses "unknown key" bad_key.toml "key 'grid.ratioo': unknown key (did you mean 'ratio'?)"
sed -e 's/^starts = 15/starts = 15\nstartz = 3/' calibrate_carbon_black.toml > bad_cal_key.toml
check_refuses "unknown key of a fit" bad_cal_key.toml "key 'calibration.startz': unknown key"
# a DEM case without [simulation] and without a size grid is still read as a DEM case
printf '[contact]\nmodel = "hertz_mindlin"\n' > no_simulation.toml
check_refuses "DEM case without [simulation]" no_simulation.toml "missing required key 'simulation'"

# --- the ball-mill rates (docs/pbm.md): capece's impact distribution must sum to one; the
# energy-spectrum keys belong to the _variant rates; the old names are unknown models
sed -e '$s/,[^,]*$/,0.5/' ball_mill_impacts.csv > bad_impacts.csv   # the last row's probability
sed -e 's/^specific_energy_file = .*/specific_energy_file = "bad_impacts.csv"/' ball_mill_spectrum.toml > bad_impacts.toml
line=$(wc -l < bad_impacts.csv)
check "bad_impacts.csv was made" grep -q ',0.5$' bad_impacts.csv
expect_error "capece probabilities not summing to one" bad_impacts.toml "bad_impacts.csv:$line: key 'rate.specific_energy_file': the probabilities sum to"

edited_case_fails() {  # <description> <sed expression> <new case> <line pattern> <message>
  sed -e "$2" ball_mill_spectrum.toml > "$3"
  expect_error "$1" "$3" "$3:$(grep -n -- "$4" "$3" | cut -d: -f1): $5"
}
edited_case_fails "capece with a skeleton key" 's/^impact_frequency = .*/impact_frequency = 4.0\nholdup = 0.5/' \
  bad_holdup.toml '^holdup' "key 'rate.holdup': capece takes"
edited_case_fails "old model name" 's/^model = "capece"/model = "tuzcu_rajamani"/' \
  old_name.toml '^model = ' "key 'rate.model'"
check "old model name: the known names include the variant" grep -qF "tuzcu_rajamani_variant" <<<"$out"

# --- calibrate: measured data without the passing column
sed -e 's/^cumulative_passing/x/' -e 's/^size_m,cumulative_passing/size_m,fraction/' measured_60s.csv > m_bad.csv
sed -e 's/"measured_60s.csv"/"m_bad.csv"/' calibrate_carbon_black.toml > bad_cal.toml
out=$("$bin" calibrate --no-plots bad_cal.toml 2>&1)
rc=$?
check "calibrate with a bad CSV: exit code 2 (got $rc)" test $rc -eq 2
check "calibrate names the file and column ($out)" grep -qF "m_bad.csv:2: key 'calibration.data[1].file': missing column 'cumulative_passing'" <<<"$out"

sed -e '0,/^min = 2.0 .*/s//min = 1.0/' calibrate_carbon_black.toml > bad_bound.toml
out=$("$bin" calibrate --no-plots bad_bound.toml 2>&1)
rc=$?
check "calibrate with a bound the model rejects: exit 2 (got $rc)" test $rc -eq 2
check "calibrate names the parameter bound ($out)" grep -qF "key 'calibration.parameter[1].min': the model rejects this bound" <<<"$out"

# --- calibrate runs: a short run (2 starts) over two data sets, one on another case with a
# coarser feed that shares the free keys; every start is reported and the fit is written
sed -e '/^\[calibration\]/,$d' -e 's/^median = 6e-4/median = 8e-4/' calibrate_carbon_black.toml > other.toml
sed -e 's/^starts = 15/starts = 2/' -e 's/^max_evaluations = 600 .*/max_evaluations = 40/' \
    -e 's/^directory = "calibrate_carbon_black_out"/directory = "short_out"/' calibrate_carbon_black.toml > short.toml
printf '\n[[calibration.data]]\nfile = "measured_60s.csv"\ntime = 60.0\ncase = "other.toml"\n' >> short.toml
out=$("$bin" calibrate --no-plots short.toml 2>&1)
rc=$?
check "short calibration runs (rc $rc)" test $rc -eq 0
check "progress line per start" test "$(grep -c 'starts done' <<<"$out")" -eq 2
check "starts.csv has a row per start" test "$(grep -vc '^start \[-\],' short_out/starts.csv)" -eq 2
check "fit.csv covers all three data sets" test "$(cut -d, -f1 short_out/fit.csv | sort -u | grep -vc 'dataset \[-\]')" -eq 3
check "best_parameters.csv names the keys" grep -q '^rate.sigma_inf,' short_out/best_parameters.csv

# --- a failing plot script warns and does not fail the run
out=$(COMMINUTE_PLOT_SCRIPT=/nonexistent/plot.py "$bin" pbm batch_grinding.toml 2>&1)
rc=$?
check "plot failure is a warning (rc $rc)" test $rc -eq 0
check "plot failure warning printed" grep -q 'warning: plotting failed' <<<"$out"

exit $fail
