// Memory bandwidth of this machine, STREAM style (McCalpin, IEEE TCCA Newsletter 1995): the four
// kernels copy a = b, scale a = q b, add a = b + c, triad a = b + q c on three arrays of doubles
// far larger than the last-level cache, on 1, 2, ... up to OMP_NUM_THREADS threads.
//   stream_bandwidth [doubles_per_array=2^25] [repeats=10]
// Bytes counted the STREAM way: 16 n for copy and scale, 24 n for add and triad (the write-allocate
// read of the destination, which plain stores also cause, is not counted). Each array is first
// touched by the thread that later streams it (static schedule), the first repeat is dropped, and
// the best of the rest is reported with the median. One line per thread count and kernel:
//   stream threads=T kernel=K bytes=B best_s=.. best_GBps=.. median_GBps=.. cpu_GBps=..
// cpu_GBps divides by the process CPU time per thread instead of the wall time (best repeat): on a
// machine shared with other work, whose time slices stretch the wall time, it estimates what the
// memory delivers while the kernel runs.
// bench/roofline.sh runs it as the bandwidth ceiling of the roofline statement in bench/RESULTS.md.
#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <string>
#include <vector>

namespace {

// A[0..n) of doubles, not initialised: the first touch (which places the pages) is the caller's.
struct Array {
  explicit Array(std::size_t n) : data(new double[n]) {}
  std::unique_ptr<double[]> data;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) {
  const long n_arg = argc > 1 ? std::atol(argv[1]) : (1L << 25);
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 10;
  if (n_arg < 1024 || repeats < 2) {
    fmt::print(stderr, "usage: {} [doubles_per_array>=1024] [repeats>=2]\n", argv[0]);
    return 2;
  }
  const auto n = static_cast<std::size_t>(n_arg);
  const int max_t = omp_get_max_threads();
  Array A(n), B(n), C(n);
  double* a = A.data.get();
  double* b = B.data.get();
  double* c = C.data.get();
  const double q = 3.0;
  fmt::print("stream arrays=3 doubles_per_array={} MiB_per_array={:.0f} max_threads={}\n", n,
             static_cast<double>(n) * 8.0 / (1024.0 * 1024.0), max_t);
  struct Kernel {
    const char* name;
    double words;  // doubles moved per element
  };
  const Kernel kernels[] = {{"copy", 2}, {"scale", 2}, {"add", 3}, {"triad", 3}};
  double check = 0;
  for (int nt = 1; nt <= max_t; ++nt) {
#pragma omp parallel for schedule(static) num_threads(nt)
    for (std::size_t i = 0; i < n; ++i) {
      a[i] = 1.0;
      b[i] = 2.0;
      c[i] = 0.0;
    }
    for (int kk = 0; kk < 4; ++kk) {
      std::vector<double> t(static_cast<std::size_t>(repeats)), cpu(t.size());
      for (int r = 0; r < repeats; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        const double c0 = process_cpu_seconds();
        switch (kk) {
          case 0:
#pragma omp parallel for schedule(static) num_threads(nt)
            for (std::size_t i = 0; i < n; ++i) c[i] = a[i];
            break;
          case 1:
#pragma omp parallel for schedule(static) num_threads(nt)
            for (std::size_t i = 0; i < n; ++i) b[i] = q * c[i];
            break;
          case 2:
#pragma omp parallel for schedule(static) num_threads(nt)
            for (std::size_t i = 0; i < n; ++i) c[i] = a[i] + b[i];
            break;
          default:
#pragma omp parallel for schedule(static) num_threads(nt)
            for (std::size_t i = 0; i < n; ++i) a[i] = b[i] + q * c[i];
            break;
        }
        t[static_cast<std::size_t>(r)] = seconds_since(t0);
        cpu[static_cast<std::size_t>(r)] = (process_cpu_seconds() - c0) / nt;
      }
      t.erase(t.begin());  // the first repeat pays for page faults and cold TLBs
      cpu.erase(cpu.begin());
      std::sort(t.begin(), t.end());
      const double cpu_best = *std::min_element(cpu.begin(), cpu.end());
      const double bytes = kernels[kk].words * 8.0 * static_cast<double>(n);
      const double best = t.front(), median = t[t.size() / 2];
      fmt::print(
          "stream threads={} kernel={} bytes={:.0f} best_s={:.5f} best_GBps={:.2f} "
          "median_GBps={:.2f} cpu_GBps={:.2f}\n",
          nt, kernels[kk].name, bytes, best, bytes / best * 1e-9, bytes / median * 1e-9,
          bytes / cpu_best * 1e-9);
    }
    check += a[n / 2] + b[n / 3] + c[n - 1];
  }
  // Keeps the stores observable; the values are fixed by the kernels (STREAM's own check).
  fmt::print("stream checksum={:.6g}\n", check);
  return 0;
}
