#pragma once
// The tracking schema of a planned go-to: follows a path (OMPL's, or any PathPlanner's) with pure
// pursuit, keeps the progress along it between ticks, and says when the robot strayed from it so
// that the caller replans. The obstacle-avoidance schema stays on beside it: what the robot's range
// rays see closer than the avoid schema's sphere of influence (another robot, a person, anything
// the map does not have) bends and slows the pursuit's command. Commands never exceed the limits
// and a unicycle never reverses (the avoid vote can stop it, not back it up).
//
// Cusps (a Reeds-Shepp path's switches between forward and reverse) split the path into legs,
// followed one after the other: the robot reaches each cusp before it takes the next leg, so the
// look-ahead never jumps across a cusp to the leg that doubles back. A unicycle drives a reverse
// leg forward, turning in place first (pure pursuit is forward-only).
//
// Pure and deterministic: the same path, pose and rays always give the same command.
#include "services/behavior/core/path/pure_pursuit.hpp"
#include "services/behavior/core/schemas/avoid_obstacles.hpp"

#include <cstddef>
#include <vector>

namespace autonomy::behavior {

struct PathFollowerConfig {
  // A short look-ahead: pure pursuit cuts corners by about the look-ahead's sagitta, and a planned
  // path keeps only one grid cell (0.1 m) more than the robot's radius from a door frame.
  PursuitSettings pursuit{0.35, 0.1, 0.8, 2.0, 40};
  double stray_distance_m = 0.5;  // > 0: farther than this from the path's closest pose -> Strayed
  // Weight of the avoid vote (magnitude 1 = full strength) in units of max speed, >= 0; 0 turns
  // the avoid schema off.
  double avoid_gain = 0.4;
  // Near the walls the path runs along: a small sphere, so that a doorway does not push the robot
  // off its path (the planner kept the path clear of the map already).
  AvoidObstaclesConfig avoid{0.9, 0.35, 2.0, 1.0};
};

enum class FollowOutcome {
  Following,  // moving along the path
  Arrived,    // at the path's end: zero command
  Strayed,    // farther than stray_distance_m from the path: replan (the command still follows it)
  NoPath,     // nothing to follow: zero command
};
const char* to_string(FollowOutcome o);

struct FollowStep {
  VelocityCommand command;
  FollowOutcome outcome = FollowOutcome::NoPath;
  double off_path_m = 0.0;   // distance to the closest path pose
  std::size_t progress = 0;  // index of that pose in the leg being followed
};

// The path cut at its cusps (where the motion turns back on itself); each leg keeps its end
// pose, which is the next leg's first.
std::vector<std::vector<geometry::Pose2>> split_at_cusps(const std::vector<geometry::Pose2>& path);

class PathFollower {
 public:
  // Throws std::invalid_argument on non-positive or non-finite limits or settings.
  PathFollower(Kinematics kinematics, MotionLimits limits, PathFollowerConfig config = {});

  // Follows `path` from its start (progress 0); an empty path is NoPath.
  void follow(std::vector<geometry::Pose2> path);
  void clear() { follow({}); }
  bool has_path() const { return !path_.empty(); }
  // Legs between cusps (1 for a path without one) and the one being followed.
  std::size_t leg_count() const { return legs_.size(); }
  std::size_t leg() const { return leg_; }
  const std::vector<geometry::Pose2>& path() const { return path_; }
  // Arrival radius at the path's end (the goal's tolerance may be tighter than the default).
  void set_goal_tolerance(double metres);

  // One control step: the robot's pose and what its range rays see now (may be empty).
  [[nodiscard]] FollowStep step(const geometry::Pose2& pose, const std::vector<RangeRay>& rays);

  Kinematics kinematics() const { return kinematics_; }
  const MotionLimits& limits() const { return limits_; }
  const PathFollowerConfig& config() const { return config_; }

 private:
  VelocityCommand with_avoidance(const VelocityCommand& pursuit, const geometry::Pose2& pose,
                                 const std::vector<RangeRay>& rays) const;

  Kinematics kinematics_;
  MotionLimits limits_;
  PathFollowerConfig config_;
  AvoidObstacles avoid_;
  std::vector<geometry::Pose2> path_;
  std::vector<std::vector<geometry::Pose2>> legs_;
  std::size_t leg_ = 0;
  std::size_t progress_ = 0;  // along legs_[leg_]
};

}  // namespace autonomy::behavior
