#include "comminute/calibrate/nelder_mead.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "comminute/core/error.hpp"

namespace comminute::calibrate {

NelderMeadOptions NelderMeadOptions::adaptive(std::size_t dimension) {
  const double n = static_cast<double>(dimension);
  NelderMeadOptions o;
  o.chi = 1 + 2 / n;
  o.psi = 0.75 - 1 / (2 * n);
  o.sigma = 1 - 1 / n;
  return o;
}

std::vector<Point> fminsearch_simplex(const Point& x0) {
  std::vector<Point> s{x0};
  for (std::size_t j = 0; j < x0.size(); ++j) {
    Point y = x0;
    y[j] = y[j] != 0 ? 1.05 * y[j] : 0.00025;
    s.push_back(y);
  }
  return s;
}

std::vector<Point> unit_box_simplex(const Point& x0, double step) {
  std::vector<Point> s{x0};
  for (std::size_t j = 0; j < x0.size(); ++j) {
    Point y = x0;
    y[j] += y[j] + step <= 1 ? step : -step;
    s.push_back(y);
  }
  return s;
}

namespace {
// a·x + b·y, elementwise.
Point combine(double a, const Point& x, double b, const Point& y) {
  Point r(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) r[i] = a * x[i] + b * y[i];
  return r;
}
}  // namespace

NelderMeadResult nelder_mead(const Objective& f, std::vector<Point> sim,
                             const NelderMeadOptions& o) {
  const std::size_t n = sim.empty() ? 0 : sim[0].size();
  if (n == 0 || sim.size() != n + 1) throw Error("nelder_mead: need n + 1 points of dimension n");
  const std::size_t max_eval = o.max_evaluations ? o.max_evaluations : 200 * n;
  const std::size_t max_iter = o.max_iterations ? o.max_iterations : 200 * n;
  NelderMeadResult r;
  r.iterations = 1;  // the initial simplex counts as iteration 1, as in fminsearch and SciPy
  auto eval = [&](const Point& x) {
    ++r.evaluations;
    const double v = f(x);
    return std::isnan(v) ? std::numeric_limits<double>::infinity() : v;
  };
  std::vector<double> fs(n + 1);
  for (std::size_t j = 0; j <= n; ++j) fs[j] = eval(sim[j]);
  auto sort = [&] {
    std::vector<std::size_t> idx(n + 1);
    std::iota(idx.begin(), idx.end(), 0);
    std::stable_sort(idx.begin(), idx.end(), [&](auto a, auto b) { return fs[a] < fs[b]; });
    std::vector<Point> s2;
    std::vector<double> f2;
    for (auto i : idx) {
      s2.push_back(sim[i]);
      f2.push_back(fs[i]);
    }
    sim.swap(s2);
    fs.swap(f2);
  };
  sort();
  while (r.evaluations < max_eval && r.iterations < max_iter) {
    double xspread = 0, fspread = 0;
    for (std::size_t j = 1; j <= n; ++j) {
      fspread = std::max(fspread, std::abs(fs[0] - fs[j]));
      for (std::size_t i = 0; i < n; ++i)
        xspread = std::max(xspread, std::abs(sim[j][i] - sim[0][i]));
    }
    if (xspread <= o.x_tolerance &&
        fspread <= o.f_tolerance + o.f_relative_tolerance * std::abs(fs[0])) {
      r.converged = true;
      break;
    }
    Point xbar(n, 0.0);
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t i = 0; i < n; ++i) xbar[i] += sim[j][i];
    for (double& v : xbar) v /= static_cast<double>(n);
    const Point xr = combine(1 + o.rho, xbar, -o.rho, sim[n]);
    const double fr = eval(xr);
    bool shrink = false;
    if (fr < fs[0]) {
      const Point xe = combine(1 + o.rho * o.chi, xbar, -o.rho * o.chi, sim[n]);
      const double fe = eval(xe);
      if (fe < fr) {
        sim[n] = xe, fs[n] = fe;
        ++r.expansions;
      } else {
        sim[n] = xr, fs[n] = fr;
        ++r.reflections;
      }
    } else if (fr < fs[n - 1]) {
      sim[n] = xr, fs[n] = fr;
      ++r.reflections;
    } else if (fr < fs[n]) {
      const Point xc = combine(1 + o.psi * o.rho, xbar, -o.psi * o.rho, sim[n]);
      const double fc = eval(xc);
      if (fc <= fr) {
        sim[n] = xc, fs[n] = fc;
        ++r.outside_contractions;
      } else {
        shrink = true;
      }
    } else {
      const Point xcc = combine(1 - o.psi, xbar, o.psi, sim[n]);
      const double fcc = eval(xcc);
      if (fcc < fs[n]) {
        sim[n] = xcc, fs[n] = fcc;
        ++r.inside_contractions;
      } else {
        shrink = true;
      }
    }
    if (shrink) {
      ++r.shrinks;
      for (std::size_t j = 1; j <= n; ++j) {
        for (std::size_t i = 0; i < n; ++i)
          sim[j][i] = sim[0][i] + o.sigma * (sim[j][i] - sim[0][i]);
        fs[j] = eval(sim[j]);
      }
    }
    sort();
    ++r.iterations;
  }
  r.x = sim[0];
  r.f = fs[0];
  return r;
}

}  // namespace comminute::calibrate
