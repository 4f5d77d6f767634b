#pragma once
// Coulomb friction with a tangential spring whose history is carried in the contact: the stored
// displacement is rotated into the current tangent plane (keeping its length), incremented by
// v_t dt, and truncated to the Coulomb limit when the contact slides (dashpot off while sliding).
#include "comminute/contact/contact_law.hpp"

namespace comminute {

// kt: tangential stiffness (N/m), ct: tangential damping (N s/m), limit: mu |F_n| (N).
// Sets out.tangential_force, adds to out.stored_energy, out.damping_dissipation,
// out.friction_dissipation.
void coulomb_tangential(const ContactKinematics& k, double kt, double ct, double limit,
                        ContactHistory& h, ContactForces& out);

}  // namespace comminute
