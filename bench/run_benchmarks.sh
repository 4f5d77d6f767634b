#!/usr/bin/env bash
# DEM throughput of comminute against the peer codes on the same cases, in one run, on this machine:
#   settle N=20000, settle N=100000 (the peers' case A, shared/bench/peers), dense N=100000 (a
#   settled packing, bench/make_dense_state.sh; the peers run it with their own settle decks, which
#   read any data file with the same walls) and drum N=20000 (the peers' case B: the STL drum side
#   turning at 30 rpm, static end walls; the peers run their in.drum decks; only with CASES).
# Each run: 1000 warm-up steps, then 2000 timed steps (each code's own timer for those steps).
# Writes bench/logs/*.log and the table bench/logs/dem_results.md (copied into bench/RESULTS.md by
# hand, with the date and the machine's load).
#   REPS=3 bench/run_benchmarks.sh      repetitions per configuration (median reported), default 1
#   CASES="settle20k" bench/run_benchmarks.sh
#   CASES="drum20k" bench/run_benchmarks.sh
#   WARM=20 STEPS=20 CASES="drum20k" bench/run_benchmarks.sh   smoke test of the chain (default 1000, 2000)
# Every code's one-thread runs are pinned to the same core (PIN1, default 0; PIN1= leaves them to
# the scheduler): the cores of a VM need not be alike (on one 2-core VM one core ran the drum 27 %
# slower than the other, bench/RESULTS.md), and an unpinned run lands on either. Two-thread runs
# bind one thread per core (OMP_PROC_BIND=true), as the peers' MPI ranks are bound by mpirun.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
peers=${PEERS_DIR:-$(cd "$root/../shared/bench/peers" && pwd)}
reps=${REPS:-1}
pin1=${PIN1-0}
warm=${WARM:-1000}
steps=${STEPS:-2000}
cases=${CASES:-"settle20k settle100k dense100k"}
COMMINUTE_PEERS=1 scripts/install-deps
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)" --target bench_dem_throughput bench_make_dense_state >/dev/null
case " $cases " in *" dense100k "*) [ -f bench/data/dense_N100000.data ] || bench/make_dense_state.sh ;; esac
mkdir -p bench/logs
# one sitting per run: the summary takes medians over every *_rN.log, so logs of an earlier sitting
# must not stay beside this one's
rm -f bench/logs/*_r[0-9]*.log bench/logs/*_r[0-9]*.log.time
# the machine and its load at the start, for the summary's first line (ratios from different
# processors are not comparable: bench/RESULTS.md, thirty-sixth stop)
{ grep -m1 "model name" /proc/cpuinfo | sed 's/.*: //'; nproc; date -u +"%Y-%m-%d %H:%M UTC";
  cut -d' ' -f1 /proc/loadavg; } > bench/logs/machine.txt
data_of() {
  case $1 in
    settle20k) echo "$peers/data/settle_N20000.data" ;;
    settle100k) echo "$peers/data/settle_N100000.data" ;;
    dense100k) echo "$root/bench/data/dense_N100000.data" ;;
    drum20k) echo "$peers/data/drum_N20000.data" ;;
  esac
}
toml_of() {
  case $1 in
    settle20k) echo bench/cases/settle_20000.toml ;;
    settle100k) echo bench/cases/settle_100000.toml ;;
    dense100k) echo bench/cases/dense_100000.toml ;;
    drum20k) echo bench/cases/drum_20000.toml ;;
  esac
}
deck_of() {  # the peers' input deck: in.drum for the drum, in.settle for the flat-walled bins
  case $1 in
    drum20k) echo in.drum ;;
    *) echo in.settle ;;
  esac
}
for rep in $(seq 1 "$reps"); do
  for c in $cases; do
    for np in 1 2; do
      pin=""; [ "$np" -eq 1 ] && [ -n "$pin1" ] && pin="taskset -c $pin1"
      log=bench/logs/comminute_${c}_p${np}_r${rep}.log
      OMP_PROC_BIND=true OMP_NUM_THREADS=$np $pin build/bench/bench_dem_throughput "$(toml_of "$c")" "$warm" "$steps" > "$log" 2>&1
      echo "comminute $c $np: $(tail -1 "$log")"
      for code in liggghts lammps; do
        log=$root/bench/logs/${code}_${c}_p${np}_r${rep}.log
        exe=liggghts; [ $code = lammps ] && exe="lmp -nocite"
        mpi=""; [ "$np" -gt 1 ] && mpi="mpirun --allow-run-as-root -np $np"
        (cd "$peers/$code" && OMP_NUM_THREADS=1 $pin /usr/bin/time -v -o "$log.time" $mpi $exe -in "$(deck_of "$c")" \
          -var data "$(data_of "$c")" -var warm "$warm" -var steps "$steps" -log none) > "$log" 2>&1 || echo "FAILED: $log"
        echo "$code $c $np: $(grep 'Loop time' "$log" | tail -1)"
      done
    done
  done
done
/usr/bin/python3 bench/summarize_dem.py bench/logs | tee bench/logs/dem_results.md
