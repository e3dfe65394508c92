#pragma once
// The behavior controller's thin DDS shell for one robot. It attaches the robot (spawn request)
// and on every tick of the simulator's clock turns what it knows into one velocity command, then
// acknowledges the tick. Runs on the service's event-loop thread. Two modes:
//
//  - Goal mode (default): goals from autonomy/nav/goal, cancels from autonomy/nav/cancel, through
//    GoalTracker and GoToController; every transition on autonomy/nav/goal_status. A goal's
//    constraint_set selects the plan layers to honour: layers come from --layers (a mission
//    file's `layers`) and from --plans (stored plans). A stored plan is used when its goal,
//    constraint set, grid and inflation match; otherwise the field is computed. An unknown
//    constraint set rejects the goal, naming it.
//    Go-to paths (GoToPathOptions, --path-planner): the grid field's controller (default), or a
//    path planned by OMPL in SE(2) on the robot's grid (doors believed closed included) and
//    followed by the tracking schema (pure pursuit with avoid-obstacles on the range scan);
//    replanned when the doors known closed change or the robot strays; no path within the
//    budget ends the goal Blocked with the planner's reason.
//  - Mission mode (--mission): MissionExecutor::step on a Perception filled each tick from the
//    robot's state (or autonomy/robot/pose_estimate when published), range rays from
//    autonomy/robot/range_scan (empty when none), teammates' contact from autonomy/radio/link
//    (else from team inbox freshness, else all in contact) and the sim clock; mission events go to
//    the log and autonomy/mission/status. Goals and cancels are ignored (with a warning).
//
// With a journal (BehaviorNodeOptions::journal_path, behavior --journal): goal mode journals each
// goal as it arrives and each status before publishing it; mission mode journals its progress
// and events after each step that changed something, before publishing them and commanding. A
// behavior started again with the same journal drives on the goal it was pursuing (published
// Active again, its reason saying it was resumed after a restart; older goals still open are
// Preempted by it; a goal that had ended is published again as it ended and not driven), and
// continues the mission in the state it had reached (event "resumed"), not from its start.
#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"
#include "common/service/lockstep_client.hpp"
#include "common/service/service.hpp"
#include "services/behavior/core/constraint_sets.hpp"
#include "services/behavior/core/go_to_controller.hpp"
#include "services/behavior/core/goal_tracker.hpp"
#include "services/behavior/core/door_knowledge.hpp"
#include "services/behavior/core/mission/contact_judge.hpp"
#include "services/behavior/core/mission/mission_executor.hpp"
#include "services/behavior/core/path/ompl_path_planner.hpp"
#include "services/behavior/core/path/path_follower.hpp"
#include "services/behavior/core/plan_resource.hpp"
#include "services/behavior/core/traffic/traffic_rule.hpp"
#include "services/behavior/journal/behavior_journal.hpp"

#include <chrono>
#include <map>
#include <set>
#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace autonomy::behavior {

enum class GoToPlanner {
  GridField,  // GoToController on the goal's cost-to-go field
  Ompl,       // OmplPathPlanner's path, followed by PathFollower
};

struct GoToPathOptions {
  GoToPlanner planner = GoToPlanner::GridField;
  OmplPlannerSettings ompl;
  double budget_s = 0.05;         // > 0: planning time per (re)plan
  PathFollowerConfig follower;
  double replan_interval_s = 1.0;  // a robot that strayed replans at most this often
  // A unicycle's paths start with a turn in place (OmplPlannerSettings::turn_in_place_at_start);
  // holonomic robots and robots of other kinds ignore it.
  bool unicycle_turns_in_place = true;
};

struct BehaviorNodeOptions {
  std::string robot_id;
  std::optional<geometry::Pose2> start;  // spawn pose; unset: the scenario's configured start
  std::optional<msg::NavGoal> initial_goal;  // pursued as soon as the robot is ready
  double grid_resolution_m = 0.1;
  GoalTrackerConfig tracker;
  GoToConfig go_to;
  ConstraintLayers layers;               // known constraint layers (--layers, the mission's)
  std::optional<PlanResource> plans;     // --plans
  std::optional<MissionSpec> mission;    // --mission: mission mode
  double contact_freshness_s = 5.0;      // team inbox: a teammate heard within this is in contact
  ContactJudgeSettings contact;          // how long a link must stay down (up) to lose (regain) contact
  DoorKnowledgeSettings doors;           // goal mode: doors seen closed are planned around
  GoToPathOptions path;                  // goal mode: how go-to paths are planned and followed
  std::string journal_path;              // "": no journal (nothing survives the process)
  // Goal mode: fleet traffic (docs/traffic.md): itineraries, reservations of narrow passages,
  // robots that hold nothing planned around. Off: this robot ignores the others (and publishes
  // no itinerary), as before issue 25.
  bool traffic = true;
  traffic::TrafficSettings traffic_rule;
};

