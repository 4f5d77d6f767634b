#include "comminute/engine/wall_element_lists.hpp"

namespace comminute {

void WallElementLists::clear(std::size_t n_walls) {
  walls_.assign(n_walls, Lists{});
}

void WallElementLists::start(std::uint32_t w) {
  Lists& l = walls_.at(w);
  l.on = true;
  l.start.assign(1, 0);
  l.items.clear();
}

void WallElementLists::append(std::uint32_t w, std::span<const std::uint32_t> elements) {
  Lists& l = walls_[w];
  l.items.insert(l.items.end(), elements.begin(), elements.end());
  l.start.push_back(static_cast<std::uint32_t>(l.items.size()));
}

WallElementLists WallElementLists::remapped(std::span<const std::uint32_t> to_new,
                                            std::size_t n_kept, std::uint32_t removed) const {
  std::vector<std::uint32_t> from(n_kept, removed);  // new slot -> old slot
  for (std::size_t old = 0; old < to_new.size(); ++old)
    if (to_new[old] != removed && to_new[old] < n_kept)
      from[to_new[old]] = static_cast<std::uint32_t>(old);
  WallElementLists next;
  next.clear(walls_.size());
  for (std::uint32_t w = 0; w < walls_.size(); ++w) {
    if (!walls_[w].on) continue;
    next.start(w);
    for (std::uint32_t old : from) {
      const auto list = old == removed ? std::nullopt : find(w, old);
      if (!list) {
        next.walls_[w] = Lists{};
        break;
      }
      next.append(w, *list);
    }
  }
  return next;
}

std::size_t WallElementLists::bytes() const {
  std::size_t b = 0;
  for (const Lists& l : walls_)
    b += (l.start.capacity() + l.items.capacity()) * sizeof(std::uint32_t);
  return b;
}

}  // namespace comminute
