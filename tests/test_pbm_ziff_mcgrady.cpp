// Method of classes against the analytic solutions of the continuous linear breakage equation
// (Ziff & McGrady, J. Phys. A 18 (1985) 3027): binary breakage with uniform daughters
// p(x, y) = 2/y (product function q = 1, ν = 2), rates S = x and S = x² (x = particle volume),
// monodisperse and exponential initial distributions. See MODELS-pbm-notes.md §1.1.
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/erf.hpp>
#include <cmath>
#include <functional>
#include <iostream>

#include "comminute/pbm/integrator.hpp"
#include "comminute/pbm/method_of_classes.hpp"
#include "comminute/pbm/power_law_rate.hpp"
#include "comminute/pbm/product_function.hpp"
#include "comminute/pbm/solve.hpp"

using namespace comminute::pbm;

namespace {

const double pi = 3.14159265358979323846;

double cell_integral(const std::function<double(double)>& f, double a, double b) {
  return boost::math::quadrature::gauss_kronrod<double, 31>::integrate(f, a, b, 10, 1e-13);
}

struct Case {
  double power;                             // S = x^power
  bool mono;                                // δ(x − 1) or e^{−x}
  std::function<double(double, double)> f;  // continuous part f(x, t)
  std::function<double(double)> m0;         // zeroth moment M0(t)
};

// Notes §1.1, table rows A1–A4 (l = 1).
Case a1() {
  return {1, true, [](double x, double t) { return std::exp(-x * t) * (2 * t + t * t * (1 - x)); },
          [](double t) { return 1 + t; }};
}
Case a2() {
  return {1, false, [](double x, double t) { return (1 + t) * (1 + t) * std::exp(-x * (1 + t)); },
          [](double t) { return 1 + t; }};
}
Case a3() {
  return {
      2, true, [](double x, double t) { return 2 * t * std::exp(-x * x * t); },
      [](double t) { return std::exp(-t) + std::sqrt(pi * t) * boost::math::erf(std::sqrt(t)); }};
}
Case a4() {
  return {2, false,
          [](double x, double t) { return (1 + 2 * t * (1 + x)) * std::exp(-x - t * x * x); },
          [](double t) {
            const double i0 = 0.5 * std::sqrt(pi / t) * std::exp(1 / (4 * t)) *
                              boost::math::erfc(1 / (2 * std::sqrt(t)));
            return 1 + 2 * t * i0;
          }};
}

// Monodisperse: uniform grid in volume whose top pivot sits at x = 1 (cells of width h = 1/n
// centred on j·h, first cell [0, h/2]). Exponential: [0, 1e−6] then n − 1 cells equally spaced
// in ln x up to 30 (e^{−30} of the mass lies beyond; ~1e−6 of the number below 1e−6); a uniform
// grid would make the never-breaking first cell far too wide for a distribution this skewed.
SizeGrid grid_for(const Case& c, std::size_t n) {
  std::vector<double> e{0.0};
  if (c.mono) {
    const double h = 1.0 / static_cast<double>(n);
    for (std::size_t j = 0; j <= n; ++j) e.push_back((static_cast<double>(j) + 0.5) * h);
  } else {
    const double step = std::log(30.0 / 1e-6) / static_cast<double>(n - 1);
    for (std::size_t j = 0; j < n; ++j) e.push_back(1e-6 * std::exp(step * static_cast<double>(j)));
  }
  return SizeGrid(e, GridCoordinate::volume, 1.0);
}

struct Errors {
  double density;  // Σ|N_i − ∫_cell f| / Σ∫_cell f over the continuous part
  double m0;       // |ΣN − M0| / M0
  double mass;     // |Σ x_i N_i − M1(0)| / M1(0)
};

Errors run(const Case& c, std::size_t n, double t, bool correction = true) {
  const SizeGrid g = grid_for(c, n);
  const PowerLawRate rate({1.0, c.power, GridCoordinate::volume, 1.0, std::nullopt, 2.0});
  const ProductFunction uniform_binary(1.0, 2.0);
  const MethodOfClasses moc(g, rate, uniform_binary, correction);
  const std::size_t m = g.classes();
  Eigen::VectorXd n0 = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m));
  for (std::size_t i = 0; i < m; ++i) {
    if (c.mono)
      n0[static_cast<Eigen::Index>(i)] = i + 1 == m ? 1.0 : 0.0;
    else
      n0[static_cast<Eigen::Index>(i)] =
          std::exp(-g.volume_edge(i)) - std::exp(-g.volume_edge(i + 1));
  }
  DormandPrince dp({1e-11, 1e-14, 1000000});
  const auto sol = solve(moc.system(), dp, n0, {t});
  const Eigen::VectorXd& nt = sol.back();
  double err = 0, ref = 0, m1_0 = 0, m1_t = 0;
  // Monodisperse: the top class also holds the surviving δ, so the density is compared below it.
  const std::size_t top = c.mono ? m - 1 : m;
  for (std::size_t i = 0; i < m; ++i) {
    m1_0 += g.pivot_volume(i) * n0[static_cast<Eigen::Index>(i)];
    m1_t += g.pivot_volume(i) * nt[static_cast<Eigen::Index>(i)];
    if (i >= top) continue;
    const double exact =
        cell_integral([&](double x) { return c.f(x, t); }, g.volume_edge(i), g.volume_edge(i + 1));
    err += std::abs(nt[static_cast<Eigen::Index>(i)] - exact);
    ref += exact;
  }
  return {err / ref, std::abs(nt.sum() - c.m0(t)) / c.m0(t), std::abs(m1_t - m1_0) / m1_0};
}