class BehaviorNode {
 public:
  BehaviorNode(service::Service& service, BehaviorNodeOptions options);

 private:
  void request_spawn();
  void on_spawn_replies(std::vector<dds::Sample<msg::SpawnReply>> samples);
  // Takes the robot states waiting in their reader (they do not wake the loop: see the constructor).
  void take_states();
  void on_map(std::vector<dds::Sample<msg::WorldMap>> samples);
  void on_goals(std::vector<dds::Sample<msg::NavGoal>> samples);
  void on_cancels(std::vector<dds::Sample<msg::NavCancel>> samples);
  void on_tick(const msg::SimClock& clock);
  void become_ready_when_possible();
  void accept_goal(const msg::NavGoal& goal);
  // Goal mode, once ready: the goals journalled by an earlier run of this process (goal_mode.cpp).
  // Returns whether the journal had any.
  bool resume_journalled_goals();
  // Publishes (and journals) a transition of a goal the tracker no longer holds.
  void publish_outside_tracker(const std::string& goal_id, GoalState state, const std::string& reason);
  // Publishes a set_goal report; remembers the constraint set when the goal was taken on.
  void pursue(const msg::NavGoal& goal, const ConstraintSet& set, const GoalReport& report);
  // The field towards `target` honouring `constraint_set` on what the robot knows now (closed
  // doors included); sets *error and returns nullopt for an unknown constraint layer.
  std::optional<CostToGoField> field_for(const geometry::Vec2& target, const ConstraintSet& set, std::string* error) const;
  // Goal mode, once per tick: folds this tick's door sightings in; when the set of closed doors
  // changed, later goals plan on the new grid and the pursued goal is replanned (or blocked).
  void update_door_knowledge(double now_s);
  // Computes and sends the command for pending_tick_ once the state of that tick is here.
  void control_pending_tick();
  uint32_t control_goal(int64_t tick);
  // Planned paths (GoToPlanner::Ompl), goal_path.cpp. plan_path() plans the pursued goal from
  // the robot's pose now; no path within the budget blocks the goal (published). A start in the
  // inflation margin leaves path_wanted_ set: the grid controller escapes first.
  void plan_path(const char* why);
  // The command of a planned path, or nullopt when the grid controller should drive this tick.
  std::optional<VelocityCommand> follow_path(const geometry::Pose2& pose, double now_s);
  std::shared_ptr<const OccupancyGrid> path_grid(std::string* error);
  // The range rays that hit something the map does not have (map_obstacles_ filters).
  std::vector<RangeRay> range_rays() const;
  void update_map_obstacles();
  // Fleet traffic (traffic_mode.cpp, docs/traffic.md), goal mode. traffic_step() decides this
  // tick's claim and returns a command when the traffic rule drives instead of the goal (waiting
  // at a holding point, stopped), nullopt to follow the goal as usual.
  void open_traffic_topics();
  void start_traffic(double radius_m);
  std::optional<VelocityCommand> traffic_step(const geometry::Pose2& pose, double now_s);
  std::vector<traffic::OtherRobot> other_robots(double now_s) const;
  // Stands aside for `whom` (traffic/give_way.hpp): the goal waits with the reason "giving way to
  // r1" at a side point until the way is clear (bounded with the goal's other waits).
  VelocityCommand give_way(const geometry::Pose2& pose, const std::string& whom,
                           const std::vector<traffic::OtherRobot>& others, double now_s);
  // Robots that hold nothing (no itinerary, a stale one, parked) near this one become obstacles
  // of its plans; `force` adds one the traffic rule found in a passage. Replans when they changed.
  void refresh_robot_obstacles(const geometry::Vec2& me, double now_s, const std::string& force = "");
  // Waiting robots leave the planning map (before a new goal is planned: they will move; the next
  // traffic step takes them in again where a route is left beside them).
  void forget_waiting_robots();
  // The map as this robot plans on it: the doors it knows of and the robots it plans around.
  WorldMap planning_world() const;
  std::string planning_closures() const;
  void publish_itinerary(double now_s, int64_t tick);
  // The command, without its translation when it drives into a robot close ahead (traffic/brake.hpp).
  VelocityCommand brake_for_robots(const geometry::Pose2& pose, const VelocityCommand& command) const;
  uint32_t control_mission(int64_t tick);
  Perception perceive() const;
  void publish(const GoalReport& report);
  void publish_mission(const MissionEvent& event, int64_t tick);
  void send_command(const VelocityCommand& command, int64_t tick);
  bool ready() const { return tracker_.has_value() || executor_.has_value(); }
  // Goal mode, no goal, the robot stopped: nothing to do before the next goal comes, so the
  // world need not publish ticks for this robot (a quiet ack, idl/clock.idl).
  bool waiting_for_a_goal() const;

