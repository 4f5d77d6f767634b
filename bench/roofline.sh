#!/usr/bin/env bash
# Roofline statement of the DEM step (issue 10, point 5), printed as a ready-to-paste markdown
# block for bench/RESULTS.md ("## Roofline"):
#   1. the machine's memory bandwidth, STREAM-type kernel (build/bench/stream_bandwidth) on one and
#      two threads;
#   2. the dense 100k case (bench/cases/dense_100000.toml) under `perf stat` on one and two threads:
#      particle-steps/s, pair-list entries and touching contacts per particle;
#   3. bytes moved per particle-step, counted from the data layout (the model below, derived in
#      bench/RESULTS.md "## Roofline"), times particle-steps/s = achieved bandwidth, and its ratio
#      to STREAM triad;
#   4. `perf record -g` of the one-thread run: the top functions.
# Hardware cache/memory counters are tried (LLC-load-misses); a VM without a PMU reports them as
# not supported, and the block says so.
#
#   bench/roofline.sh                 # build dir "build", 200 warm-up + 1000 timed steps
#   BUILD=build WARMUP=1000 STEPS=2000 PERF_STEPS=300 STREAM_N=33554432 bench/roofline.sh
#   REPORT_ONLY=1 OUT=/tmp/roofline.abc bench/roofline.sh   # the block again from a run's files
#
# Needs bench/data/dense_N100000.data (git-ignored; bench/make_dense_state.sh makes it).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD:-build}
WARMUP=${WARMUP:-200}
STEPS=${STEPS:-1000}
PERF_STEPS=${PERF_STEPS:-300}
STREAM_N=${STREAM_N:-33554432}   # doubles per array: 256 MiB each, 3 arrays, >> L3
CASE=bench/cases/dense_100000.toml
DATA=bench/data/dense_N100000.data
OUT=${OUT:-$(mktemp -d /tmp/roofline.XXXXXX)}
mkdir -p "$OUT"
if [[ -z ${REPORT_ONLY:-} ]]; then  # REPORT_ONLY=1 OUT=dir: print the block from a run's files
[[ -f $DATA ]] || { echo "missing $DATA (run bench/make_dense_state.sh)" >&2; exit 2; }
COMMINUTE_PEERS=1 scripts/install-deps  # perf
cmake --build "$BUILD" -j2 --target stream_bandwidth bench_dem_throughput >/dev/null

echo "== STREAM ($OUT/stream.txt)" >&2
OMP_NUM_THREADS=2 OMP_PROC_BIND=spread "$BUILD/bench/stream_bandwidth" "$STREAM_N" 10 \
  | tee "$OUT/stream.txt" >&2

for t in 1 2; do
  echo "== dense 100k, $t thread(s) ($OUT/dense_t$t.txt)" >&2
  OMP_NUM_THREADS=$t perf stat -x, -o "$OUT/perfstat_t$t.csv" \
    -e task-clock,context-switches,page-faults,cycles,instructions,LLC-load-misses,LLC-loads \
    "$BUILD/bench/bench_dem_throughput" "$CASE" "$WARMUP" "$STEPS" | tee "$OUT/dense_t$t.txt" >&2
done

# CPU time of setup + warm-up alone, subtracted from the one-thread run's: the timed steps' CPU
# time, a rate that a loaded machine does not distort as much as the wall clock
OMP_NUM_THREADS=1 perf stat -x, -o "$OUT/perfstat_t1_zero.csv" -e task-clock \
  "$BUILD/bench/bench_dem_throughput" "$CASE" "$WARMUP" 0 >/dev/null

echo "== perf record -g, one thread, $PERF_STEPS steps ($OUT/perf.data)" >&2
OMP_NUM_THREADS=1 perf record -q -g -o "$OUT/perf.data" \
  "$BUILD/bench/bench_dem_throughput" "$CASE" 20 "$PERF_STEPS" >/dev/null 2>&1
perf report -i "$OUT/perf.data" --no-children --stdio -g none --sort symbol \
  --percent-limit 1.5 2>/dev/null | grep -E '^ +[0-9.]+%' | head -12 >"$OUT/top.txt" || true

echo "$WARMUP $STEPS" >"$OUT/steps.txt"
fi
read -r WARMUP STEPS <"$OUT/steps.txt"

python3 - "$OUT" "$STEPS" "$WARMUP" <<'PY'
import re, sys, os, platform, subprocess
out, steps, warm = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
def kv(line):
    return dict(re.findall(r'(\w+)=([^\s]+)', line))
stream, stream_cpu = {}, {}
for line in open(os.path.join(out, 'stream.txt')):
    if line.startswith('stream threads='):
        d = kv(line); stream[(int(d['threads']), d['kernel'])] = float(d['best_GBps'])
        stream_cpu[(int(d['threads']), d['kernel'])] = float(d['cpu_GBps'])
dense = {}
for t in (1, 2):
    for line in open(os.path.join(out, f'dense_t{t}.txt')):
        if line.startswith('N='): dense[t] = kv(line)