void expect_convergence(const Case& c, const char* name, double t) {
  // Expected order: 2 for the weighted scheme with pure breakage (Kumar, Kumar & Warnecke 2014;
  // notes §2.3). Observed on these grids: 1.85–2.1 for every case and refinement. We require an
  // observed order above 1.8 at each doubling from n = 40 (a first-order error in B_{i,k} or the
  // weights gives ≈ 1) and, at n = 160, errors below 5e−3 (all observed ≤ 3.1e−3).
  std::vector<Errors> e;
  const std::vector<std::size_t> ns{20, 40, 80, 160};
  for (std::size_t n : ns) e.push_back(run(c, n, t));
  for (std::size_t k = 0; k < ns.size(); ++k) {
    std::cout << name << " n=" << ns[k] << " density L1 rel err " << e[k].density << "  M0 rel err "
              << e[k].m0 << "  mass drift " << e[k].mass;
    if (k > 0)
      std::cout << "  order(density) " << std::log2(e[k - 1].density / e[k].density)
                << "  order(M0) " << std::log2(e[k - 1].m0 / e[k].m0);
    std::cout << "\n";
  }
  for (std::size_t k = 1; k < ns.size(); ++k) {
    EXPECT_LT(e[k].density, e[k - 1].density) << name << " n=" << ns[k];
    EXPECT_LT(e[k].m0, e[k - 1].m0) << name << " n=" << ns[k];
  }
  for (std::size_t k = 2; k < ns.size(); ++k) {
    EXPECT_GT(std::log2(e[k - 1].density / e[k].density), 1.8) << name << " n=" << ns[k];
    EXPECT_GT(std::log2(e[k - 1].m0 / e[k].m0), 1.8) << name << " n=" << ns[k];
  }
  EXPECT_LT(e.back().density, 5e-3) << name;
  EXPECT_LT(e.back().m0, 5e-3) << name;
  // Mass: the weights make Σ x_i N_i an exact invariant of the semi-discrete system and every
  // Runge–Kutta stage keeps linear invariants, so only round-off remains (~1e−15 per step).
  for (const auto& x : e) EXPECT_LT(x.mass, 1e-12) << name;
}

}  // namespace

TEST(ZiffMcGrady, RateVolumeMonodisperse) {
  expect_convergence(a1(), "A1 S=x mono", 2.0);
}
TEST(ZiffMcGrady, RateVolumeExponential) {
  expect_convergence(a2(), "A2 S=x exp", 2.0);
}
TEST(ZiffMcGrady, RateVolumeSquaredMonodisperse) {
  expect_convergence(a3(), "A3 S=x^2 mono", 2.0);
}
TEST(ZiffMcGrady, RateVolumeSquaredExponential) {
  expect_convergence(a4(), "A4 S=x^2 exp", 2.0);
}

TEST(ZiffMcGrady, MassIsLostWithoutTheKumarCorrection) {
  // Same problem, ω = 1: fragments are counted exactly but placed at pivots, so mass drifts at
  // the grid's resolution. "Visibly": above 1e−3 on the coarse grid, while the corrected scheme
  // stays below 1e−12 (asserted above).
  const Errors with = run(a2(), 20, 2.0, true), without = run(a2(), 20, 2.0, false);
  std::cout << "mass drift with correction " << with.mass << ", without " << without.mass << "\n";
  EXPECT_LT(with.mass, 1e-12);
  EXPECT_GT(without.mass, 1e-3);
}
