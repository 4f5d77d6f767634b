#include "comminute/geometry/mesh_surface.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>
#include <utility>

namespace comminute {

namespace {

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t a) {
  while (parent[a] != a) a = parent[a] = parent[parent[a]];
  return a;
}

// Normals this close are one plane (cos of about 1.4e-6 rad).
constexpr double kCoplanar = 1 - 1e-12;
// Relative slack of the plane-distance reject and of the candidate-triangle lists: far above the
// round-off of a distance (1e-16 relative), far below any skin.
constexpr double kReachSlack = 1e-9;

}  // namespace

MeshSurface::MeshSurface(std::vector<Vec3> vertices,
                         std::vector<std::array<std::uint32_t, 3>> triangles)
    : v_(std::move(vertices)), tri_(std::move(triangles)) {
  const std::size_t nt = tri_.size();
  normal_.resize(nt);
  area_.resize(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    const Vec3 c = cross(v_[tri_[t][1]] - v_[tri_[t][0]], v_[tri_[t][2]] - v_[tri_[t][0]]);
    area_[t] = 0.5 * norm(c);
    normal_[t] = c / norm(c);
  }
  // unique edges
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> edge_of;
  tri_edge_.resize(nt);
  for (std::size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const auto key = std::minmax(tri_[t][k], tri_[t][(k + 1) % 3]);
      auto [it, fresh] = edge_of.emplace(key, static_cast<std::uint32_t>(edge_vertex_.size()));
      if (fresh) {
        edge_vertex_.push_back({key.first, key.second});
        edge_triangle_.push_back({static_cast<std::int64_t>(t), -1});
      } else {
        edge_triangle_[it->second][1] = static_cast<std::int64_t>(t);
      }
      tri_edge_[t][k] = it->second;
    }
  // planar patches: union across edges whose two triangles share their normal
  std::vector<std::uint32_t> parent(nt);
  std::iota(parent.begin(), parent.end(), 0u);
  for (const auto& et : edge_triangle_)
    if (et[1] >= 0 && dot(normal_[et[0]], normal_[et[1]]) >= kCoplanar) {
      const auto a = find_root(parent, static_cast<std::uint32_t>(et[0]));
      const auto b = find_root(parent, static_cast<std::uint32_t>(et[1]));
      parent[std::max(a, b)] = std::min(a, b);
    }
  // patch ids in order of their first triangle
  patch_.assign(nt, 0);
  std::vector<std::int64_t> id_of_root(nt, -1);
  for (std::size_t t = 0; t < nt; ++t) {
    const auto root = find_root(parent, static_cast<std::uint32_t>(t));
    if (id_of_root[root] < 0) id_of_root[root] = static_cast<std::int64_t>(n_patch_++);
    patch_[t] = static_cast<std::uint32_t>(id_of_root[root]);
  }
  for (const auto& et : edge_triangle_)
    if (et[1] >= 0 && patch_[et[0]] != patch_[et[1]]) {
      const auto [a, b] = std::minmax(patch_[et[0]], patch_[et[1]]);
      patch_pairs_.push_back(static_cast<std::uint64_t>(a) << 32 | b);
    }
  std::sort(patch_pairs_.begin(), patch_pairs_.end());
  patch_pairs_.erase(std::unique(patch_pairs_.begin(), patch_pairs_.end()), patch_pairs_.end());
  // triangles around each vertex (CSR)
  vertex_start_.assign(v_.size() + 1, 0);
  for (const auto& t : tri_)
    for (auto v : t) ++vertex_start_[v + 1];
  for (std::size_t v = 0; v < v_.size(); ++v) vertex_start_[v + 1] += vertex_start_[v];
  vertex_triangle_.resize(vertex_start_.back());
  std::vector<std::uint32_t> fill(vertex_start_.begin(), vertex_start_.end() - 1);
  for (std::size_t t = 0; t < nt; ++t)
    for (auto v : tri_[t]) vertex_triangle_[fill[v]++] = static_cast<std::uint32_t>(t);
  // features inside a planar patch: an edge between two triangles of one patch, a vertex whose
  // edges all are such edges
  edge_flat_.assign(edge_vertex_.size(), 0);
  vertex_flat_.assign(v_.size(), 1);
  for (std::size_t e = 0; e < edge_vertex_.size(); ++e) {
    const auto& et = edge_triangle_[e];
    edge_flat_[e] = et[1] >= 0 && patch_[et[0]] == patch_[et[1]];
    if (!edge_flat_[e]) vertex_flat_[edge_vertex_[e][0]] = vertex_flat_[edge_vertex_[e][1]] = 0;
  }
  bins_.build(v_, tri_);
}

