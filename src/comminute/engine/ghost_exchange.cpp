#include "comminute/engine/ghost_exchange.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "comminute/core/error.hpp"

namespace comminute {

void GhostExchange::attach(ParticleStore& p) {
  f_label_[0] = p.add_field("periodic.image_x", 0.0);
  f_label_[1] = p.add_field("periodic.image_y", 0.0);
  f_label_[2] = p.add_field("periodic.image_z", 0.0);
}

PeriodicMap::Shift GhostExchange::label_of(const ParticleStore& p, std::size_t i) const {
  PeriodicMap::Shift c{};
  for (std::size_t a = 0; a < 3; ++a) c[a] = static_cast<int>(p.field(f_label_[a])[i]);
  return c;
}

void GhostExchange::wrap(ParticleStore& p) {
  wrapped_.clear();
  for (std::size_t i = 0; i < p.owned(); ++i) {
    const PeriodicMap::Shift s = map.wrap_shift(p.x[i]);
    if (s == PeriodicMap::Shift{0, 0, 0}) continue;
    wrapped_.push_back({p.id[i], s});
    p.x[i] = map.point(p.x[i], s);
    p.v[i] = map.vector(p.v[i], s);
    p.w[i] = map.vector(p.w[i], s);
    for (std::size_t a = 0; a < 3; ++a) p.field(f_label_[a])[i] -= s[a];
  }
  std::sort(wrapped_.begin(), wrapped_.end(),
            [](const Wrapped& a, const Wrapped& b) { return a.id < b.id; });
}

void GhostExchange::plan(const ParticleStore& p, double skin) {
  owner_.clear();
  image_.clear();
  const std::size_t n = p.owned();
  double rmax = 0;
  for (std::size_t i = 0; i < n; ++i) rmax = std::max(rmax, p.radius[i]);
  const auto& images = map.images();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < images.size(); ++k)
      if (map.needs_ghost(p.x[i], images[k], p.radius[i] + rmax + skin)) {
        owner_.push_back(static_cast<std::uint32_t>(i));
        image_.push_back(static_cast<std::uint8_t>(k));
      }
}

void GhostExchange::append(ParticleStore& p) const {
  for (std::size_t g = 0; g < owner_.size(); ++g) {
    const std::size_t o = owner_[g];
    const auto& s = image(g);
    p.add_ghost(o, map.point(p.x[o], s), map.vector(p.v[o], s), map.vector(p.w[o], s));
  }
}

const std::vector<std::uint64_t>& GhostExchange::labels(const ParticleStore& p) {
  const std::size_t n = p.owned();
  labels_.resize(p.size());
  for (std::size_t i = 0; i < n; ++i) labels_[i] = PeriodicMap::pack(label_of(p, i));
  for (std::size_t g = 0; g < p.ghost_owner.size(); ++g) {
    PeriodicMap::Shift c = label_of(p, owner_[g]);
    for (std::size_t a = 0; a < 3; ++a) c[a] -= image(g)[a];
    labels_[n + g] = PeriodicMap::pack(c);
  }
  return labels_;
}

void GhostExchange::turn_carried(const NeighborList::Carry& carried,
                                 ContactStateStore& state) const {
  if (!map.is_sector()) return;  // translations leave vectors as they are
  for (std::size_t e = 0; e < carried.to.size(); ++e) {
    // labels of a sector use the first field only: the difference is a signed turn count t, and
    // the pair's new copy is the old one turned by -t (x = R^{-c} u)
    const auto t = static_cast<int>(static_cast<std::int64_t>(carried.shift[e]));
    if (t != 0)
      state.map_vectors(carried.to[e], [&](const Vec3& v) { return map.turn_vector(v, -t); });
  }
}

void GhostExchange::fold(ParticleStore& p) const {
  const std::size_t n = p.owned();
  for (std::size_t g = 0; g < p.ghost_owner.size(); ++g) {
    const std::size_t o = p.ghost_owner[g], s = n + g;
    p.f[o] += map.inverse_vector(p.f[s], image(g));
    p.t[o] += map.inverse_vector(p.t[s], image(g));
    p.f[s] = {};
    p.t[s] = {};
  }
}

Vec3 GhostExchange::position(const ParticleStore& p, std::size_t slot, std::size_t n) const {
  if (slot < n || slot - n >= owner_.size()) return p.x[slot];
  return from_owner_frame(slot, n, p.x[owner_[slot - n]]);
}

Vec3 GhostExchange::from_owner_frame(std::size_t slot, std::size_t n, const Vec3& x) const {
  if (slot < n || slot - n >= owner_.size()) return x;
  return map.point(x, image(slot - n));
}

Vec3 GhostExchange::to_owner_frame(std::size_t slot, std::size_t n, const Vec3& x) const {
  if (slot < n || slot - n >= owner_.size()) return x;
  PeriodicMap::Shift back = image(slot - n);
  for (int& c : back) c = -c;
  return map.point(x, back);
}

void GhostExchange::save(Archive& a) const {
  a.put("periodic/ghost_owner", owner_);
  a.put("periodic/ghost_image", image_);
}

void GhostExchange::load(const Archive& a, std::size_t n_owned) {
  auto owner = a.get<std::uint32_t>("periodic/ghost_owner");
  auto image = a.get<std::uint8_t>("periodic/ghost_image");
  if (image.size() != owner.size())
    throw Error(
        fmt::format("checkpoint entry 'periodic/ghost_image' holds {} ghosts, "
                    "'periodic/ghost_owner' {}",
                    image.size(), owner.size()));
  for (std::size_t g = 0; g < owner.size(); ++g)
    if (owner[g] >= n_owned || image[g] >= map.images().size())
      throw Error(
          fmt::format("checkpoint entry 'periodic/ghost_owner': ghost {} (owner {}, image "
                      "{}) is not an image of one of the {} particles",
                      g, owner[g], image[g], n_owned));
  owner_ = std::move(owner);
  image_ = std::move(image);
}

}  // namespace comminute
