#include "comminute/geometry/periodic_images_wall.hpp"

#include <algorithm>
#include <limits>

#include "comminute/core/error.hpp"

namespace comminute {

PeriodicImagesWall::PeriodicImagesWall(std::unique_ptr<Wall> inner, const PeriodicMap& map)
    : inner_(std::move(inner)), map_(map) {
  if (!map_.active()) throw Error("periodic images need a periodic map");
  name = inner_->name;
  material = inner_->material;
  kinematics = inner_->kinematics;
  if (map_.is_sector()) {
    for (int k = 0; k < map_.sector_count(); ++k) images_.push_back({k, 0, 0});
    return;
  }
  images_.push_back({0, 0, 0});
  for (int sx = -1; sx <= 1; ++sx)
    for (int sy = -1; sy <= 1; ++sy)
      for (int sz = -1; sz <= 1; ++sz) {
        const PeriodicMap::Shift s{sx, sy, sz};
        bool ok = s != PeriodicMap::Shift{0, 0, 0};
        for (int a = 0; a < 3; ++a)
          if (s[static_cast<std::size_t>(a)] != 0 && !map_.periodic(a)) ok = false;
        if (ok) images_.push_back(s);
      }
}

int PeriodicImagesWall::contacts(const Vec3& x, double r, double margin,
                                 std::vector<WallContact>& out) const {
  thread_local std::vector<WallContact> found;
  const auto n = static_cast<int>(images_.size());
  int count = 0;
  for (int k = 0; k < n; ++k) {
    // the particle at x meets the copy M^{-s} W of the wall exactly where its image M^{s} x
    // meets W
    const PeriodicMap::Shift& s = images_[static_cast<std::size_t>(k)];
    found.clear();
    inner_->contacts(map_.point(x, s), r, margin, found);
    PeriodicMap::Shift back = s;
    for (int& c : back) c = -c;
    for (WallContact c : found) {
      c.point = map_.point(c.point, back);
      c.normal = map_.inverse_vector(c.normal, s);
      c.feature = c.feature * n + k;
      out.push_back(c);
      ++count;
    }
  }
  return count;
}

void PeriodicImagesWall::advance(double dt) {
  inner_->kinematics = kinematics;
  inner_->advance(dt);
  kinematics = inner_->kinematics;
}

SurfaceMesh PeriodicImagesWall::surface(double extent) const {
  // every image, so that ParaView shows the whole machine
  const SurfaceMesh one = inner_->surface(extent);
  SurfaceMesh all;
  for (const auto& s : images_) {
    PeriodicMap::Shift back = s;
    for (int& c : back) c = -c;
    const auto base = static_cast<std::uint32_t>(all.vertices.size());
    for (const Vec3& v : one.vertices) all.vertices.push_back(map_.point(v, back));
    for (const auto& t : one.triangles)
      all.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    all.wear_depth.insert(all.wear_depth.end(), one.wear_depth.begin(), one.wear_depth.end());
  }
  return all;
}

bool PeriodicImagesWall::continues(int from, int to) const {
  const auto n = static_cast<int>(images_.size());
  if (from < 0 || to < 0 || from % n != to % n) return false;
  return inner_->continues(from / n, to / n);
}

int PeriodicImagesWall::image_index(const PeriodicMap::Shift& s) const {
  const auto it = std::find(images_.begin(), images_.end(), s);
  return it == images_.end() ? -1 : static_cast<int>(it - images_.begin());
}

int PeriodicImagesWall::feature_after_wrap(int feature, const std::array<int, 3>& shift) const {
  // the particle moved to M^{w} x: the copy it met through image s is its image s − w now
  const auto n = static_cast<int>(images_.size());
  if (feature < 0) return feature;
  PeriodicMap::Shift s = images_[static_cast<std::size_t>(feature % n)];
  if (map_.is_sector()) {
    const int m = map_.sector_count();
    s[0] = ((s[0] - shift[0]) % m + m) % m;
  } else {
    for (std::size_t a = 0; a < 3; ++a) s[a] -= shift[a];
  }
  const int k = image_index(s);
  if (k < 0) return std::numeric_limits<int>::min();  // out of reach: the contact ends
  return feature / n * n + k;
}

void PeriodicImagesWall::save(Archive& a, const std::string& prefix) const {
  inner_->save(a, prefix);
}

void PeriodicImagesWall::load(const Archive& a, const std::string& prefix) {
  inner_->load(a, prefix);
  kinematics = inner_->kinematics;
}

}  // namespace comminute
