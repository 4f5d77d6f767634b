#include "comminute/engine/time_step_control.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "comminute/fracture/rayleigh_time.hpp"

namespace comminute {

double TimeStepControl::decide(const ParticleStore& p, const MaterialTable& materials) const {
  r_min_.assign(materials.size(), std::numeric_limits<double>::infinity());
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i) {
    double r = p.radius[i];
    if (p.flags[i] & pflag::growing) {  // at full size: R = (3 m / (4 pi rho))^(1/3)
      const double rho = materials.material(p.material[i]).density;
      r = std::max(r, std::cbrt(3 * p.physical_mass(i) / (4 * std::numbers::pi * rho)));
    }
    // t_R is proportional to R sqrt(rho): a particle of mass scale s steps like one of radius
    // R sqrt(s) (density scaling, docs/models.md "Time step")
    r *= std::sqrt(p.mass_scale(i));
    double& m = r_min_[p.material[i]];
    m = std::min(m, r);
  }
  double dt = ceiling_;
  for (std::size_t k = 0; k < r_min_.size(); ++k) {
    if (!std::isfinite(r_min_[k])) continue;
    const Material& m = materials.material(static_cast<std::uint16_t>(k));
    dt = std::min(dt, fraction_ * fracture::rayleigh_time(2 * r_min_[k], m.density,
                                                          m.shear_modulus(), m.poisson_ratio));
  }
  return dt;
}

}  // namespace comminute
