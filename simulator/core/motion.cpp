#include "simulator/core/motion.hpp"

#include <cmath>

namespace autonomy::sim {

geometry::Pose2 advance(const geometry::Pose2& start, Kinematics kinematics, const Velocity& v,
                        double t) {
  const double turn = v.omega * t;
  geometry::Pose2 end = start;
  end.theta = geometry::wrap_angle(start.theta + turn);
  if (kinematics == Kinematics::Holonomic) {
    end.x += v.vx * t;
    end.y += v.vy * t;
    return end;
  }
  // Unicycle: below this turn the arc formula loses precision (division by a tiny omega) and
  // the chord of a straight line is exact to far below a nanometre.
  constexpr double kStraightTurn = 1e-9;
  if (std::abs(turn) < kStraightTurn) {
    end.x += v.vx * t * std::cos(start.theta);
    end.y += v.vx * t * std::sin(start.theta);
  } else {
    const double r = v.vx / v.omega;
    end.x += r * (std::sin(start.theta + turn) - std::sin(start.theta));
    end.y += -r * (std::cos(start.theta + turn) - std::cos(start.theta));
  }
  return end;
}

double path_length(Kinematics kinematics, const Velocity& v, double t) {
  const double speed = kinematics == Kinematics::Holonomic ? std::hypot(v.vx, v.vy) : std::abs(v.vx);
  return speed * std::abs(t);
}

}  // namespace autonomy::sim
