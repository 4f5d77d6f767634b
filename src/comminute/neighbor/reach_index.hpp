#pragma once
// Spatial index of the particles' reach spheres at the last neighbour-list build (position and
// radius then), kept between builds so that particles appended in place (breakage fragments) find
// every partner the list must hold without a rebuild. Entries 0..n-1 are the slots at the build,
// binned in the build's two cell grids (small and large particles); appended spheres go to an
// overflow grid on the small grid's cells (a list per cell, its head array made at the first
// append, so a run without appends holds none). remap() follows the slots through compaction.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "comminute/core/vec3.hpp"
#include "comminute/neighbor/cell_grid.hpp"

namespace comminute {

class ReachIndex {
 public:
  static constexpr std::uint32_t none = 0xFFFFFFFFu;
  // Takes the grids of a build over n slots; r_small / r_large: largest radius in each grid.
  void adopt(CellGrid small, CellGrid large, bool has_large, double r_small, double r_large,
             std::size_t n);
  // Indexes the spheres (x[s], r[s]) from scratch (after a checkpoint is read).
  void build(const std::vector<Vec3>& x, const std::vector<double>& r, double skin);
  void clear() { valid_ = false; }
  bool valid() const { return valid_; }
  // old slot -> new slot (none: removed)
  void remap(const std::vector<std::uint32_t>& to_new);
  void insert(std::uint32_t slot, const Vec3& x, double r);
  // Visits the current slot of every sphere that may come within `gap` of the sphere (x, r): a
  // superset, the caller tests the distance.
  template <class F>
  void visit_near(const Vec3& x, double r, double gap, F&& f) const {
    auto visit = [&](std::uint32_t e) {
      if (slot_[e] != none) f(slot_[e]);
    };
    auto cells = [&](const CellGrid& g, double r_other) {
      const double n = std::ceil((r + r_other + gap) / g.edge());  // clamped before converting
      return n > 0 ? static_cast<int>(std::min(n, 1e9)) : 0;
    };
    const auto c = small_.cell_of(x);
    small_.visit_around(c, cells(small_, r_small_), visit);
    if (has_large_) large_.visit_around(large_.cell_of(x), cells(large_, r_large_), visit);
    if (extra_next_.empty()) return;
    small_.visit_cells_around(c, cells(small_, r_extra_), [&](std::size_t cell) {
      for (std::uint32_t e = extra_head_[cell]; e != none; e = extra_next_[e - n_build_]) visit(e);
    });
  }

 private:
  CellGrid small_, large_;
  bool has_large_ = false, valid_ = false;
  double r_small_ = 0, r_large_ = 0, r_extra_ = 0;  // m, largest radius per part
  std::vector<std::uint32_t> slot_;                 // entry -> current slot
  // the appended entries (n_build_ on): per small cell the last one appended there, and per entry
  // the one appended there before it (none: the first)
  std::size_t n_build_ = 0;
  std::vector<std::uint32_t> extra_head_, extra_next_;
};

}  // namespace comminute
