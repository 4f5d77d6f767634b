#include "comminute/bonds/cluster_shape.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

#include "comminute/core/error.hpp"

namespace comminute::bonds {

double ClusterShape::equivalent_diameter() const {
  return std::cbrt(6 * volume() / std::numbers::pi);
}

Vec3 ClusterShape::outward_normal(const Vec3& x) const {
  const Vec3 h = half_extent();
  const double eps = 1e-7 * std::max({h.x, h.y, h.z});
  Vec3 g;
  for (int a = 0; a < 3; ++a) {
    Vec3 up = x, down = x;
    up[a] += eps;
    down[a] -= eps;
    g[a] = signed_distance(up) - signed_distance(down);
  }
  const double n = norm(g);
  return n > 0 ? g / n : Vec3{1, 0, 0};
}

double ellipsoid_signed_distance(const Vec3& e, const Vec3& x) {
  // by symmetry the first octant; a zero coordinate is moved off the plane by 1e-9 of the
  // smallest semi-axis (changes the distance by at most that much)
  const double emin = std::min({e.x, e.y, e.z});
  Vec3 y;
  for (int a = 0; a < 3; ++a) y[a] = std::max(std::abs(x[a]), 1e-9 * emin);
  const double q =
      (y.x / e.x) * (y.x / e.x) + (y.y / e.y) * (y.y / e.y) + (y.z / e.z) * (y.z / e.z);
  auto f = [&](double t) {
    double s = -1;
    for (int a = 0; a < 3; ++a) {
      const double r = e[a] * y[a] / (t + e[a] * e[a]);
      s += r * r;
    }
    return s;
  };
  // F decreases on t > −emin²; F ≥ 0 at the lower end, F ≤ 0 at the upper one
  int k = 0;
  for (int a = 1; a < 3; ++a)
    if (e[a] < e[k]) k = a;
  double lo = -e[k] * e[k] + e[k] * y[k];
  double hi = std::max({e.x, e.y, e.z}) * norm(y);
  for (int it = 0; it < 200 && hi - lo > 0; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (f(mid) > 0 ? lo : hi) = mid;
  }
  const double t = 0.5 * (lo + hi);
  Vec3 c;
  for (int a = 0; a < 3; ++a) c[a] = e[a] * e[a] * y[a] / (t + e[a] * e[a]);
  const double d = norm(y - c);
  return q < 1 ? -d : d;
}

namespace {

class SphereShape final : public ClusterShape {
 public:
  explicit SphereShape(double d) : r_(0.5 * d) {}
  double signed_distance(const Vec3& x) const override { return norm(x) - r_; }
  double volume() const override { return 4.0 / 3.0 * std::numbers::pi * r_ * r_ * r_; }
  Vec3 half_extent() const override { return {r_, r_, r_}; }

 private:
  double r_;
};

class EllipsoidShape final : public ClusterShape {
 public:
  EllipsoidShape(double l, double w, double t) : e_{0.5 * l, 0.5 * w, 0.5 * t} {}
  double signed_distance(const Vec3& x) const override { return ellipsoid_signed_distance(e_, x); }
  double volume() const override { return 4.0 / 3.0 * std::numbers::pi * e_.x * e_.y * e_.z; }
  Vec3 half_extent() const override { return e_; }

 private:
  Vec3 e_;
};

// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection, 2005, Sec. 5.1.5).
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1 / (va + vb + vc);
  return a + (vb * denom) * ab + (vc * denom) * ac;
}

class MeshShape final : public ClusterShape {
 public:
  explicit MeshShape(IndexedMesh m) : m_(std::move(m)) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (const auto& t : m_.triangles)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = t[k], b = t[(k + 1) % 3];
        ++edges[{std::min(a, b), std::max(a, b)}];
      }
    for (const auto& [e, n] : edges)
      if (n != 2) throw Error("the grain mesh is not closed: an edge belongs to one triangle only");
    // volume and centroid by the divergence theorem over tetrahedra from the origin
    double v = 0;
    Vec3 c;
    for (const auto& t : m_.triangles) {
      const Vec3 &a = m_.vertices[t[0]], &b = m_.vertices[t[1]], &d = m_.vertices[t[2]];
      const double vt = dot(a, cross(b, d)) / 6;
      v += vt;
      c += vt * (a + b + d) / 4;
    }
    if (v < 0) {  // inward-facing triangles: the same solid
      v = -v;
      c = -c;
    }
    if (!(v > 0)) throw Error("the grain mesh encloses no volume");
    c /= v;
    volume_ = v;
    for (Vec3& x : m_.vertices) {
      x -= c;
      for (int a = 0; a < 3; ++a) half_[a] = std::max(half_[a], std::abs(x[a]));
    }
  }
  double signed_distance(const Vec3& x) const override {
    double d2 = std::numeric_limits<double>::infinity();
    double winding = 0;
    for (const auto& t : m_.triangles) {
      const Vec3 a = m_.vertices[t[0]] - x, b = m_.vertices[t[1]] - x, c = m_.vertices[t[2]] - x;
      d2 = std::min(d2, norm2(closest_on_triangle({}, a, b, c)));
      // solid angle of the triangle seen from x (Van Oosterom & Strackee, IEEE Trans. Biomed.
      // Eng. 1983, eq. 8); the sum over a closed surface is ±4π inside, 0 outside
      const double la = norm(a), lb = norm(b), lc = norm(c);
      winding += 2 * std::atan2(dot(a, cross(b, c)),
                                la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb);
    }
    const bool inside = std::abs(winding) > 2 * std::numbers::pi;
    return inside ? -std::sqrt(d2) : std::sqrt(d2);
  }
  double volume() const override { return volume_; }
  Vec3 half_extent() const override { return half_; }

 private:
  IndexedMesh m_;
  double volume_ = 0;
  Vec3 half_;
};

}  // namespace

std::unique_ptr<ClusterShape> make_sphere_shape(double diameter) {
  return std::make_unique<SphereShape>(diameter);
}

std::unique_ptr<ClusterShape> make_ellipsoid_shape(double length, double width, double thickness) {
  return std::make_unique<EllipsoidShape>(length, width, thickness);
}

std::unique_ptr<ClusterShape> make_mesh_shape(const IndexedMesh& mesh) {
  return std::make_unique<MeshShape>(mesh);
}

}  // namespace comminute::bonds
