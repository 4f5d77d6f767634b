#include "comminute/pbm/size_grid.hpp"

#include <fmt/format.h>

#include <cmath>

#include "comminute/core/error.hpp"

namespace comminute::pbm {

SizeGrid::SizeGrid(std::vector<double> edges, GridCoordinate coordinate, double shape_factor)
    : shape_factor_(shape_factor) {
  if (!(shape_factor > 0)) throw Error("SizeGrid: shape factor must be positive");
  if (edges.size() < 2) throw Error("SizeGrid: at least two edges are needed");
  if (!(edges.front() >= 0)) throw Error("SizeGrid: edges must not be negative");
  for (std::size_t i = 1; i < edges.size(); ++i)
    if (!(edges[i] > edges[i - 1]))
      throw Error(fmt::format("SizeGrid: edge {} ({}) is not above edge {} ({})", i, edges[i],
                              i - 1, edges[i - 1]));
  volume_edges_ = std::move(edges);
  if (coordinate == GridCoordinate::size)
    for (double& e : volume_edges_) e = volume_of_size(e);
  for (std::size_t i = 0; i + 1 < volume_edges_.size(); ++i)
    pivot_volume_.push_back(0.5 * (volume_edges_[i] + volume_edges_[i + 1]));
  // 1e−12: exp/pow round-off of generated edges is ~1e−15; user sieve series typed with 4–6
  // digits are treated as general grids.
  geometric_ = volume_edges_.front() > 0;
  const double r = volume_edges_[1] / volume_edges_[0];
  for (std::size_t i = 1; geometric_ && i + 1 < volume_edges_.size(); ++i)
    geometric_ = std::abs(volume_edges_[i + 1] / volume_edges_[i] / r - 1) < 1e-12;
}

SizeGrid SizeGrid::logarithmic(double lo, double hi, std::size_t classes, GridCoordinate coordinate,
                               double shape_factor) {
  if (!(lo > 0 && hi > lo && classes > 0)) throw Error("SizeGrid: need 0 < lo < hi, classes > 0");
  std::vector<double> e(classes + 1);
  const double step = std::log(hi / lo) / static_cast<double>(classes);
  for (std::size_t i = 0; i <= classes; ++i) e[i] = lo * std::exp(step * static_cast<double>(i));
  e.back() = hi;
  return SizeGrid(std::move(e), coordinate, shape_factor);
}

SizeGrid SizeGrid::geometric(double top, double ratio, std::size_t classes,
                             GridCoordinate coordinate, double shape_factor) {
  if (!(top > 0 && ratio > 1 && classes > 0)) throw Error("SizeGrid: need top > 0, ratio > 1");
  std::vector<double> e(classes + 1);
  e[classes] = top;
  for (std::size_t i = classes; i > 0; --i) e[i - 1] = e[i] / ratio;
  return SizeGrid(std::move(e), coordinate, shape_factor);
}

double SizeGrid::size_of_volume(double v) const {
  return std::cbrt(v / shape_factor_);
}

}  // namespace comminute::pbm
