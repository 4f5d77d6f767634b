#pragma once
// Contacts evaluated at rest, for breakage's energy bookkeeping (fragment growth, replacement).
#include <cstdint>

#include "comminute/contact/contact_law.hpp"
#include "comminute/contact/contact_state.hpp"
#include "comminute/core/vec3.hpp"

namespace comminute {
class Simulation;
}

namespace comminute::breakage {

// The contact model evaluated at rest between sphere i (radius, mass, material) and a sphere
// (r_j > 0) or a wall (r_j = 0) at `overlap` along `normal`, on a copy of the contact's state (or
// a fresh one): nothing slips or advances. Gives the forces and energies a contact holds in that
// state.
ContactForces contact_at_rest(const Simulation& sim, double overlap, double r_i, double m_i,
                              std::uint16_t a, double r_j, double m_j, std::uint16_t b,
                              const Vec3& normal, const ContactScratch& state);

// Normal elastic energy (J) of a contact with overlap `overlap` (0 when not touching) between
// sphere i (radius, material) and a sphere (r_j > 0) or a wall (r_j = 0): contact_at_rest()'s
// normal_elastic_energy, taken from the law alone.
double overlap_energy(const Simulation& sim, double overlap, double r_i, std::uint16_t a,
                      double r_j, std::uint16_t b);

}  // namespace comminute::breakage
