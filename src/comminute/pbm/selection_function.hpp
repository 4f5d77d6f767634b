#pragma once
// Breakage rates (selection functions) S (1/s): the fraction of the particles of a size that
// break per unit time. Called with both the particle size d (m) and volume v (m³) so that each
// model states which one its formula uses.
#include "comminute/pbm/model_context.hpp"

namespace comminute::pbm {

class SelectionFunction {
 public:
  virtual ~SelectionFunction() = default;
  virtual double rate(double size, double volume) const = 0;
};

// [rate] model = "<name>": each rate model's file registers its factory, which reads the model's
// own keys from the table.
using SelectionFunctionRegistry =
    Registry<SelectionFunction, const CaseTable&, const ModelContext&>;

}  // namespace comminute::pbm
