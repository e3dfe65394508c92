#pragma once
// The simulated world: a rectangular room with rectangular obstacles and disc-shaped robots
// that follow velocity commands. Pure and deterministic: time advances only through step(),
// robots are processed in id order, and nothing here reads clocks, files or random devices.
//
// Safety rules it enforces, whoever the controller is:
// - a command is checked against the robot's limits and rejected whole when it breaks one;
// - a held command expires after command_timeout_s of simulated time, then the robot stops;
// - a robot never ends a step overlapping an obstacle, the world boundary or another robot.
#include "simulator/core/motion.hpp"
#include "simulator/core/robot_status.hpp"
#include "simulator/core/spawn_result.hpp"
#include "simulator/core/velocity_command.hpp"
#include "simulator/core/world_spec.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::sim {

class World {
 public:
  // Spawns spec.robots_at_start. Throws std::invalid_argument when the spec itself is unusable
  // (non-positive size or command timeout, a start robot that cannot be placed): the scenario
  // loader reports those with file positions before a World is ever built.
  explicit World(WorldSpec spec);

  // Puts robot `id` into the world at `pose`, or at its configured start pose when no pose is
  // given. An id that is not configured gets spec().attach_defaults as body and limits.
  // Re-spawning a present robot without a pose is accepted as a re-attach (already_present).
  SpawnResult spawn(const std::string& id, std::optional<geometry::Pose2> pose = std::nullopt);

  // Checks `command` and, if it is valid, makes it the robot's held command from now on.
  CommandResult submit(const VelocityCommand& command);

  // Advances simulated time by dt > 0 seconds, moving every robot by its held command.
  void step(double dt);

  // Takes a robot out of the world; false when it was not there.
  bool remove(const std::string& id);

  std::vector<RobotStatus> robots() const;  // sorted by id
  std::optional<RobotStatus> robot(const std::string& id) const;
  double time_s() const { return time_s_; }
  const WorldSpec& spec() const { return spec_; }

 private:
  struct Robot {
    RobotStatus status;
    Velocity held;              // the last accepted command
    double held_until_s = 0.0;  // simulated time the held command expires
  };

  // The configuration for `id`: a start robot, a known robot, or nothing.
  const RobotSpec* configured(const std::string& id) const;
  // Why a disc of `radius` at `center` cannot be there (ignoring robot `self`), if it cannot.
  std::optional<std::string> placement_problem(const std::string& self,
                                               const geometry::Vec2& center,
                                               double radius) const;
  bool is_free(const std::string& self, const geometry::Vec2& center, double radius) const;
  void move(Robot& robot, double dt);

  WorldSpec spec_;
  std::map<std::string, Robot> robots_;  // ordered: id order is the processing order
  double time_s_ = 0.0;
};

}  // namespace autonomy::sim
