#pragma once
// A user's breakage function: cumulative mass passing against size ratio d/D, the same for
// every parent (normalised).
#include "comminute/pbm/breakage_function.hpp"
#include "comminute/pbm/cumulative_table.hpp"

namespace comminute::pbm {

class TabulatedBreakageFunction : public BreakageFunction {
 public:
  explicit TabulatedBreakageFunction(CumulativeTable table) : table_(std::move(table)) {}
  double cumulative_mass(double v, double y) const override;
  bool homogeneous() const override { return true; }

 private:
  CumulativeTable table_;
};

}  // namespace comminute::pbm
