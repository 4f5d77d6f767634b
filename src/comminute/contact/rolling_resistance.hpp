#pragma once
// Rolling resistance models ([contact] rolling = "none" | "constant_torque" | "epsd"), built from
// the [contact] table (a model reads its own keys).
#include <string>

#include "comminute/contact/contact_law.hpp"

namespace comminute {

class RollingResistance {
 public:
  virtual ~RollingResistance() = default;
  virtual std::string name() const = 0;
  // Declares the model's per-contact slots (none by default).
  virtual void declare(ContactStateStore&) {}
  // Adds the rolling torque on i (and its dissipation) given the normal force already computed.
  virtual void compute(const ContactKinematics& k, const PairParameters& p, const StateRef& s,
                       ContactForces& out) const = 0;
};

using RollingResistanceRegistry = Registry<RollingResistance, const CaseTable&>;

}  // namespace comminute
