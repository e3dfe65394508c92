#pragma once
// Door observations, after RHINO's policy in the courier paper ("whenever it passes a door it
// estimates the opening angle of that door"): a door is observed when its doorway centre is within
// the sensor's range and visible from the robot (no wall, obstacle or other door leaf in between;
// the door's own leaf does not hide its doorway), and the estimate is the true opening angle plus
// Gaussian noise, clamped to [0, max_angle]. Other robots do not hide doors.
#include "common/geometry/geometry.hpp"
#include "simulator/core/door.hpp"
#include "simulator/core/obstacle_map.hpp"
#include "simulator/core/random.hpp"
#include "simulator/core/sensor_spec.hpp"

#include <string>
#include <vector>

namespace autonomy::sim {

struct DoorObservation {
  std::string door_id;
  double angle_estimate = 0.0;  // rad, 0 = closed
  double distance_m = 0.0;      // from the robot's centre to the doorway centre (exact)
  double bearing_rad = 0.0;     // of the doorway centre, relative to the robot's heading
};

// A door as the observer sees it: its geometry and its current angle.
struct DoorView {
  const DoorSpec* spec = nullptr;
  double angle = 0.0;
};

class DoorObserver {
 public:
  explicit DoorObserver(const DoorSensorSpec& spec) : spec_(spec) {}

  // Observations in the order of `doors`. `noise` may be null (exact estimates).
  std::vector<DoorObservation> observe(const geometry::Pose2& pose, const ObstacleMap& map,
                                       const std::vector<DoorView>& doors, Rng* noise) const;

 private:
  DoorSensorSpec spec_;
};

// No obstacle of `map` and no leaf of `doors` (except door index `except`, if set) lies between
// a and b. The LOS rule the World's line_of_sight and the DoorObserver share.
bool visible(const ObstacleMap& map, const std::vector<DoorView>& doors, const geometry::Vec2& a,
             const geometry::Vec2& b, std::size_t except = static_cast<std::size_t>(-1));

}  // namespace autonomy::sim
