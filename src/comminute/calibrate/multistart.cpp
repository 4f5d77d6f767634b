#include "comminute/calibrate/multistart.hpp"

#include <omp.h>

#include <cmath>
#include <exception>
#include <mutex>

#include "comminute/core/rng.hpp"

namespace comminute::calibrate {

MultiStartResult multistart(
    const ParameterSpace& space, const std::function<double(const std::vector<double>&)>& f,
    const MultiStartOptions& o,
    const std::function<void(std::size_t, std::size_t, const StartResult&)>& progress) {
  const std::size_t n = space.size();
  Rng rng(o.seed, rng_stream::calibration);
  std::vector<Point> u0(o.starts, Point(n));
  for (auto& u : u0)
    for (double& x : u) x = rng.uniform();
  auto in_unit = [&](const Point& u) {
    const double fc = f(space.to_parameters(u));
    const double d2 = ParameterSpace::outside2(u);
    return d2 == 0 ? fc : fc + (std::abs(fc) + 1.0) * 1e3 * d2;
  };
  MultiStartResult res;
  res.starts.resize(o.starts);
  std::mutex m;
  std::size_t done = 0;
  std::exception_ptr error;
  const int threads = o.threads > 0 ? o.threads : omp_get_max_threads();
  const auto count = static_cast<long>(o.starts);
#pragma omp parallel for schedule(static, 1) num_threads(threads)
  for (long s = 0; s < count; ++s) {
    try {
      const auto k = static_cast<std::size_t>(s);
      StartResult r;
      r.index = k;
      r.start = space.to_parameters(u0[k]);
      r.run = nelder_mead(in_unit, unit_box_simplex(u0[k], o.simplex_step), o.nelder_mead);
      r.best = space.to_parameters(r.run.x);
      r.f = r.run.f;
      std::lock_guard<std::mutex> lock(m);
      res.starts[k] = r;
      ++done;
      if (progress) progress(done, o.starts, r);
    } catch (...) {
      std::lock_guard<std::mutex> lock(m);
      if (!error) error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);
  for (std::size_t k = 1; k < res.starts.size(); ++k)
    if (res.starts[k].f < res.starts[res.best].f) res.best = k;
  return res;
}

}  // namespace comminute::calibrate
