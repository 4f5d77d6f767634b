// BondsModule: making one bond (for the sweep at create_at and for the pairs a pour lists).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "comminute/bonds/bonds_module.hpp"
#include "comminute/core/error.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::bonds {

void BondsModule::make_bond(Simulation& sim, std::uint32_t i, std::uint32_t j) {
  const ParticleStore& p = sim.particles;
  if (p.id[j] < p.id[i]) std::swap(i, j);
  const Vec3 d = p.x[j] - p.x[i];
  const double length = norm(d);
  if (!(length > 0)) return;  // coincident centres: no direction to bond along
  const BondState s = law_->create(p.radius[i], p.radius[j], length, d / length, rng_);
  // velocity Verlet is stable for ω dt < 2; ω² ≤ 4 k / m covers the axial, shear, bending and
  // twist modes of two solid spheres joined by the bond
  const double m = std::min(p.mass[i], p.mass[j]);
  const double limit = std::sqrt(m / (4 * law_->stiffness(s)));
  if (sim.dt > limit)
    throw SimulationError(fmt::format(
        "the bond between particles {} and {} needs a time step of at most {:.4g} s (it is "
        "{:.4g} s): set [simulation] time_step",
        p.id[i], p.id[j], limit, sim.dt));
  bonds_.add(p.id[i], i, p.id[j], j, s);
  indexed_ = false;  // the per-particle index lacks the new bond
}

void BondsModule::bond_pairs(Simulation& sim,
                             const std::vector<std::array<std::uint32_t, 2>>& slots) {
  const std::size_t n = sim.particles.owned();
  for (const auto& [i, j] : slots) {
    if (i >= n || j >= n || i == j)
      throw Error(
          fmt::format("bond_pairs: slots {} and {} are not two owned particles of {}", i, j, n));
    make_bond(sim, i, j);
  }
}

}  // namespace comminute::bonds