// Closest point of triangle t to x and its region (Ericson 2005, Sec. 5.1.5), with the face
// region tested first and inclusively: a projection on an edge between two triangles of a plane
// is a face contact of both (one is kept per patch), so a flat tiled surface acts as a plane.
MeshSurface::Closest MeshSurface::closest(std::uint32_t t, const Vec3& p) const {
  const Vec3 &a = v_[tri_[t][0]], &b = v_[tri_[t][1]], &c = v_[tri_[t][2]];
  const Vec3 ab = b - a, ac = c - a, ap = p - a, bp = p - b, cp = p - c;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap), d3 = dot(ab, bp), d4 = dot(ac, bp),
               d5 = dot(ab, cp), d6 = dot(ac, cp);
  const double va = d3 * d6 - d5 * d4, vb = d5 * d2 - d1 * d6, vc = d1 * d4 - d3 * d2;
  const double tol = -1e-12 * std::abs(va + vb + vc);
  const Vec3& n = normal_[t];
  if (va >= tol && vb >= tol && vc >= tol) return {p - dot(p - a, n) * n, face, 0};
  if (d1 <= 0 && d2 <= 0) return {a, corner, 0};
  if (d3 >= 0 && d4 <= d3) return {b, corner, 1};
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return {a + ab * (d1 / (d1 - d3)), edge, 0};
  if (d6 >= 0 && d5 <= d6) return {c, corner, 2};
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return {a + ac * (d2 / (d2 - d6)), edge, 2};
  return {b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))), edge, 1};
}

void MeshSurface::gather(const Vec3& x, double reach, std::vector<std::uint32_t>& near) const {
  const Vec3 d{reach, reach, reach};
  bins_.query(x - d, x + d, near);
  std::sort(near.begin(), near.end());
  near.erase(std::unique(near.begin(), near.end()), near.end());
}

bool MeshSurface::beyond(std::uint32_t t, const Vec3& x, double reach) const {
  // the distance to the plane bounds the distance to the triangle from below; the relative slack
  // keeps every triangle whose computed distance (closest()) could round below `reach`
  return std::abs(dot(x - v_[tri_[t][0]], normal_[t])) >= reach * (1 + kReachSlack);
}

void MeshSurface::near_triangles(const Vec3& x, double reach,
                                 std::vector<std::uint32_t>& out) const {
  thread_local std::vector<std::uint32_t> near;
  near.clear();
  const Vec3 d{reach, reach, reach};
  bins_.query(x - d, x + d, near);
  // the bins list many triangles (repeated across cells) and few are within reach: those few are
  // sorted and made unique, not the whole gathered list (the same ascending list as gather())
  const std::size_t first = out.size();
  for (std::uint32_t t : near)
    if (!beyond(t, x, reach) && norm(x - closest(t, x).point) < reach * (1 + kReachSlack))
      out.push_back(t);
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
  out.erase(std::unique(out.begin() + static_cast<std::ptrdiff_t>(first), out.end()), out.end());
}

void MeshSurface::contacts(const Vec3& x, double r, double margin,
                           std::vector<WallContact>& out) const {
  thread_local std::vector<std::uint32_t> near;
  near.clear();
  gather(x, r + margin, near);
  contacts_among(x, r, margin, near, out);
}

void MeshSurface::contacts_among(const Vec3& x, double r, double margin,
                                 std::span<const std::uint32_t> near,
                                 std::vector<WallContact>& out) const {
  struct Hit {
    WallContact contact;
    Region region;
    std::uint32_t id;  // patch, edge or vertex
  };
  thread_local std::vector<Hit> hits;
  hits.clear();
  const double reach = r + margin;
  const bool candidates = margin > 0;
  for (std::uint32_t t : near) {
    if (beyond(t, x, reach)) continue;
    const Closest q = closest(t, x);
    if (candidates) {
      // every feature of a triangle within reach that lies within reach itself: the face, and
      // the edges and corners that are not inside a planar patch
      const double dist = norm(x - q.point);
      if (dist >= reach) continue;
      const int element = static_cast<int>(t);
      hits.push_back({{normal_[t], q.point, r - dist, 0, element}, face, patch_[t]});
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t e = tri_edge_[t][k], v = tri_[t][k];
        const Vec3 &a = v_[edge_vertex_[e][0]], &b = v_[edge_vertex_[e][1]];
        const double s = std::clamp(dot(x - a, b - a) / norm2(b - a), 0.0, 1.0);
        const Vec3 pe = a + (b - a) * s;
        const double de = norm(x - pe);
        if (!edge_flat_[e] && de < reach)
          hits.push_back({{normal_[t], pe, r - de, 0, element}, edge, e});
        const double dv = norm(x - v_[v]);
        if (!vertex_flat_[v] && dv < reach)
          hits.push_back({{normal_[t], v_[v], r - dv, 0, element}, corner, v});
      }
      continue;
    }
    Hit h;
    h.region = q.region;
    double dist = 0;
    Vec3 nrm = normal_[t];
    if (q.region == face) {
      const double s = dot(x - v_[tri_[t][0]], nrm);
      dist = std::abs(s);
      if (s < 0) nrm = -1.0 * nrm;
      h.id = patch_[t];
    } else {
      const Vec3 delta = x - q.point;
      dist = norm(delta);
      if (dist > 0) nrm = delta / dist;
      h.id = q.region == edge ? tri_edge_[t][q.local] : tri_[t][q.local];
      if (q.region == edge ? edge_flat_[h.id] : vertex_flat_[h.id]) continue;
    }
    if (dist >= reach) continue;
    h.contact = {nrm, q.point, r - dist, 0, static_cast<int>(t)};
    hits.push_back(h);
  }
  // Grouped by feature (then triangle): each feature once, from its lowest triangle. An edge or
  // corner is the closest feature of the surface only when every triangle around it finds its
  // closest point there (the sphere centre is in that feature's Voronoi region): each triangle
  // reports a feature at most once, so that is a count.
  std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) {
    return std::tie(a.region, a.id, a.contact.element) <
           std::tie(b.region, b.id, b.contact.element);
  });
  const int np = static_cast<int>(n_patch_), ne = static_cast<int>(edge_vertex_.size());
  const std::size_t first = out.size();
  for (std::size_t g = 0; g < hits.size();) {
    const Hit& h = hits[g];
    std::size_t end = g + 1;
    while (end < hits.size() && hits[end].region == h.region && hits[end].id == h.id) ++end;
    const std::size_t reports = end - g;
    g = end;
    if (!candidates && h.region == edge && reports != (edge_triangle_[h.id][1] >= 0 ? 2u : 1u))
      continue;
    if (!candidates && h.region == corner &&
        reports != vertex_start_[h.id + 1] - vertex_start_[h.id])
      continue;
    WallContact c = h.contact;
    c.feature = h.region == face   ? static_cast<int>(h.id)
                : h.region == edge ? np + static_cast<int>(h.id)
                                   : np + ne + static_cast<int>(h.id);
    out.push_back(c);
  }
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end(),
            [](const WallContact& a, const WallContact& b) { return a.feature < b.feature; });
}