def perf_counter(t, name):
    for line in open(os.path.join(out, f'perfstat_t{t}.csv')):
        f = line.strip().split(',')
        if len(f) > 2 and f[2].startswith(name): return f[0]
    return 'absent'
# Bytes per particle-step (DRAM, compulsory: each array line read once per pass, written back
# once if stored; bench/RESULTS.md "## Roofline" derives each term from the code):
#   kick_drift  reads flags 4, mass 8, inertia 8, f 24, t 24, v 24, w 24, x 24, x_build 24 = 164,
#               writes v, w, x, f, t = 120                                          -> 284 B/particle
#   pair loop   reads x, v, w, f, t 5x24, radius, mass, inertia 3x8, material 2 = 146,
#               writes f, t = 48                                                     -> 194 B/particle
#               first 4 + second 4 + active 1 read + 1 written                      ->  10 B/pair entry
#               tangential spring (total form) 24 read + 24 written                 ->  48 B/contact
#   kick        reads flags 4, mass 8, inertia 8, f, t, v, w, x 5x24 = 140, writes v, w = 48
#                                                                                   -> 188 B/particle
B_PARTICLE, B_PAIR, B_CONTACT = 284 + 194 + 188, 10, 48
cpu = platform.processor() or ''
try:
    cpu = [l.split(':', 1)[1].strip() for l in open('/proc/cpuinfo') if l.startswith('model name')][0]
except Exception: pass
load = open('/proc/loadavg').read().split()[:3]
triad1, triad2 = stream.get((1, 'triad'), float('nan')), stream.get((2, 'triad'), float('nan'))
print()
print('## Roofline (issue 10, point 5)')
print()
print(f'Machine: {cpu}, {os.cpu_count()} cores; load average at the end {" / ".join(load)}. '
      f'Command: `bench/roofline.sh` (WARMUP={warm} STEPS={steps}).')
print()
nan = float('nan')
print('| kernel | 1 thread GB/s | 2 threads GB/s | 1 thread, CPU time | 2 threads, CPU time |')
print('|---|---|---|---|---|')
for k in ('copy', 'scale', 'add', 'triad'):
    print(f'| STREAM {k} | {stream.get((1,k),nan):.2f} | {stream.get((2,k),nan):.2f} | '
          f'{stream_cpu.get((1,k),nan):.2f} | {stream_cpu.get((2,k),nan):.2f} |')
print()
print('STREAM counting (copy, scale 16 B, add, triad 24 B per element; best of 9 repeats): "GB/s" over '
      'the wall time, "CPU time" over the process CPU time per thread (the two agree on an idle machine).')
print()
def task_clock_s(name):
    for line in open(os.path.join(out, name)):
        f = line.strip().split(',')
        if len(f) > 2 and f[2].startswith('task-clock'): return float(f[0]) * 1e-3
    return float('nan')
cpu_steps_s = task_clock_s('perfstat_t1.csv') - task_clock_s('perfstat_t1_zero.csv')
print('| dense 100k | particle-steps/s | pairs/particle | contacts/particle | B/particle-step '
      '| achieved GB/s | of STREAM triad | LLC-load-misses |')
print('|---|---|---|---|---|---|---|---|')
for t in (1, 2):
    d = dense[t]
    n, rate = float(d['N']), float(d['particle_steps_per_s'])
    pairs, contacts = float(d['pairs']) / n, float(d['contacts']) / n
    b = B_PARTICLE + B_PAIR * pairs + B_CONTACT * contacts
    gbs = b * rate * 1e-9
    ref = triad1 if t == 1 else triad2
    llc = perf_counter(t, 'LLC-load-misses')
    print(f'| {t} thread{"s" if t > 1 else ""} | {rate:.3g} | {pairs:.2f} | {contacts:.2f} | '
          f'{b:.0f} | {gbs:.2f} | {100 * gbs / ref:.0f} % | {llc} |')
d1 = dense[1]
cpu_rate = float(d1['N']) * steps / cpu_steps_s
b1 = B_PARTICLE + B_PAIR * float(d1['pairs']) / float(d1['N']) + B_CONTACT * float(d1['contacts']) / float(d1['N'])
triad1_cpu = stream_cpu.get((1, 'triad'), nan)
print(f'| 1 thread, CPU time | {cpu_rate:.3g} | | | {b1:.0f} | {b1 * cpu_rate * 1e-9:.2f} | '
      f'{100 * b1 * cpu_rate * 1e-9 / triad1_cpu:.0f} % (CPU-time triad) | |')
print()
print('particle-steps/s: the timed steps over their wall time (bench_dem_throughput); "CPU time": '
      'over their CPU time (perf stat task-clock of the run minus that of setup and warm-up alone).')
print()
print(f'Bytes per particle-step = {B_PARTICLE} + {B_PAIR} x pairs/particle + {B_CONTACT} x '
      'contacts/particle (the count below).')
print()
print('Top functions, one thread (`perf record -g`, cpu-clock, self time):')
print()
print('```')
for line in open(os.path.join(out, 'top.txt')):
    print(line[:140].rstrip())
print('```')
PY
