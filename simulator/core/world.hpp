#pragma once
// The simulated world: a rectangular area with obstacles (rectangles, polygons, occupancy
// rasters), doors that open and close, and disc-shaped robots that follow velocity commands and
// sense their surroundings. Pure and deterministic: time advances only through step(), robots
// and doors are processed in id / file order, random processes draw from streams seeded by
// spec().seed (random.hpp), and nothing here reads clocks, files or random devices.
//
// Safety rules it enforces, whoever the controller is:
// - a command is checked against the robot's limits and rejected whole when it breaks one;
// - a held command expires after command_timeout_s of simulated time, then the robot stops;
// - a robot never ends a step overlapping an obstacle, a door leaf, the world boundary or another
//   robot (it stops at the contact, it never passes through);
// - a door never swings through a robot: it waits until the robot has left the leaf's sweep.
//
// Cost: robots are kept in a uniform grid (uniform_grid.hpp), so a collision test looks at the
// robots in the cells around the disc and a range scan at those within its range: a step costs
// about robots x (robots nearby), not robots squared. use_all_pairs_reference(true) switches back
// to testing every robot (same results, for benchmarks and tests that compare the two).
//
// Sensing reads the state after the last step; each robot's noise comes from its own stream, so
// whether and how often other robots sense does not change what it sees.
#include "simulator/core/door.hpp"
#include "simulator/core/door_observer.hpp"
#include "simulator/core/motion.hpp"
#include "simulator/core/obstacle_map.hpp"
#include "simulator/core/random.hpp"
#include "simulator/core/range_sensor.hpp"
#include "simulator/core/robot_status.hpp"
#include "simulator/core/spawn_result.hpp"
#include "simulator/core/uniform_grid.hpp"
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
  // A copy has its own robot grid (the grid points at the robots of its world).
  World(const World& other);
  World& operator=(const World& other);
  World(World&&) = default;  // std::map keeps its nodes: the grid's pointers stay valid
  World& operator=(World&&) = default;

  // Puts robot `id` into the world at `pose`, or at its configured start pose when no pose is
  // given. An id that is not configured gets spec().attach_defaults as body and limits.
  // Re-spawning a present robot without a pose is accepted as a re-attach (already_present).
  SpawnResult spawn(const std::string& id, std::optional<geometry::Pose2> pose = std::nullopt);

  // Checks `command` and, if it is valid, makes it the robot's held command from now on.
  CommandResult submit(const VelocityCommand& command);

  // Advances simulated time by dt > 0 seconds, moving every robot by its held command, then
  // advancing every door's schedule to the new time and moving the leaves that can move.
  void step(double dt);

  // Takes a robot out of the world; false when it was not there.
  bool remove(const std::string& id);

  std::vector<RobotStatus> robots() const;  // sorted by id
  std::optional<RobotStatus> robot(const std::string& id) const;
  double time_s() const { return time_s_; }
  const WorldSpec& spec() const { return spec_; }
  // Body, limits and sensors of a present robot.
  std::optional<RobotSpec> robot_spec(const std::string& id) const;

  // --- Doors ---------------------------------------------------------------------------------
  std::vector<DoorStatus> doors() const;  // in spec().doors order
  std::optional<DoorStatus> door(const std::string& id) const;
  // Asks door `id` to take `angle` (0 = closed .. its max_angle) now, or as soon as no robot is
  // in the way. Its schedule's later events still apply. Rejects unknown ids and bad angles.
  CommandResult set_door(const std::string& id, double angle);

  // --- Sensing -------------------------------------------------------------------------------
  // Nothing between a and b blocks sight: no obstacle and no door leaf (robots do not block).
  bool line_of_sight(const geometry::Vec2& a, const geometry::Vec2& b) const;
  // A range scan of robot `id` with its configured sensor, or with `sensor`; nothing when the
  // robot is absent or (configured case) has no range sensor. Rays meet obstacles, the world
  // boundary, door leaves and other robots.
  std::optional<RangeScan> sense(const std::string& id);
  std::optional<RangeScan> sense(const std::string& id, const RangeSensorSpec& sensor);
  // The doors robot `id` sees now (door_observer.hpp), with its configured or the given sensor.
  std::vector<DoorObservation> observe_doors(const std::string& id);
  std::vector<DoorObservation> observe_doors(const std::string& id, const DoorSensorSpec& sensor);
  // The robot's pose as its localisation reports it (true pose plus configured noise).
  std::optional<geometry::Pose2> observe_pose(const std::string& id);

  const ObstacleMap& obstacle_map() const { return map_; }

  // true: collisions and scans test every robot (the reference the grid must agree with).
  void use_all_pairs_reference(bool all_pairs) { all_pairs_ = all_pairs; }

 private:
  struct Robot {
    RobotStatus status;
    Velocity held;              // the last accepted command
    double held_until_s = 0.0;  // simulated time the held command expires
    RobotSpec body;             // as configured (or attach_defaults), id set
    Rng noise;                  // this robot's sensor noise stream
    std::optional<RangeSensor> range;  // from body.sensors.range, when configured
  };
  struct Door {
    double angle = 0.0;
    double target = 0.0;
    DoorLeaf leaf;
    DoorSchedule schedule;
  };

  // The configuration for `id`: a start robot, a known robot, or nothing.
  const RobotSpec* configured(const std::string& id) const;
  // Why a disc of `radius` at `center` cannot be there (ignoring robot `self`), if it cannot.
  std::optional<std::string> placement_problem(const std::string& self,
                                               const geometry::Vec2& center,
                                               double radius) const;
  bool is_free(const std::string& self, const geometry::Vec2& center, double radius) const;
  void move(Robot& robot, double dt);
  // Moves door i to its target unless a robot is in the sweep.
  void try_move_door(std::size_t i);
  std::vector<DoorView> door_views() const;
  void rebuild_robot_grid();
  // Door leaves and the robots (except `except_robot`) whose disc may lie within `reach` of
  // `center`; the all-pairs reference lists every robot.
  DynamicObstacles dynamic_obstacles(const std::string& except_robot, const geometry::Vec2& center,
                                     double reach) const;

  WorldSpec spec_;
  ObstacleMap map_;
  std::vector<Door> doors_;  // parallel to spec_.doors
  std::map<std::string, Robot> robots_;  // ordered: id order is the processing order
  UniformGrid<const Robot*> robot_grid_;  // every robot of robots_, by its current position
  double max_robot_radius_ = 0.0;         // of every robot ever spawned (bounds grid queries)
  bool all_pairs_ = false;
  double time_s_ = 0.0;
};

}  // namespace autonomy::sim
