#pragma once
// Random numbers. Every random choice in a run flows from the case file's one seed: each
// consumer takes its own stream, Rng(seed, stream_id), so adding a consumer does not shift the
// numbers of the others. A consumer that draws for many items (the breakage of each parent) takes
// one stream per item, Rng(seed, stream_id, key) with the item's key (the parent's particle id,
// unique within a run): the item's numbers then depend on the seed, the stream and the key only,
// not on the order in which the items are worked through, the thread count or a restart, and
// nothing is carried from item to item. xoshiro256** (Blackman & Vigna 2018) seeded through
// splitmix64; the state is four integers, so checkpoints store it exactly. Distributions are
// computed here, not with <random>'s, whose algorithms differ between standard libraries.
#include <array>
#include <cstdint>

namespace comminute {

class Rng {
 public:
  using State = std::array<std::uint64_t, 4>;

  explicit Rng(std::uint64_t seed = 1, std::uint64_t stream = 0);
  // The stream of item `key`: Rng(seed ^ h(key), stream), h the splitmix64 output function
  // (Steele, Lea & Flood, OOPSLA 2014), which spreads consecutive keys over all 64 bits.
  Rng(std::uint64_t seed, std::uint64_t stream, std::uint64_t key);

  std::uint64_t next_u64();
  // Uniform on (0, 1): never exactly 0 or 1 (53 random bits, offset by half an ulp).
  double uniform();
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Standard normal by inversion of the normal CDF (one uniform per draw, reproducible).
  double normal();
  double normal(double mean, double sd) { return mean + sd * normal(); }
  // Integer uniform in [0, n).
  std::uint64_t below(std::uint64_t n);

  const State& state() const { return s_; }
  void set_state(const State& s) { s_ = s; }

 private:
  State s_{};
};

// Stream identifiers of the engine's consumers (documented so that runs stay comparable).
namespace rng_stream {
inline constexpr std::uint64_t insertion = 1;
// breakage: the strengths of the particles the run starts with or inserts (one stream, slot order);
// a broken parent's progeny sizes, then its fragments' strengths, from Rng(seed, breakage, id)
inline constexpr std::uint64_t breakage = 2;
inline constexpr std::uint64_t placement = 3;  // a parent's fragments: Rng(seed, placement, id)
inline constexpr std::uint64_t texture = 4;
inline constexpr std::uint64_t calibration = 5;
inline constexpr std::uint64_t pbm = 6;
inline constexpr std::uint64_t bonds = 7;     // bond strength scatter
inline constexpr std::uint64_t clusters = 8;  // grain packings and placement (+ 16 per [[insert]])
inline constexpr std::uint64_t grain_pour = 9;  // poured grains' places, orientations (+ 16 per)
}  // namespace rng_stream

}  // namespace comminute
