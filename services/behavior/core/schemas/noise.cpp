#include "services/behavior/core/schemas/noise.hpp"

#include <cmath>
#include <random>
#include <stdexcept>

namespace autonomy::behavior {

namespace {

// SplitMix64 (Steele, Lea, Flood, "Fast splittable pseudorandom number generators", 2014): mixes
// (seed, epoch) into a well-spread 64-bit seed, so neighbouring epochs get unrelated directions.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

}  // namespace

Noise::Noise(NoiseConfig config) : config_(config) {
  if (!(std::isfinite(config.persistence_s) && config.persistence_s > 0.0)) {
    throw std::invalid_argument("noise: persistence must be positive and finite");
  }
}

double Noise::direction(std::int64_t epoch) const {
  std::mt19937_64 generator(mix(config_.seed ^ mix(static_cast<std::uint64_t>(epoch))));
  // Not std::uniform_real_distribution: its output may differ between standard libraries.
  const double unit = static_cast<double>(generator() >> 11) * 0x1.0p-53;  // [0, 1)
  return 2.0 * M_PI * unit;
}

geometry::Vec2 Noise::vote(const Perception& p) const {
  if (!std::isfinite(p.time_s)) return geometry::Vec2::Zero();
  const auto epoch = static_cast<std::int64_t>(std::floor(p.time_s / config_.persistence_s));
  const double a = direction(epoch);
  return {std::cos(a), std::sin(a)};
}

}  // namespace autonomy::behavior
