#include "comminute/contact/tangential_friction.hpp"

#include <cmath>

namespace comminute {

void coulomb_tangential(const ContactKinematics& k, double kt, double ct, double limit,
                        ContactHistory& h, ContactForces& out) {
  Vec3 xi = h.tangential_spring;
  // rotate into the current tangent plane, preserving the magnitude
  const double len2 = norm2(xi);
  if (len2 > 0.0) {
    xi -= dot(xi, k.normal) * k.normal;
    const double l2 = norm2(xi);
    if (l2 > 0.0) xi *= std::sqrt(len2 / l2);
  }
  xi += k.tangential_velocity * k.dt;
  Vec3 ft = -kt * xi - ct * k.tangential_velocity;
  const double ft2 = norm2(ft);
  if (ft2 > limit * limit) {
    // sliding: the spring is cut back so that |k_t xi| = mu |F_n|; the energy it loses is friction
    const double spring = kt * std::sqrt(norm2(xi));
    const double before = 0.5 * kt * norm2(xi);
    if (spring > 0.0) {
      xi *= limit / spring;
      ft = -kt * xi;
    } else {
      ft = {};
      xi = {};
    }
    out.friction_dissipation += before - 0.5 * kt * norm2(xi);
  } else {
    out.damping_dissipation += ct * norm2(k.tangential_velocity) * k.dt;
  }
  h.tangential_spring = xi;
  out.tangential_force = ft;
  out.stored_energy += 0.5 * kt * norm2(xi);
}

}  // namespace comminute
