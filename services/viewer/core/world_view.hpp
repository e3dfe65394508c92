#pragma once
// What the viewer knows of the world: the latest sample of every robot, door, goal, itinerary,
// radio link and courier job, plus what the samples alone do not keep (each robot's recent
// trajectory, each job's state history). Pure: no DDS, no sockets; the node feeds it samples and
// asks for frames (frames.hpp) when it is time to push one to the pages.
#include "common/msg/courier.hpp"
#include "common/msg/navigation.hpp"
#include "common/msg/radio.hpp"
#include "common/msg/robot.hpp"
#include "common/msg/simulation.hpp"
#include "common/msg/truth.hpp"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace autonomy::viewer {

struct WorldViewLimits {
  std::size_t trail_points = 80;      // positions kept per robot (the tail drawn behind it)
  double trail_spacing_m = 0.05;      // a new tail point once the robot moved this far
  std::size_t job_history = 32;       // state changes kept per courier job (its Gantt row)
  std::size_t max_jobs = 500;         // jobs kept; the oldest ended ones go first
};

struct TrailPoint {
  double x = 0.0, y = 0.0;
};

// A robot's goal as sent (position) joined with its latest status (state, reason).
struct GoalView {
  std::string goal_id;
  bool has_position = false;  // the NavGoal was heard (a late joiner may only hear the status)
  double x = 0.0, y = 0.0;
  bool has_status = false;
  msg::GoalState state = msg::GoalState::Accepted;
  std::string reason;
  double distance_to_goal = 0.0;
};

struct RobotView {
  bool has_state = false;  // false: only its goal or itinerary was heard so far
  msg::RobotState state;
  std::deque<TrailPoint> trail;  // oldest first; the last point is near the current position
  std::optional<GoalView> goal;
  std::optional<msg::Itinerary> itinerary;
};

struct JobStateChange {
  msg::JobState state = msg::JobState::Queued;
  std::string phase;
  int64_t tick = 0;
};

struct JobView {
  msg::CourierJobStatus latest;
  std::vector<JobStateChange> history;  // one entry per state or phase change, oldest first
  uint64_t first_seen = 0;              // order of arrival, for a stable listing
};

class WorldView {
 public:
  explicit WorldView(WorldViewLimits limits = {}) : limits_(limits) {}

  void apply(const msg::WorldMap& map);
  void apply(const msg::RobotState& state);
  void remove_robot(const std::string& robot_id);  // its state instance was disposed or lost
  void apply(const msg::DoorState& door);
  void apply(const msg::NavGoal& goal);
  void apply(const msg::GoalStatus& status);
  void apply(const msg::Itinerary& itinerary);
  void apply(const msg::RadioLink& link);
  void apply(const msg::CourierJobStatus& job);

  // Bumped by every change of the map / of anything else: the node sends a frame when it moved.
  uint64_t map_version() const { return map_version_; }
  uint64_t state_version() const { return state_version_; }

  const std::optional<msg::WorldMap>& map() const { return map_; }
  const std::map<std::string, RobotView>& robots() const { return robots_; }
  const std::map<std::string, msg::DoorState>& doors() const { return doors_; }
  const std::map<std::pair<std::string, std::string>, msg::RadioLink>& links() const { return links_; }
  const std::map<std::string, JobView>& jobs() const { return jobs_; }
  // The newest simulated time heard in a robot state, ns.
  int64_t sim_time_ns() const { return sim_time_ns_; }
  int64_t tick() const { return tick_; }
  const WorldViewLimits& limits() const { return limits_; }

 private:
  RobotView& robot(const std::string& robot_id);
  void forget_oldest_ended_job();

  WorldViewLimits limits_;
  std::optional<msg::WorldMap> map_;
  std::map<std::string, RobotView> robots_;
  std::map<std::string, msg::DoorState> doors_;
  std::map<std::pair<std::string, std::string>, msg::RadioLink> links_;
  std::map<std::string, JobView> jobs_;
  uint64_t jobs_seen_ = 0;
  int64_t sim_time_ns_ = 0;
  int64_t tick_ = 0;
  uint64_t map_version_ = 0;
  uint64_t state_version_ = 0;
};

}  // namespace autonomy::viewer
