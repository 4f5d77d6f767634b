#include "comminute/breakage/contact_at_rest.hpp"

#include "comminute/engine/simulation.hpp"

namespace comminute::breakage {

namespace {
// R* (m) or m* (kg) of sphere i with a sphere (b > 0) or a wall (b = 0): a b / (a + b), or a
double effective(double a, double b) {
  return b > 0 ? a * b / (a + b) : a;
}
}  // namespace

ContactForces contact_at_rest(const Simulation& sim, double overlap, double r_i, double m_i,
                              std::uint16_t a, double r_j, double m_j, std::uint16_t b,
                              const Vec3& normal, const ContactScratch& state) {
  ContactKinematics ck;
  ck.normal = normal;
  ck.overlap = overlap;
  ck.effective_radius = effective(r_i, r_j);
  ck.effective_mass = effective(m_i, m_j);
  ck.dt = 0;
  ContactForces out;
  sim.contacts().evaluate(ck, sim.materials.pair(a, b), state.ref(), out);
  return out;
}

double overlap_energy(const Simulation& sim, double overlap, double r_i, std::uint16_t a,
                      double r_j, std::uint16_t b) {
  if (overlap <= 0) return 0.0;
  return sim.contacts().normal_elastic_energy(sim.materials.pair(a, b), effective(r_i, r_j),
                                              overlap);
}

}  // namespace comminute::breakage
