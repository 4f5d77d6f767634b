#include "comminute/particles/material.hpp"

#include <cmath>

#include "comminute/particles/restitution.hpp"

namespace comminute {

std::uint16_t MaterialTable::add(const Material& m) {
  const std::size_t n = materials_.size();
  std::vector<PairInput> old = inputs_;
  materials_.push_back(m);
  inputs_.assign((n + 1) * (n + 1), PairInput{});
  pairs_.assign((n + 1) * (n + 1), PairParameters{});
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b) inputs_[a * (n + 1) + b] = old[a * n + b];
  for (std::size_t a = 0; a <= n; ++a)
    for (std::size_t b = 0; b <= n; ++b)
      rebuild_pair(static_cast<std::uint16_t>(a), static_cast<std::uint16_t>(b),
                   inputs_[a * (n + 1) + b]);
  return static_cast<std::uint16_t>(n);
}

void MaterialTable::set_pair(std::uint16_t a, std::uint16_t b, const PairInput& p) {
  rebuild_pair(a, b, p);
  rebuild_pair(b, a, p);
}

void MaterialTable::rebuild_pair(std::uint16_t a, std::uint16_t b, const PairInput& p) {
  const std::size_t n = materials_.size();
  inputs_[a * n + b] = p;
  const Material& m1 = materials_[a];
  const Material& m2 = materials_[b];
  PairParameters q;
  static_cast<PairInput&>(q) = p;
  const double v1 = m1.poisson_ratio, v2 = m2.poisson_ratio;
  // 1/E* = (1-ν1²)/E1 + (1-ν2²)/E2, 1/G* = 2(2-ν1)(1+ν1)/E1 + 2(2-ν2)(1+ν2)/E2 (Johnson, Contact
  // Mechanics, Cambridge UP 1985, ch. 4 and 7; the LIGGGHTS/EDEM convention for G*)
  q.effective_modulus =
      1.0 / ((1 - v1 * v1) / m1.youngs_modulus + (1 - v2 * v2) / m2.youngs_modulus);
  q.effective_shear_modulus = 1.0 / (2 * (2 - v1) * (1 + v1) / m1.youngs_modulus +
                                     2 * (2 - v2) * (1 + v2) / m2.youngs_modulus);
  q.damping_beta = damping_beta(p.restitution);
  q.shear_normal_root = std::sqrt(4.0 * q.effective_shear_modulus / q.effective_modulus);
  if (q.dynamic_friction < 0) q.dynamic_friction = q.friction;
  pairs_[a * n + b] = q;
}

bool MaterialTable::has_dynamic_friction() const {
  for (const auto& q : pairs_)
    if (q.dynamic_friction != q.friction) return true;
  return false;
}

int MaterialTable::find(const std::string& name) const {
  for (std::size_t k = 0; k < materials_.size(); ++k)
    if (materials_[k].name == name) return static_cast<int>(k);
  return -1;
}

}  // namespace comminute
