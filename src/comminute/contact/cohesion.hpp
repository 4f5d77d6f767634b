#pragma once
// Adhesion models ([contact] cohesion = "none" | "sjkr"), built from the [contact] table.
#include <string>

#include "comminute/contact/contact_law.hpp"

namespace comminute {

class Cohesion {
 public:
  virtual ~Cohesion() = default;
  virtual std::string name() const = 0;
  // Adds the (attractive, negative) adhesive normal force for a touching contact.
  virtual void compute(const ContactKinematics& k, const PairParameters& p,
                       ContactForces& out) const = 0;
};

using CohesionRegistry = Registry<Cohesion, const CaseTable&>;

}  // namespace comminute
