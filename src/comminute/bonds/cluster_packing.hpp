#pragma once
// A grain template: the sub-spheres that fill a cluster shape, all of one radius, in the shape's
// body frame, and the pairs of them to bond.
//
// Packing (a dense random packing by overlap relaxation, in the spirit of the force-biased
// algorithm of Mościński, Bargieł, Rycerz & Jacobs, Mol. Simul. 1989): n centres are drawn
// uniformly where a sphere of the radius fits; then, repeatedly, every overlapping pair is pushed
// apart by half its overlap each and every sphere that pokes out of the shape is moved back along
// the surface normal until it fits. The radius starts at the value that gives the target solid
// fraction φ, r = (φ V / (n 4π/3))^{1/3}; when the overlaps do not vanish (jammed) it shrinks by
// 1 % and the relaxation goes on. The result: every sphere inside the shape, overlaps below
// 1e-4 r, solid fraction at most φ.
#include <array>
#include <cstdint>
#include <vector>

#include "comminute/bonds/cluster_shape.hpp"
#include "comminute/core/rng.hpp"

namespace comminute::bonds {

struct GrainTemplate {
  std::vector<Vec3> centres;       // m, body frame
  double radius = 0;               // m, of every sub-sphere
  double volume = 0;               // m³, of the shape (the grain's nominal volume)
  double equivalent_diameter = 0;  // m
  std::vector<std::array<std::uint32_t, 2>> bonds;  // pairs of sub-spheres (i < j)
  double solid_fraction() const;                    // sub-sphere volume / shape volume
};

// Packs n sub-spheres into the shape at a target solid fraction; throws Error when n < 1 or the
// relaxation cannot fit them (after shrinking the radius to half its start).
GrainTemplate pack_cluster(const ClusterShape& shape, int n, double solid_fraction, Rng& rng);

// The pairs whose surface gap |x_j − x_i| − 2r is at most gap (overlapping pairs included).
std::vector<std::array<std::uint32_t, 2>> pairs_within_gap(const std::vector<Vec3>& centres,
                                                           double radius, double gap);

// Number of connected components of n nodes joined by the pairs (1: one piece).
std::size_t count_components(std::size_t n, const std::vector<std::array<std::uint32_t, 2>>& pairs);

}  // namespace comminute::bonds
