#pragma once
// Breakage (daughter-distribution) functions: how the fragments of one breakage event of a parent
// of volume y are distributed over fragment volume v. Every function gives Austin's cumulative
// mass form B(v, y); functions defined by number (Diemer–Olson) also give the cumulative number
// of fragments, which the method of classes integrates exactly over each class.
#include <optional>
#include <string>

#include "comminute/pbm/model_context.hpp"

namespace comminute::pbm {

class BreakageFunction {
 public:
  virtual ~BreakageFunction() = default;
  // Fraction of the parent's mass in fragments of volume below v (0 ≤ v ≤ y; B(y, y) = 1).
  virtual double cumulative_mass(double v, double y) const = 0;
  // Number of fragments of volume below v; empty for functions defined by mass only.
  virtual std::optional<double> cumulative_number(double /*v*/, double /*y*/) const {
    return std::nullopt;
  }
  // True when B depends on v/y only (a "normalised" function): then on a grid geometric in
  // volume the method of classes evaluates it n times instead of n²/2.
  virtual bool homogeneous() const { return false; }
  // One line for run reports (the product function reports its z50 here); empty by default.
  virtual std::string summary() const { return {}; }
  // The function that breaks a parent of volume y (itself, except for population splits).
  virtual const BreakageFunction& of_parent(double /*y*/) const { return *this; }
};

// [breakage] function = "<name>": each function's file registers its factory, which reads the
// function's own keys from the table.
using BreakageFunctionRegistry = Registry<BreakageFunction, const CaseTable&, const ModelContext&>;

}  // namespace comminute::pbm