  service::Service& service_;
  BehaviorNodeOptions options_;
  std::string participant_name_;
  std::string spawn_request_id_;
  bool spawned_ = false;
  std::optional<msg::RobotState> state_;
  std::map<std::string, msg::RobotState> teammate_states_;  // last state per teammate id
  std::optional<msg::WorldMap> map_;
  WorldMap world_;                     // map_ as the planner's world (doors open)
  DoorKnowledge doors_;                // goal mode: what this robot saw of the doors
  std::map<std::string, double> door_sightings_;  // door id -> this robot's latest angle, since the last tick
  std::set<std::string> unknown_doors_;            // seen but not on the map (warned once)
  std::optional<ConstraintSet> pursued_constraints_;  // of the goal being pursued
  std::optional<GoalTracker> tracker_;
  std::optional<GoToController> controller_;
  std::optional<PathFollower> follower_;  // GoToPlanner::Ompl
  bool path_wanted_ = false;              // the pursued goal needs a (new) path
  double last_plan_s_ = -1e18;            // sim time of the last plan
  // The map's obstacles (doors believed closed included) grown by a few centimetres: range hits
  // there are the map's own, already planned around; the avoid schema sees only the others.
  std::optional<OccupancyGrid> map_obstacles_;
  // The tracker's grid as the OMPL planner holds it, copied once per grid (a copy per plan cost
  // milliseconds on the recon map): a new grid has a new raster.
  std::shared_ptr<const OccupancyGrid> path_grid_;

  // Fleet traffic (goal mode, options_.traffic).
  std::optional<traffic::TrafficRule> traffic_;
  std::map<std::string, msg::Itinerary> itineraries_;  // the others', newest per robot
  std::vector<geometry::Vec2> path_ahead_;             // this tick's path on the goal's field
  traffic::TrafficDecision traffic_decision_;          // this tick's
  struct Holding {
    std::string blocker;
    std::optional<geometry::Vec2> point;
    std::optional<CostToGoField> field;
  };
  std::optional<Holding> holding_;                     // while waiting for a passage or giving way
  struct RobotObstacle {
    enum class Kind { NoItinerary, StaleItinerary, Parked, Waiting };
    geometry::Vec2 position;
    double radius = 0.0;
    std::string why;  // "robot r2 (no itinerary for 3.0 s) at (1.00, 2.00)": written when planned around
    bool soft = false;  // a waiting robot: dropped when it leaves no route
    Kind kind = Kind::NoItinerary;
    double itinerary_age_s = 0.0;  // StaleItinerary
  };
  // "robot r2 (parked) at (1.00, 2.00) in corridor": a robot obstacle as the log and statuses name it.
  std::string describe_robot_obstacle(const std::string& id, const RobotObstacle& o) const;
  std::map<std::string, RobotObstacle> robot_obstacles_;  // planned around now
  // Waiting robots left out of the plan because they left no route, where they stood then: they
  // stay left out while they stand there (taking them in again each tick would replan each tick).
  std::map<std::string, geometry::Vec2> soft_dropped_;
  // The pursued goal's time spent waiting (for passages and giving way) in all, bounded by the
  // rule's max_wait_s: waits one after another must not keep a goal open for ever.
  std::string waited_goal_;
  double waited_s_ = 0.0;
  std::optional<double> last_traffic_step_s_;
  std::set<std::string> forced_obstacles_;                // found in a passage by the rule
  // Robots standing with nothing to drive (fresh itinerary, no path, no claim): where and since
  // when (sim time) they stand; planned around once they have stood long (traffic_mode.cpp).
  struct Standing {
    geometry::Vec2 position;
    double since_s = 0.0;
  };
  std::map<std::string, Standing> standing_;
  std::optional<double> traffic_since_s_;                 // sim time of the first traffic step
  double last_itinerary_s_ = -1e18;
  std::string last_itinerary_key_;                        // claim, passage, whom it waits for
  double robot_radius_ = 0.0;
  std::unique_ptr<dds::Topic<msg::Itinerary>> itinerary_topic_;
  std::unique_ptr<dds::Reader<msg::Itinerary>> itinerary_reader_;
  std::unique_ptr<dds::Writer<msg::Itinerary>> itinerary_writer_;

