#include "comminute/bonds/bond_failure.hpp"

namespace comminute::bonds {

const char* cause_name(FailureCause c) {
  switch (c) {
    case FailureCause::tensile:
      return "tensile";
    case FailureCause::shear:
      return "shear";
    case FailureCause::particle_removed:
      return "particle_removed";
  }
  return "unknown";
}

}  // namespace comminute::bonds
