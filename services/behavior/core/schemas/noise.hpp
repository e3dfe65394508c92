#pragma once
// noise (Arkin 1989): a unit vector in a random direction, held for persistence_s before a new
// direction is drawn, so the robot wanders out of local minima instead of jittering in place.
//
// Deterministic without hidden state: time is cut into epochs of persistence_s
// (epoch = floor(time_s / persistence_s)) and each epoch's direction is drawn from a generator
// seeded with (seed, epoch). The same seed and time always give the same vote, whatever was asked
// before, so runs replay exactly and two robots given different seeds disperse differently.
// The caller supplies the seed (from the mission or scenario seed and the robot id).
#include "services/behavior/core/schemas/motor_schema.hpp"

#include <cstdint>

namespace autonomy::behavior {

struct NoiseConfig {
  double persistence_s = 2.0;  // > 0
  std::uint64_t seed = 0;
};

class Noise final : public MotorSchema {
 public:
  // Throws std::invalid_argument on a non-positive or non-finite persistence.
  explicit Noise(NoiseConfig config);

  [[nodiscard]] geometry::Vec2 vote(const Perception& p) const override;
  std::string_view name() const override { return "noise"; }

  // The direction (radians, world frame) held during `epoch`.
  double direction(std::int64_t epoch) const;

 private:
  NoiseConfig config_;
};

}  // namespace autonomy::behavior
