#pragma once
// Mineral texture of the particles as an engine module (docs/breakage.md, "Texture"). It holds
// the texture volume once (shared, never copied per particle) and the pool of per-particle
// textures (texture_pool.hpp), and keeps the per-particle fields
//   texture.owner    id of the particle whose texture this particle carries (0: none yet),
//   composition.<k>  volume fraction of phase k (the voxel fraction of the particle's texture),
// which the composition-dependent criterion and the outlets read. Every step (pre_force, after
// insertion, and end_of_step, after breakage) where particles were added or removed since its last
// look, it makes one pass over the particles and gives each particle of a textured material whose
// texture.owner is not its own id its texture:
//   texture.owner = 0            a new particle: an n^3 cube sampled from the volume at a random
//                                position and orientation (texture_sampler.hpp); with
//                                density_from_phases its mass becomes V sum_k phi_k rho_k (the
//                                change of its kinetic and potential energy is booked);
//   texture.owner = a parent id  a fragment: the fragments of one parent (those carrying the
//                                parent's id) split the parent's cube (texture_inheritance.hpp),
//                                in proportion to their final volumes; the parent's texture is
//                                then dropped from the pool. Every generation inherits.
// With density_from_phases the module is also the breakage module's FragmentMassRule: when a
// parent breaks it splits the parent's texture at once and shares the fragments' mass (their sum
// unchanged) in proportion to V_j rho_j, rho_j = sum_k phi_jk rho_k of fragment j's cube, before
// the fragments are placed and given velocities; the cubes are handed to the fragments at the
// end of the step.
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "comminute/breakage/fragment_mass_rule.hpp"
#include "comminute/breakage/texture/texture_inheritance.hpp"
#include "comminute/breakage/texture/texture_pool.hpp"
#include "comminute/breakage/texture/texture_sampler.hpp"
#include "comminute/breakage/texture/texture_volume.hpp"
#include "comminute/core/rng.hpp"
#include "comminute/engine/module.hpp"
#include "comminute/engine/sample_rows.hpp"
#include "comminute/engine/series_source.hpp"
#include "comminute/particles/particle_store.hpp"

namespace comminute::breakage::texture {

struct TextureOptions {
  // Cells per edge of a particle's cube, per material (0: the material has no texture).
  std::vector<std::size_t> resolution;
  bool density_from_phases = true;  // new particles' mass from their phases
  double output_interval = 0;       // s between rows of texture.csv (0: every 1000 steps)
};

class TextureModule final : public Module, public SeriesSource, public FragmentMassRule {
 public:
  TextureModule(std::shared_ptr<const TextureVolume> volume, TextureOptions opt,
                std::uint64_t seed);
  std::string name() const override { return "texture"; }
  // Registers texture.owner and composition.<k>. Call right after construction as well, so that
  // a checkpoint restores the fields.
  void register_fields(ParticleStore& p);
  void setup(Simulation& sim) override;
  void pre_force(Simulation& sim) override { update(sim); }
  void end_of_step(Simulation& sim) override { update(sim); }
  void save(Archive& a) const override;
  void load(const Archive& a) override;
  SeriesSource* series_source() override { return this; }
  Cadence output_cadence() const override;
  void sample(const Simulation& sim) override;
  std::vector<Table> tables(const Simulation& sim) const override;

  const TextureVolume& volume() const { return *volume_; }
  const TexturePool& pool() const { return pool_; }
  // Gives every particle that needs one its texture (what the hooks call).
  void update(Simulation& sim);
  // FragmentMassRule: splits the parent's texture now and shares the mass by V_j rho_j.
  void share(const ParticleStore& p, std::size_t parent, const std::vector<double>& radii,
             std::vector<double>& masses) override;
  bool density_from_phases() const { return opt_.density_from_phases; }

 private:
  bool textured(const ParticleStore& p, std::size_t i) const;
  void set_composition(ParticleStore& p, std::size_t i, const Cube& c) const;
  void sample_new(Simulation& sim, std::size_t i);

  std::shared_ptr<const TextureVolume> volume_;
  TextureOptions opt_;
  Rng rng_;
  TexturePool pool_;
  TextureInheritance inheritance_;
  CubeSampler sampler_;
  std::size_t owner_ = 0;
  std::vector<std::size_t> composition_;
  std::map<std::uint64_t, std::vector<Cube>> pending_;  // split at breakage, by parent id
  std::uint64_t inherited_ = 0, sampled_ = 0;  // fragments given a texture, particles sampled
  SampleRows rows_;                            // texture.csv
  // The particles as update() last saw them: the next id to be issued (0: not seen yet) and the
  // count; unchanged, no particle needs a texture and none left (update() skips its pass).
  std::uint64_t seen_next_id_ = 0;
  std::size_t seen_owned_ = 0;
  std::vector<std::uint64_t> alive_;  // ids of the textured particles (update()'s pass)
};

}  // namespace comminute::breakage::texture
