#pragma once
// The cells of a statistics grid: Cartesian (a box cut into nx × ny × nz cells) or cylindrical
// (n_r × n_theta × n_z cells of a ring r_min…r_max around an axis through `origin`, from
// z_min to z_max along the axis, theta from the first basis vector). A cylindrical grid may turn
// about its axis (turn()): cells then stay with a rotating part. Tensors and vectors binned on a
// cylindrical grid are expressed in each particle's (e_r, e_theta, e_axis) basis.
#include <array>
#include <cstddef>
#include <limits>
#include <vector>

#include "comminute/core/vec3.hpp"
#include "comminute/engine/contact_stress.hpp"

namespace comminute::analysis {

struct StatGridSpec {
  bool cylindrical = false;
  std::array<std::size_t, 3> cells{1, 1, 1};  // (x, y, z) or (r, theta, axial)
  Vec3 lo, hi;                                // m, Cartesian box
  Vec3 origin;                                // m, a point on the cylinder's axis
  Vec3 axis{0, 0, 1};                         // unit
  double r_min = 0, r_max = 0;                // m
  double z_min = 0, z_max = 0;                // m, along the axis from origin
};

class StatGrid {
 public:
  static constexpr std::size_t outside = std::numeric_limits<std::size_t>::max();
  explicit StatGrid(const StatGridSpec& spec);

  const StatGridSpec& spec() const { return s_; }
  std::size_t size() const { return s_.cells[0] * s_.cells[1] * s_.cells[2]; }
  // The cell holding point x (first index fastest), or `outside`.
  std::size_t cell_of(const Vec3& x) const;
  double volume(std::size_t cell) const;  // m³
  // The cell's index triple and the coordinates of its centre ((x, y, z) or (r, theta, axial)).
  std::array<std::size_t, 3> index(std::size_t cell) const;
  std::array<double, 3> centre(std::size_t cell) const;
  // The lattice of cell corners ((cells+1) per direction, first index fastest), in m, as the
  // grid stands now.
  std::vector<Vec3> corners() const;
  // Turns a cylindrical grid by `angle` (rad) about its axis (right-handed).
  void turn(double angle) { angle_ += angle; }
  double angle() const { return angle_; }
  void set_angle(double a) { angle_ = a; }
  // The basis in which a particle at x expresses vectors and tensors: the lab axes (Cartesian),
  // or (e_r, e_theta, e_axis) at x (cylindrical).
  std::array<Vec3, 3> basis_at(const Vec3& x) const;

 private:
  StatGridSpec s_;
  Vec3 e1_, e2_;  // with axis: right-handed (e1, e2, axis)
  double angle_ = 0;
};

// Components of a vector and of a symmetric tensor in an orthonormal basis.
Vec3 in_basis(const Vec3& v, const std::array<Vec3, 3>& e);
SymTensor in_basis(const SymTensor& t, const std::array<Vec3, 3>& e);

}  // namespace comminute::analysis
