#pragma once
// Breakage rates (selection functions) S (1/s): the fraction of the particles of a size that
// break per unit time. Called with both the particle size d (m) and volume v (m³) so that each
// model states which one its formula uses.
namespace comminute::pbm {

class SelectionFunction {
 public:
  virtual ~SelectionFunction() = default;
  virtual double rate(double size, double volume) const = 0;
};

}  // namespace comminute::pbm
