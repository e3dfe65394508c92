#pragma once
// What a robot senses, as configured per robot (RobotSpec::sensors). A sensor with zero range or
// zero rays is absent. Noise is Gaussian with the given standard deviation, drawn from the
// robot's own seeded stream (see random.hpp), so runs with the same seed see the same noise.
#include <cmath>

namespace autonomy::sim {

// A planar range finder (laser or a sonar ring) at the robot's centre: `rays` rays spread over
// `fov_rad` around the heading. Ranges are measured from the robot's centre.
struct RangeSensorSpec {
  int rays = 0;                  // 0: no range sensor
  double fov_rad = 2.0 * M_PI;   // (0, 2 pi]; 2 pi: rays all around, none duplicated
  double max_range_m = 10.0;     // > 0; a ray that meets nothing reports exactly this
  double noise_stddev_m = 0.0;   // >= 0; added to hits only, result clamped to [0, max_range)
};

// Door-state estimation as RHINO did it while passing doors: a door whose doorway centre is
// within range and in line of sight is observed with its opening angle plus noise.
struct DoorSensorSpec {
  double range_m = 0.0;            // 0: no door observations
  double angle_noise_rad = 0.0;    // >= 0; the estimate is clamped to [0, the door's max_angle]
};

// The robot's own pose as its localisation reports it.
struct PoseSensorSpec {
  double position_noise_m = 0.0;   // >= 0, per axis
  double heading_noise_rad = 0.0;  // >= 0
};

struct SensorSpec {
  RangeSensorSpec range;
  DoorSensorSpec doors;
  PoseSensorSpec pose;
};

}  // namespace autonomy::sim