bool MeshSurface::patch_has_vertex(std::uint32_t patch, std::uint32_t v) const {
  for (std::uint32_t s = vertex_start_[v]; s < vertex_start_[v + 1]; ++s)
    if (patch_[vertex_triangle_[s]] == patch) return true;
  return false;
}

bool MeshSurface::adjacent(int a, int b) const {
  if (a == b) return true;
  if (a < 0 || b < 0) return false;
  if (a > b) std::swap(a, b);
  const auto np = static_cast<std::int64_t>(n_patch_);
  const auto ne = static_cast<std::int64_t>(edge_vertex_.size());
  const std::int64_t nv = static_cast<std::int64_t>(v_.size());
  auto kind = [&](std::int64_t f) {
    return f < np ? 0 : f < np + ne ? 1 : f < np + ne + nv ? 2 : 3;
  };
  const int ka = kind(a), kb = kind(b);
  if (ka == 3 || kb == 3) return false;
  const auto ua = static_cast<std::uint32_t>(ka == 0 ? a : ka == 1 ? a - np : a - np - ne);
  const auto ub = static_cast<std::uint32_t>(kb == 0 ? b : kb == 1 ? b - np : b - np - ne);
  if (ka == 0 && kb == 0)
    return std::binary_search(patch_pairs_.begin(), patch_pairs_.end(),
                              static_cast<std::uint64_t>(ua) << 32 | ub);
  if (ka == 0 && kb == 1) {
    for (auto t : edge_triangle_[ub])
      if (t >= 0 && patch_[t] == ua) return true;
    return false;
  }
  if (ka == 0 && kb == 2) return patch_has_vertex(ua, ub);
  if (ka == 1 && kb == 1) {
    const auto &e = edge_vertex_[ua], &f = edge_vertex_[ub];
    return e[0] == f[0] || e[0] == f[1] || e[1] == f[0] || e[1] == f[1];
  }
  if (ka == 1 && kb == 2) return edge_vertex_[ua][0] == ub || edge_vertex_[ua][1] == ub;
  // two corners: joined by an edge
  for (std::uint32_t s = vertex_start_[ua]; s < vertex_start_[ua + 1]; ++s)
    for (auto v : tri_[vertex_triangle_[s]])
      if (v == ub) return true;
  return false;
}

double MeshSurface::reach_from(const Vec3& c) const {
  double r2 = 0;
  for (const Vec3& p : v_) r2 = std::max(r2, norm2(p - c));
  return std::sqrt(r2);
}

double MeshSurface::reach_from_axis(const Vec3& c, const Vec3& a) const {
  double r2 = 0;
  for (const Vec3& p : v_) r2 = std::max(r2, norm2(cross(a, p - c)));
  return std::sqrt(r2);
}

std::size_t MeshSurface::bytes() const {
  return v_.capacity() * sizeof(Vec3) + tri_.capacity() * sizeof(tri_[0]) +
         normal_.capacity() * sizeof(Vec3) + area_.capacity() * sizeof(double) +
         tri_edge_.capacity() * sizeof(tri_edge_[0]) +
         edge_vertex_.capacity() * sizeof(edge_vertex_[0]) +
         edge_triangle_.capacity() * sizeof(edge_triangle_[0]) +
         patch_.capacity() * sizeof(std::uint32_t) +
         (vertex_start_.capacity() + vertex_triangle_.capacity()) * sizeof(std::uint32_t) +
         patch_pairs_.capacity() * sizeof(std::uint64_t) + bins_.bytes();
}

}  // namespace comminute
