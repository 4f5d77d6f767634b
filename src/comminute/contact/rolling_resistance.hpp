#pragma once
// Rolling resistance models ([contact] rolling = "none" | "constant_torque" | "epsd").
#include <string>

#include "comminute/contact/contact_law.hpp"

namespace comminute {

class RollingResistance {
 public:
  virtual ~RollingResistance() = default;
  virtual std::string name() const = 0;
  // Adds the rolling torque on i (and its dissipation) given the normal force already computed.
  virtual void compute(const ContactKinematics& k, const PairParameters& p, ContactHistory& h,
                       ContactForces& out) const = 0;
};

using RollingResistanceRegistry = Registry<RollingResistance>;

}  // namespace comminute
