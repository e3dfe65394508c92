#pragma once
// Simulated range readings: N rays from a pose against the static obstacles (ObstacleMap, which
// walks a uniform grid or a raster per ray, so the cost does not grow with the number of
// obstacles), door leaves and other robots' discs. One work method, scan(); the sensor itself
// holds only the ray directions, so one instance serves any number of robots.
#include "common/geometry/geometry.hpp"
#include "simulator/core/door.hpp"
#include "simulator/core/obstacle_map.hpp"
#include "simulator/core/random.hpp"
#include "simulator/core/sensor_spec.hpp"

#include <vector>

namespace autonomy::sim {

struct Disc {
  geometry::Vec2 center;
  double radius = 0.0;
};

// One sweep, laid out like ROS's sensor_msgs/LaserScan: ray i points at
// angle_min + i * angle_increment relative to the robot's heading (counter-clockwise).
struct RangeScan {
  double angle_min = 0.0;
  double angle_increment = 0.0;
  double max_range_m = 0.0;
  std::vector<float> ranges;  // m; == max_range_m where nothing was within range
};

// What the rays can meet besides the static map. Built per tick by the World.
struct DynamicObstacles {
  std::vector<DoorLeaf> leaves;
  std::vector<Disc> robots;  // the sensing robot itself excluded
};

class RangeSensor {
 public:
  // spec.rays >= 1, spec.max_range_m > 0 (the caller checks; asserted).
  explicit RangeSensor(const RangeSensorSpec& spec);

  // `noise` may be null (then readings are exact) and is only drawn from for rays that hit.
  RangeScan scan(const geometry::Pose2& pose, const ObstacleMap& map, const DynamicObstacles& dynamic,
                 Rng* noise) const;

  const RangeSensorSpec& spec() const { return spec_; }

 private:
  RangeSensorSpec spec_;
  double angle_min_ = 0.0;
  double angle_increment_ = 0.0;
  std::vector<geometry::Vec2> directions_;  // unit vectors in the robot frame
};

}  // namespace autonomy::sim
