#include "comminute/breakage/contact_at_rest.hpp"

#include "comminute/engine/simulation.hpp"

namespace comminute::breakage {

ContactForces contact_at_rest(const Simulation& sim, double overlap, double r_i, double m_i,
                              std::uint16_t a, double r_j, double m_j, std::uint16_t b,
                              const Vec3& normal, const ContactScratch& state) {
  ContactKinematics ck;
  ck.normal = normal;
  ck.overlap = overlap;
  ck.effective_radius = r_j > 0 ? r_i * r_j / (r_i + r_j) : r_i;
  ck.effective_mass = m_j > 0 ? m_i * m_j / (m_i + m_j) : m_i;
  ck.dt = 0;
  ContactForces out;
  sim.contacts().evaluate(ck, sim.materials.pair(a, b), state.ref(), out);
  return out;
}

double overlap_energy(const Simulation& sim, double overlap, double r_i, std::uint16_t a,
                      double r_j, std::uint16_t b) {
  if (overlap <= 0) return 0.0;
  const double effective_radius = r_j > 0 ? r_i * r_j / (r_i + r_j) : r_i;  // contact_at_rest()'s
  return sim.contacts().normal_elastic_energy(sim.materials.pair(a, b), effective_radius, overlap);
}

}  // namespace comminute::breakage
