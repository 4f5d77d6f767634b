#pragma once
// Size classes of a population balance. The balance is written in particle volume v (m³), the
// variable of the breakage equation; d = (v/k_v)^(1/3) is the equivalent particle size (m) with
// volume shape factor k_v (π/6 for spheres). A grid is built in one coordinate — size or volume —
// and both are always available, so no rate or output is ever ambiguous about its variable.
#include <cstddef>
#include <vector>

namespace comminute::pbm {

enum class GridCoordinate { size, volume };

class SizeGrid {
 public:
  // Class edges in `coordinate` (m or m³), strictly increasing, at least two, the first >= 0.
  // Throws comminute::Error otherwise (case builders check first and name the key).
  SizeGrid(std::vector<double> edges, GridCoordinate coordinate, double shape_factor);

  // `classes` classes with edges equally spaced in ln(coordinate) between lo and hi.
  static SizeGrid logarithmic(double lo, double hi, std::size_t classes, GridCoordinate coordinate,
                              double shape_factor);
  // Sieve series: top edge `top`, each lower edge the previous one divided by `ratio` (√2 for the
  // classical series in size).
  static SizeGrid geometric(double top, double ratio, std::size_t classes,
                            GridCoordinate coordinate, double shape_factor);

  std::size_t classes() const { return pivot_volume_.size(); }
  double shape_factor() const { return shape_factor_; }
  // Edge i (0 … classes) and pivot i (0 … classes−1); classes are ordered fine to coarse.
  double volume_edge(std::size_t i) const { return volume_edges_[i]; }
  double size_edge(std::size_t i) const { return size_of_volume(volume_edges_[i]); }
  // Pivot = arithmetic mean volume of the class (as in Dyssol's Crusher PBM TM).
  double pivot_volume(std::size_t i) const { return pivot_volume_[i]; }
  double pivot_size(std::size_t i) const { return size_of_volume(pivot_volume_[i]); }
  double volume_width(std::size_t i) const { return volume_edges_[i + 1] - volume_edges_[i]; }

  // Edges in constant ratio in volume (logarithmic and geometric grids, in size or volume).
  bool geometric_in_volume() const { return geometric_; }

  double volume_of_size(double d) const { return shape_factor_ * d * d * d; }
  double size_of_volume(double v) const;

 private:
  double shape_factor_;
  std::vector<double> volume_edges_, pivot_volume_;
  bool geometric_ = false;
};

}  // namespace comminute::pbm
