// Deterministic Gaussian draws: a counter-based hash per (seed, index) and Box–Muller.
//
// This work is based on:
//   - Box, G. E. P. & Muller, M. E. (1958) A note on the generation of random normal deviates.
//     Ann. Math. Statist. 29(2); Aebi, VR Ocean, eq. 12.
//   - Steele, G. L., Lea, D. & Flood, C. H. (2014) Fast splittable pseudorandom number
//     generators (SplitMix64 and its finaliser). OOPSLA '14.
// Equations: docs/math.md (M.6.1).
#include <cmath>

#include "ocean/spectrum.hpp"

namespace ocean {

namespace {
std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
std::uint64_t hash(std::uint64_t seed, std::uint64_t counter) {
  return mix64(mix64(seed + 0x9e3779b97f4a7c15ULL) ^ (counter * 0xd1b54a32d192ed03ULL));
}
}  // namespace

namespace {
constexpr double kTwoPow53 = 9007199254740992.0;
}  // namespace

double uniform_draw(std::uint64_t seed, std::uint64_t index) {
  return static_cast<double>(hash(seed, index) >> 11) / kTwoPow53;
}

std::array<double, 2> gaussian_pair(std::uint64_t seed, std::uint64_t index) {
  // u1 ∈ (0, 1] so that log(u1) is finite; u2 ∈ [0, 1).
  const double u1 = static_cast<double>((hash(seed, 2 * index) >> 11) + 1) / kTwoPow53;
  const double u2 = static_cast<double>(hash(seed, 2 * index + 1) >> 11) / kTwoPow53;
  const double r = std::sqrt(-2.0 * std::log(u1));
  const double angle = 2.0 * kPi * u2;
  return {r * std::sin(angle), r * std::cos(angle)};  // Aebi, VR Ocean, eq. 12
}

}  // namespace ocean
