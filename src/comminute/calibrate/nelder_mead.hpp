#pragma once
// Nelder–Mead simplex minimiser (Nelder & Mead, Computer J. 7 (1965) 308), in the form of
// Lagarias et al. (SIAM J. Optim. 9 (1998) 112) as implemented by MATLAB's fminsearch and SciPy:
// reflection ρ, expansion χ, contraction ψ (outside when f_n ≤ f_r < f_{n+1}, inside when
// f_r ≥ f_{n+1}), shrink σ; vertices kept stably sorted; stop when max|f_1 − f_j| ≤ f_tol and
// max_j ‖x_j − x_1‖∞ ≤ x_tol (checked before each iteration), or at the evaluation limit.
#include <cstddef>
#include <functional>
#include <vector>

namespace comminute::calibrate {

using Point = std::vector<double>;
using Objective = std::function<double(const Point&)>;

struct NelderMeadOptions {
  double rho = 1.0, chi = 2.0, psi = 0.5, sigma = 0.5;
  double x_tolerance = 1e-4;
  double f_tolerance = 1e-4;          // absolute
  double f_relative_tolerance = 0.0;  // added: f_tol + f_rel·|f_1|
  std::size_t max_evaluations = 0;    // 0 = 200 × dimension (SciPy's default)
  std::size_t max_iterations = 0;     // 0 = 200 × dimension
  // Gao & Han (2012) dimension-adapted coefficients (SciPy `adaptive=True`).
  static NelderMeadOptions adaptive(std::size_t dimension);
};

struct NelderMeadResult {
  Point x;
  double f = 0;
  std::size_t iterations = 0;  // counting the initial simplex as 1 (fminsearch, SciPy)
  std::size_t evaluations = 0;
  std::size_t reflections = 0, expansions = 0, outside_contractions = 0, inside_contractions = 0,
              shrinks = 0;
  bool converged = false;  // tolerances met (not stopped by a limit)
};

// fminsearch's start: x0 and, for each j, x0 with component j × 1.05 (0.00025 where it is 0).
std::vector<Point> fminsearch_simplex(const Point& x0);
// x0 and x0 + step·e_j, stepping −step instead where x0_j + step would leave [0, 1].
std::vector<Point> unit_box_simplex(const Point& x0, double step);

NelderMeadResult nelder_mead(const Objective& f, std::vector<Point> simplex,
                             const NelderMeadOptions& options = {});

}  // namespace comminute::calibrate
