#include "comminute/breakage/progeny/progeny_sizes.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "comminute/core/error.hpp"
#include "comminute/core/units.hpp"

namespace comminute::breakage {

double sphere_diameter(double m, double rho) {
  return std::cbrt(6.0 * m / (units::pi * rho));
}

namespace {

// Sizes (m) of the class boundaries, descending from d to min_size.
std::vector<double> class_boundaries(double d, double min_size) {
  std::vector<double> b;
  for (double n : {1.0, 2.0, 4.0, 10.0, 25.0, 50.0, 75.0})
    if (d / n > min_size) b.push_back(d / n);
  for (double x = b.back() / std::sqrt(2.0); x > min_size; x /= std::sqrt(2.0)) b.push_back(x);
  b.push_back(min_size);
  return b;
}

// Draws sizes in [lo, hi] from the number distribution of the class: 16 log-spaced sub-intervals
// weighted by their mass share / size^3, log-uniform inside a sub-interval.
class ClassSampler {
 public:
  ClassSampler(const ProgenyDistribution& dist, double lo, double hi) : lo_(lo), hi_(hi) {
    double cum = 0;
    for (int k = 0; k < parts; ++k) {
      const double a = edge(k), b = edge(k + 1), mid = std::sqrt(a * b);
      cum += std::max(0.0, dist.passing(b) - dist.passing(a)) / (mid * mid * mid);
      cum_[k] = cum;
    }
  }
  double draw(Rng& rng) const {
    const double target = rng.uniform() * cum_[parts - 1];
    int k = 0;
    while (k < parts - 1 && cum_[k] < target) ++k;
    return edge(k) * std::pow(edge(k + 1) / edge(k), rng.uniform());
  }

 private:
  static constexpr int parts = 16;
  double edge(int k) const { return lo_ * std::pow(hi_ / lo_, static_cast<double>(k) / parts); }
  double lo_, hi_;
  double cum_[parts] = {};
};

}  // namespace

Progeny draw_progeny(const ProgenyDistribution& dist, double mass, double density, double min_size,
                     FinesRule rule, Rng& rng) {
  const double d = dist.diameter();
  auto mass_of = [&](double x) { return density * units::pi / 6.0 * x * x * x; };
  // A state no run produces (a corrupt checkpoint: a radius of 1e180 m) would make fragments of
  // zero mass and never finish: refused.
  if (!(mass > 0) || !(mass_of(d) > 0) || !std::isfinite(mass_of(d)))
    throw Error(
        fmt::format("breakage: cannot split a particle of diameter {} m, mass {} kg and "
                    "minimum fragment size {} m",
                    d, mass, min_size));
  std::vector<double> pieces;  // kg, resolved fragments
  double carry = 0;            // kg passed on to the next finer class
  double used = 0;             // kg in `pieces`
  if (min_size < d) {
    const std::vector<double> b = class_boundaries(d, min_size);
    for (std::size_t c = 0; c + 1 < b.size(); ++c) {
      const double hi = b[c], lo = b[c + 1];
      double rest = mass * (dist.passing(hi) - dist.passing(lo)) / 100.0 + carry;
      // A distribution outside [0, 100] % or not monotone (a corrupt state: t10 from a NaN or
      // absurd energy) could ask for more mass than the parent has, and as many fragments: no
      // class takes more than what is left (a valid distribution never comes near this bound).
      if (rest > 1.000001 * (mass - used)) rest = mass - used;
      carry = 0;
      const double m_lo = mass_of(lo), m_hi = mass_of(hi);
      if (rest < m_lo) {
        carry = rest;
        continue;
      }
      const ClassSampler sampler(dist, lo, hi);
      while (rest > 0) {
        if (rest <= m_hi) {
          pieces.push_back(rest);
          used += rest;
          break;
        }
        const double m = mass_of(sampler.draw(rng));
        if (rest - m >= m_lo) {
          pieces.push_back(m);
          used += m;
          rest -= m;
        } else {  // rest in (m_hi, m + m_lo): closes the class as equal halves, or as one
          // fragment when halves would fall below the class (a class narrower than 2^(1/3) in
          // size: the last one ends at the minimum fragment size, which no fragment may undercut)
          if (rest / 2 >= m_lo) {
            pieces.push_back(rest / 2);
            pieces.push_back(rest / 2);
          } else {
            pieces.push_back(rest);  // at most 2 m_lo: size below 2^(1/3) lo
          }
          used += rest;
          break;
        }
      }
    }
  }
  // Everything not in a resolved fragment is fines.
  double resolved = 0;
  for (double m : pieces) resolved += m;
  double fines = std::max(0.0, mass - resolved);

  Progeny out;
  std::sort(pieces.begin(), pieces.end(), std::greater<>());
  for (double m : pieces) out.fragments.push_back({m, sphere_diameter(m, density), false});
  if (rule == FinesRule::mass) {
    out.fines_mass = fines;
  } else if (fines > 0) {
    const double m_min = mass_of(std::min(min_size, d));
    const double count = std::floor(fines / m_min);
    if (count >= 1) {
      const double m = fines / count;
      for (double k = 0; k < count; ++k)
        out.fragments.push_back({m, sphere_diameter(m, density), true});
    } else if (!out.fragments.empty()) {
      out.fragments.back().mass += fines;  // too little for one fines particle: merge
    } else {
      out.fragments.push_back({fines, sphere_diameter(fines, density), true});
    }
  }
  // Close the mass exactly: the last particle takes what the others leave.
  if (!out.fragments.empty()) {
    double others = out.fines_mass;
    for (std::size_t k = 0; k + 1 < out.fragments.size(); ++k) others += out.fragments[k].mass;
    Fragment& last = out.fragments.back();
    last.mass = mass - others;
    last.diameter = sphere_diameter(last.mass, density);
  } else {
    out.fines_mass = mass;
  }
  return out;
}

}  // namespace comminute::breakage
