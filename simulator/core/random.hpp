#pragma once
// Seeded random numbers for the simulator's noise and random processes, the same on every
// platform and standard library: only 64-bit integer arithmetic and <cmath>, no
// std::*_distribution (whose algorithms the standard leaves to the implementation).
//
// Streams are derived, not shared: each consumer (a door's random schedule, a robot's sensor
// noise) gets its own Rng from the run's seed and a stable name, so adding a robot or a door
// does not change the numbers any other one draws.
#include <cmath>
#include <cstdint>
#include <string_view>

namespace autonomy::sim {

// SplitMix64 (Steele, Lea, Flood 2014): a good 64-bit mixer, used to seed and to derive streams.
constexpr std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// FNV-1a of a name, to derive a stream from (seed, name).
constexpr std::uint64_t name_hash(std::string_view name) {
  std::uint64_t h = 0xCBF29CE484222325ull;
  for (const char c : name) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001B3ull;
  }
  return h;
}

// xoshiro256** (Blackman, Vigna 2018).
class Rng {
 public:
  explicit Rng(std::uint64_t seed = 0) {
    std::uint64_t x = seed;
    for (std::uint64_t& word : s_) {
      x = splitmix64(x);
      word = x;
    }
  }
  // The stream called `name` of the run seeded with `seed`.
  static Rng stream(std::uint64_t seed, std::string_view name) {
    return Rng(splitmix64(seed) ^ name_hash(name));
  }

  std::uint64_t next() {
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

  // Uniform in [0, 1), 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  // Standard normal by the Box-Muller transform (one value per call; the pair's twin is kept).
  double normal() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = 1.0 - uniform();  // (0, 1]: log is finite
    const double u2 = uniform();
    const double radius = std::sqrt(-2.0 * std::log(u1));
    const double angle = 2.0 * M_PI * u2;
    spare_ = radius * std::sin(angle);
    has_spare_ = true;
    return radius * std::cos(angle);
  }
  double normal(double mean, double stddev) { return stddev > 0.0 ? mean + stddev * normal() : mean; }

  // Exponentially distributed waiting time with `rate` > 0 events per unit.
  double exponential(double rate) { return -std::log(1.0 - uniform()) / rate; }

 private:
  static constexpr std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t s_[4] = {};
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace autonomy::sim