  std::unique_ptr<BehaviorJournal> journal_;
  std::vector<JournalledGoal> journalled_goals_;        // as found at start, resumed once ready
  std::optional<JournalledMission> journalled_mission_;  // as found at start, resumed at the first step
  bool reattach_first_ = false;  // restarted with a journal: ask for the robot back before spawning it at --start
  std::string resuming_goal_;  // the journalled goal queued to be taken on again at the next tick ("": none)

  std::optional<MissionExecutor> executor_;
  ContactJudge contact_;  // the mission's view of contact: link flags with hysteresis
  std::optional<msg::NavGoal> queued_goal_;  // arrived before the robot was ready
  std::optional<int64_t> pending_tick_;
  bool stopped_robot_ = true;  // the last command sent was zero (or none was sent)
  std::chrono::steady_clock::time_point last_spawn_request_;

  // Mission-mode inputs from the simulator's sensor and radio models (absent until published).
  std::optional<msg::PoseEstimate> pose_estimate_;
  std::optional<msg::RangeScan> scan_;
  std::map<std::string, bool> link_connected_;  // teammate id -> direct link connected
  // Some RadioLink sample arrived: the simulator's radio runs, and a teammate without a sample
  // has no link (the simulator writes samples only for pairs that connect, and one when they lose it).
  bool radio_links_seen_ = false;
  std::map<std::string, double> last_heard_s_;  // teammate id -> sim time of its last inbox message
  std::map<std::string, geometry::Vec2> last_known_position_;  // while in contact

  dds::Topic<msg::RobotState> state_topic_;
  dds::Topic<msg::WorldMap> map_topic_;
  dds::Topic<msg::NavGoal> goal_topic_;
  dds::Topic<msg::NavCancel> cancel_topic_;
  dds::Topic<msg::GoalStatus> goal_status_topic_;
  dds::Topic<msg::MissionStatus> mission_status_topic_;
  dds::Topic<msg::VelocityCommand> cmd_topic_;
  dds::Topic<msg::SpawnRequest> spawn_request_topic_;
  dds::Topic<msg::SpawnReply> spawn_reply_topic_;
  dds::Reader<msg::RobotState> state_reader_;
  dds::Reader<msg::WorldMap> map_reader_;
  dds::Reader<msg::NavGoal> goal_reader_;
  dds::Reader<msg::NavCancel> cancel_reader_;
  dds::Reader<msg::SpawnReply> spawn_reply_reader_;
  dds::Topic<msg::DoorObservation> door_topic_;
  dds::Reader<msg::DoorObservation> door_reader_;
  dds::Writer<msg::GoalStatus> goal_status_writer_;
  dds::Writer<msg::MissionStatus> mission_status_writer_;
  dds::Writer<msg::VelocityCommand> cmd_writer_;
  dds::Writer<msg::SpawnRequest> spawn_request_writer_;
  // Mission mode only.
  std::unique_ptr<dds::Topic<msg::PoseEstimate>> pose_topic_;
  std::unique_ptr<dds::Topic<msg::RangeScan>> scan_topic_;
  std::unique_ptr<dds::Topic<msg::RadioLink>> link_topic_;
  std::unique_ptr<dds::Topic<msg::TeamDelivery>> inbox_topic_;
  std::unique_ptr<dds::Reader<msg::PoseEstimate>> pose_reader_;
  std::unique_ptr<dds::Reader<msg::RangeScan>> scan_reader_;
  std::unique_ptr<dds::Reader<msg::RadioLink>> link_reader_;
  std::unique_ptr<dds::Reader<msg::TeamDelivery>> inbox_reader_;
  service::LockstepClient lockstep_;
};

}  // namespace autonomy::behavior
