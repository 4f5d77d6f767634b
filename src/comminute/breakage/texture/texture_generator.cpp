#include "comminute/breakage/texture/texture_generator.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "comminute/core/error.hpp"

namespace comminute::breakage::texture {

namespace {

// Poisson number of grains with mean `mean`: exact (product of uniforms, Knuth) below 50, the
// normal approximation above (relative error of the variance below 1/mean).
std::uint64_t poisson(double mean, Rng& rng) {
  if (mean < 50) {
    const double l = std::exp(-mean);
    std::uint64_t k = 0;
    for (double prod = rng.uniform(); prod > l; prod *= rng.uniform()) ++k;
    return k;
  }
  return static_cast<std::uint64_t>(std::max(0.0, std::round(rng.normal(mean, std::sqrt(mean)))));
}

void boolean_spheres(const GeneratorSpec& s, const GrainSpec& g, double matrix_left,
                     std::vector<std::uint8_t>& labels, Rng& rng) {
  // Conditional fraction of the matrix left that this phase must cover.
  const double p = g.volume_fraction / matrix_left;
  const double mean_r3 =
      std::pow(g.grain_radius, 3) * std::exp(4.5 * g.grain_radius_sigma * g.grain_radius_sigma);
  // Boolean model: V_V = 1 - exp(-lambda (4/3) pi E[r^3]) (Chiu, Stoyan, Kendall & Mecke,
  // Stochastic Geometry and its Applications, 3rd ed. 2013, ch. 3) solved for lambda.
  const double lambda = -std::log(1 - p) / (4.0 / 3.0 * std::numbers::pi * mean_r3);
  const double vx = s.voxel_size;
  const auto nx = static_cast<long>(s.nx), ny = static_cast<long>(s.ny),
             nz = static_cast<long>(s.nz);
  const double box = vx * vx * vx * static_cast<double>(nx * ny * nz);
  if (!(lambda * box < 1e8))
    throw Error("texture generator: more than 1e8 grains expected (grains too small for the box)");
  const std::uint64_t count = poisson(lambda * box, rng);
  std::vector<std::uint8_t> hit(labels.size(), 0);
  for (std::uint64_t n = 0; n < count; ++n) {
    const double cx = rng.uniform() * static_cast<double>(nx),
                 cy = rng.uniform() * static_cast<double>(ny),
                 cz = rng.uniform() * static_cast<double>(nz);  // in voxels
    const double r = g.grain_radius * std::exp(g.grain_radius_sigma * rng.normal()) / vx;
    const long lo_x = static_cast<long>(std::floor(cx - r)), hi_x = static_cast<long>(cx + r);
    const long lo_y = static_cast<long>(std::floor(cy - r)), hi_y = static_cast<long>(cy + r);
    const long lo_z = static_cast<long>(std::floor(cz - r)), hi_z = static_cast<long>(cz + r);
    for (long k = lo_z; k <= hi_z; ++k)
      for (long j = lo_y; j <= hi_y; ++j)
        for (long i = lo_x; i <= hi_x; ++i) {
          const double dx = static_cast<double>(i) + 0.5 - cx,
                       dy = static_cast<double>(j) + 0.5 - cy,
                       dz = static_cast<double>(k) + 0.5 - cz;
          if (dx * dx + dy * dy + dz * dz > r * r) continue;
          const long wi = ((i % nx) + nx) % nx, wj = ((j % ny) + ny) % ny,
                     wk = ((k % nz) + nz) % nz;  // periodic box
          hit[static_cast<std::size_t>(wi + nx * (wj + ny * wk))] = 1;
        }
  }
  for (std::size_t v = 0; v < labels.size(); ++v)
    if (hit[v] && labels[v] == 0) labels[v] = g.phase;  // only into the matrix left
}

void lattice(const GeneratorSpec& s, const std::vector<GrainSpec>& grains,
             std::vector<std::uint8_t>& labels, Rng& rng) {
  // Wiegel's random lattice: one edge for all grains (that of the first grain phase).
  const auto edge = static_cast<std::size_t>(
      std::max(1.0, std::round(2 * grains.front().grain_radius / s.voxel_size)));
  const std::size_t cx = (s.nx + edge - 1) / edge, cy = (s.ny + edge - 1) / edge,
                    cz = (s.nz + edge - 1) / edge;
  std::vector<std::uint8_t> cell(cx * cy * cz, 0);
  for (auto& c : cell) {
    double u = rng.uniform();
    for (const auto& g : grains) {
      if (u < g.volume_fraction) {
        c = g.phase;
        break;
      }
      u -= g.volume_fraction;
    }
  }
  for (std::size_t k = 0; k < s.nz; ++k)
    for (std::size_t j = 0; j < s.ny; ++j)
      for (std::size_t i = 0; i < s.nx; ++i)
        labels[i + s.nx * (j + s.ny * k)] = cell[i / edge + cx * (j / edge + cy * (k / edge))];
}

}  // namespace

TextureVolume generate_texture(const GeneratorSpec& spec, std::vector<Phase> phases,
                               std::uint64_t seed) {
  if (spec.grains.empty()) throw Error("texture generator: no grain phase");
  double total = 0;
  for (const auto& g : spec.grains) {
    if (g.phase == 0 || g.phase >= phases.size())
      throw Error("texture generator: grain phase must be 1.." + std::to_string(phases.size() - 1));
    if (!(g.volume_fraction > 0)) throw Error("texture generator: volume_fraction must be > 0");
    if (!(g.grain_radius > 0)) throw Error("texture generator: grain_radius must be > 0");
    total += g.volume_fraction;
  }
  if (!(total < 1)) throw Error("texture generator: grain volume fractions must sum below 1");
  Rng rng(seed, generator_stream);
  std::vector<std::uint8_t> labels(spec.nx * spec.ny * spec.nz, 0);
  if (spec.model == TextureModel::lattice) {
    lattice(spec, spec.grains, labels, rng);
  } else {
    double left = 1;
    for (const auto& g : spec.grains) {
      boolean_spheres(spec, g, left, labels, rng);
      left -= g.volume_fraction;
    }
  }
  return TextureVolume(spec.nx, spec.ny, spec.nz, spec.voxel_size, std::move(labels),
                       std::move(phases));
}

}  // namespace comminute::breakage::texture
