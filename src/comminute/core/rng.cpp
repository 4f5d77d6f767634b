#include "comminute/core/rng.hpp"

#include <boost/math/special_functions/erf.hpp>
#include <cmath>

#include "comminute/core/math_policy.hpp"

namespace comminute {

namespace {
std::uint64_t splitmix64(std::uint64_t& x) {
  std::uint64_t z = (x += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}
std::uint64_t rotl(std::uint64_t x, int k) {
  return (x << k) | (x >> (64 - k));
}
}  // namespace

Rng::Rng(std::uint64_t seed, std::uint64_t stream) {
  std::uint64_t x = seed ^ (0xD1B54A32D192ED03ull * (stream + 1));
  for (auto& w : s_) w = splitmix64(x);
}

Rng::Rng(std::uint64_t seed, std::uint64_t stream, std::uint64_t key)
    : Rng(seed ^ splitmix64(key), stream) {}

std::uint64_t Rng::next_u64() {
  const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
  const std::uint64_t t = s_[1] << 17;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = rotl(s_[3], 45);
  return result;
}

double Rng::uniform() {
  return (static_cast<double>(next_u64() >> 11) + 0.5) * 0x1.0p-53;
}

double Rng::normal() {
  // Phi^-1(u) = -sqrt(2) erfc^-1(2u)
  return -std::sqrt(2.0) * boost::math::erfc_inv(2.0 * uniform(), DoublePrecision());
}

std::uint64_t Rng::below(std::uint64_t n) {
  // Rejection of the short last block makes the modulo unbiased.
  const std::uint64_t threshold = (0 - n) % n;
  while (true) {
    const std::uint64_t r = next_u64();
    if (r >= threshold) return r % n;
  }
}

}  // namespace comminute
