#pragma once
// Per wall and particle: the elements (triangles of a mesh wall) within the skin of the
// particle's reach sphere when the wall candidates were last searched (Wall::near_elements).
// While the candidates are current (the reach grew and the wall travelled less than skin/2 each)
// a list holds every element the particle can touch, so the force loop looks its contacts up among
// them (Wall::contacts_among) instead of searching the wall's cell grid every step; the result
// is the same, bit for bit. A wall without elements, or lists not built since a checkpoint was
// read, falls back to the search.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace comminute {

class WallElementLists {
 public:
  // No lists for any of n_walls walls.
  void clear(std::size_t n_walls);
  // Wall w gets lists, appended by append() for particles 0, 1, 2, ... in that order.
  void start(std::uint32_t w);
  // The list of wall w's next particle.
  void append(std::uint32_t w, std::span<const std::uint32_t> elements);
  // Particle i's list for wall w, or nothing when wall w has no list for it.
  // (in the header: the wall force loop asks once per particle and wall, every step)
  std::optional<std::span<const std::uint32_t>> find(std::uint32_t w, std::uint32_t i) const {
    if (w >= walls_.size()) return std::nullopt;
    const Lists& l = walls_[w];
    if (!l.on || i + 1 >= l.start.size()) return std::nullopt;
    return std::span<const std::uint32_t>(l.items.data() + l.start[i], l.start[i + 1] - l.start[i]);
  }
  bool on(std::uint32_t w) const { return w < walls_.size() && walls_[w].on; }
  // After particles were removed and others appended (PairTracker::replace): the lists of the
  // kept particles at their new slots 0 .. n_kept - 1 (to_new: old slot -> new slot or
  // `removed`), ready for append() of the appended ones. A wall loses its lists when they did not
  // cover every kept particle.
  WallElementLists remapped(std::span<const std::uint32_t> to_new, std::size_t n_kept,
                            std::uint32_t removed) const;
  std::size_t bytes() const;

 private:
  struct Lists {
    bool on = false;
    std::vector<std::uint32_t> start{0};  // per particle, + 1
    std::vector<std::uint32_t> items;
  };
  std::vector<Lists> walls_;
};

}  // namespace comminute
