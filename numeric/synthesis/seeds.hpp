// Seeds of the multistart and of the random search: splitmix64 (Steele, Lea, Flood 2014) of the
// user's seed and an index, so start k or chunk k is the same program on any machine and thread.
#pragma once
#include <cstdint>

namespace scalcal {

// Relative distance to the best value within which a start counts as a hit.
inline constexpr double kHitTolerance = 1e-8;

constexpr std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

constexpr std::uint64_t start_seed(std::uint64_t seed, std::uint64_t index) {
  return splitmix64(splitmix64(seed) ^ (index * 0xD1B54A32D192ED03ull));
}

// The number of workers for `requested` (0: every core).
int thread_count(int requested);

}  // namespace scalcal
