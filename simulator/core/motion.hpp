#pragma once
// Kinematic integration of a constant velocity over a time span, exact for both models (a
// unicycle with constant vx and omega drives a circular arc), so the result does not depend on
// the step size.
#include "common/geometry/geometry.hpp"
#include "simulator/core/kinematics.hpp"

namespace autonomy::sim {

struct Velocity {
  double vx = 0.0;
  double vy = 0.0;
  double omega = 0.0;
};

// Pose after moving with `v` for `t` seconds from `start`; theta wrapped to (-pi, pi].
geometry::Pose2 advance(const geometry::Pose2& start, Kinematics kinematics, const Velocity& v,
                        double t);

// Length of the path driven with `v` over `t` seconds (the arc length for a unicycle).
double path_length(Kinematics kinematics, const Velocity& v, double t);

}  // namespace autonomy::sim
