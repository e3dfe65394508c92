// Integration tests: the real simulator, behavior and autonomy binaries as child processes over
// Cyclone DDS on loopback (deploy/dds/loopback.xml), observed by this test's own participant.
//
// One DDS domain per test, because ctest runs the tests in parallel (each in its own process).
// Every test joins exactly the domain listed here; keep the ids distinct.
//
//   domain  test
//   ------  -----------------------------------------------
//     61    SystemTest.LockstepRobotReachesGoal
//     62    SystemTest.LockstepSecondRobotAttachedAtRunTimeReachesGoal
//     63    SystemTest.DurabilityLateJoiningReaderGetsCurrentState
//     64    SystemTest.ToolsTopicEchoPrintsRobotStateAsJson
//     65    SystemTest.LockstepKilledBehaviorDoesNotHangSimulator
//     66    SystemTest.CommandsBadVelocityCommandsAreRejectedAndCounted
//     67    ShutdownTest.SigintStopsSimulatorAndBehaviorCleanly
//     68    ShutdownTest.SigtermStopsSimulatorAndBehaviorCleanly
//     69    SystemTest.DeterminismSameRunGivesIdenticalTrajectory
//     70    SystemTest.SpawnBadPoseIsRejected
//     59    SystemTest.LockstepStalledBehaviorRejoinsAndStaysInStep
// (ctest names them integration.<suite>.<test>.)
#include "tests/support/goal_statuses.hpp"
#include "tests/support/process_test.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <list>
#include <memory>
#include <sstream>

namespace autonomy::test {
namespace {

using namespace std::chrono_literals;
using msg::GoalState;

enum Domain : int {
  kDomainGoalReached = 61,
  kDomainSecondRobot = 62,
  kDomainLateJoiner = 63,
  kDomainTopicEcho = 64,
  kDomainKilledBehavior = 65,
  kDomainBadCommands = 66,
  kDomainSigint = 67,
  kDomainSigterm = 68,
  kDomainDeterminism = 69,
  kDomainBadSpawn = 70,
  kDomainStalledBehavior = 59,
};

// The demo scenario (deploy/scenarios/demo.pbtxt), built into the simulator.
constexpr double kWallMinX = 9.8, kWallMaxX = 10.2, kWallMinY = 0.0, kWallMaxY = 8.0;
constexpr double kGoalX = 18.0, kGoalY = 2.0;
constexpr double kGoalTolerance = 0.2;  // GoalTrackerConfig::default_tolerance_m (NavGoal.tolerance 0)


double distance_to_rect(double x, double y, double min_x, double min_y, double max_x, double max_y) {
  const double dx = std::max({min_x - x, 0.0, x - max_x});
  const double dy = std::max({min_y - y, 0.0, y - max_y});
  return std::hypot(dx, dy);
}

double distance_to_wall(const msg::RobotState& s) {
  return distance_to_rect(s.x, s.y, kWallMinX, kWallMinY, kWallMaxX, kWallMaxY);
}


bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

class SystemTest : public ProcessTest {};

// Sends a goal once the behavior's goal reader is matched (NavGoal is volatile).
::testing::AssertionResult send_goal(const dds::Writer<msg::NavGoal>& writer, uint32_t readers, const std::string& robot,
                                     const std::string& goal_id, double x, double y) {
  if (!writer.wait_for_readers(readers, kDeadline))
    return ::testing::AssertionFailure() << "timed out waiting for " << readers << " reader(s) of autonomy/nav/goal";
  writer.write({robot, goal_id, x, y, 0.0});
  return ::testing::AssertionSuccess();
}

std::vector<msg::GoalStatus> statuses_of(const Recorder<msg::GoalStatus>& r, const std::string& goal_id) {
  return r.matching([&](const msg::GoalStatus& s) { return s.goal_id == goal_id; });
}

bool goal_ended(const Recorder<msg::GoalStatus>& r, const std::string& goal_id) {
  for (const auto& s : statuses_of(r, goal_id))
    if (s.state != GoalState::Accepted && s.state != GoalState::Active) return true;
  return false;
}

std::optional<msg::RobotState> last_state_of(const Recorder<msg::RobotState>& r, const std::string& robot) {
  std::optional<msg::RobotState> last;
  for (const auto& s : r.all())
    if (s.robot_id == robot && (!last || s.tick >= last->tick)) last = s;
  return last;
}

std::optional<msg::SimulatorStatus> last_status(const Recorder<msg::SimulatorStatus>& r) {
  if (r.all().empty()) return std::nullopt;
  return r.all().back();
}

int64_t last_tick(const Recorder<msg::SimClock>& r) { return r.all().empty() ? -1 : r.all().back().tick; }
// The world's tick: the clock is not published for quiet ticks (idl/clock.idl: an idle behavior
// needs none), the simulator's status (every 200 ms) has it anyway.
int64_t world_tick(const Recorder<msg::SimClock>& clock, const Recorder<msg::SimulatorStatus>& status) {
  return std::max(last_tick(clock), status.all().empty() ? int64_t{-1} : status.all().back().tick);
}

// Per robot, the ticks of its states never go back; and it never touched the wall.
void expect_states_consistent(const std::vector<msg::RobotState>& states, const std::string& robot) {
  int64_t previous = -1;
  size_t seen = 0;
  for (const auto& s : states) {
    if (s.robot_id != robot) continue;
    ++seen;
    EXPECT_GE(s.tick, previous) << robot << ": robot state ticks went back";
    previous = s.tick;
    EXPECT_GE(distance_to_wall(s), s.radius - 0.001)
        << robot << " entered the wall at tick " << s.tick << ": (" << s.x << ", " << s.y << ")";
    EXPECT_FALSE(s.in_collision) << robot << " in collision at tick " << s.tick << ": (" << s.x << ", " << s.y << ")";
  }
  EXPECT_GT(seen, 0u) << "no robot state of " << robot;
}

// 1. A robot reaches its goal in lockstep.
TEST_F(SystemTest, LockstepRobotReachesGoal) {
  join(kDomainGoalReached);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  Recorder<msg::RobotState> states(participant(), dds::topics::robot_state);
  Recorder<msg::GoalStatus> goals(participant(), dds::topics::goal_status);
  Recorder<msg::SimulatorStatus> sim_status(participant(), dds::topics::sim_status);
  dds::Topic<msg::NavGoal> goal_topic(participant(), dds::topics::nav_goal);
  dds::Writer<msg::NavGoal> goal_writer(participant(), goal_topic);

  start_simulator({"--wait-for", "behavior/r1"});
  auto& behavior = start_behavior("r1");
  ASSERT_TRUE(await_ready(beats, behavior));
  ASSERT_TRUE(send_goal(goal_writer, 1, "r1", "it-goal-1", kGoalX, kGoalY));

  ASSERT_TRUE(await("goal it-goal-1 of r1 to end (reached/failed)", [&] {
    goals.poll();
    states.poll();
    return goal_ended(goals, "it-goal-1");
  }, 60s)) << "statuses: " << states_text(statuses_of(goals, "it-goal-1"));

  const auto history = statuses_of(goals, "it-goal-1");
  std::vector<GoalState> order;
  for (const auto& s : history) order.push_back(s.state);
  ASSERT_EQ(order, (std::vector<GoalState>{GoalState::Accepted, GoalState::Active, GoalState::Reached}))
      << "statuses: " << states_text(history);
  for (const auto& s : history) EXPECT_EQ(s.robot_id, "r1");
  const int64_t reached_tick = history.back().tick;

  // The world goes on after the goal: take the robot's state some ticks later, once stopped (its
  // last published one: the ticks of a robot standing idle are quiet, idl/clock.idl).
  ASSERT_TRUE(await("the world 10 ticks after reaching the goal", [&] {
    states.poll();
    sim_status.poll();
    const auto s = last_status(sim_status);
    return s && s->tick >= reached_tick + 10;
  }));
  const auto last = *last_state_of(states, "r1");
  const double distance = std::hypot(last.x - kGoalX, last.y - kGoalY);
  EXPECT_LE(distance, kGoalTolerance + 0.05) << "r1 ended at (" << last.x << ", " << last.y << ")";
  EXPECT_LE(history.back().distance_to_goal, kGoalTolerance + 1e-9);
  expect_states_consistent(states.all(), "r1");
  // It went around the wall's free end (the wall spans y 0..8), not through it.
  double max_y = 0.0;
  for (const auto& s : states.all())
    if (s.robot_id == "r1") max_y = std::max(max_y, s.y);
  EXPECT_GT(max_y, kWallMaxY) << "r1 never passed above the wall's end";
  std::fprintf(stderr, "r1: %zu states seen, goal reached at tick %lld\n", states.all().size(),
               static_cast<long long>(reached_tick));

  ASSERT_TRUE(await("a simulator status after tick " + std::to_string(reached_tick), [&] {
    sim_status.poll();
    const auto s = last_status(sim_status);
    return s && s->tick > reached_tick;
  }));
  const auto status = *last_status(sim_status);
  EXPECT_GT(status.commands_applied, 0u);
  EXPECT_EQ(status.commands_rejected, 0u);
  EXPECT_EQ(status.participants_dropped, 0u);
  EXPECT_TRUE(contains(status.lockstep_participants, "behavior/r1"));
}

// 2. A second robot attached at run time also reaches its goal; the world keeps running.
TEST_F(SystemTest, LockstepSecondRobotAttachedAtRunTimeReachesGoal) {
  join(kDomainSecondRobot);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  Recorder<msg::RobotState> states(participant(), dds::topics::robot_state);
  Recorder<msg::GoalStatus> goals(participant(), dds::topics::goal_status);
  Recorder<msg::SimClock> clock(participant(), dds::topics::clock);
  Recorder<msg::SimulatorStatus> sim_status(participant(), dds::topics::sim_status);
  dds::Topic<msg::NavGoal> goal_topic(participant(), dds::topics::nav_goal);
  dds::Writer<msg::NavGoal> goal_writer(participant(), goal_topic);
  auto poll_all = [&] {
    states.poll();
    goals.poll();
    clock.poll();
    sim_status.poll();
  };

  start_simulator({"--wait-for", "behavior/r1"});
  auto& r1 = start_behavior("r1");
  ASSERT_TRUE(await_ready(beats, r1));
  ASSERT_TRUE(send_goal(goal_writer, 1, "r1", "goal-r1", kGoalX, kGoalY));
  ASSERT_TRUE(await("r1 moving (0.5 m from its start (2, 2))", [&] {
    poll_all();
    const auto s = last_state_of(states, "r1");
    return s && std::hypot(s->x - 2.0, s->y - 2.0) > 0.5;
  }));
  poll_all();
  EXPECT_TRUE(states.matching([](const msg::RobotState& s) { return s.robot_id == "r2"; }).empty())
      << "r2 existed before its behavior process started";
  // The status is published on its own period; a fast robot can cover 0.5 m before the first.
  ASSERT_TRUE(await("a simulator status before r2 starts", [&] {
    poll_all();
    return last_status(sim_status).has_value();
  }));
  EXPECT_EQ(last_status(sim_status)->robots, 1u);
  const int64_t tick_before_r2 = last_tick(clock);

  auto& r2 = start_behavior("r2");
  ASSERT_TRUE(await_ready(beats, r2));
  // Two goal readers now: r1's and r2's behavior.
  ASSERT_TRUE(send_goal(goal_writer, 2, "r2", "goal-r2", 2.5, 9.0));

  ASSERT_TRUE(await("both goals to end", [&] {
    poll_all();
    return goal_ended(goals, "goal-r1") && goal_ended(goals, "goal-r2");
  }, 60s)) << "r1: " << states_text(statuses_of(goals, "goal-r1"))
           << "; r2: " << states_text(statuses_of(goals, "goal-r2"));
  EXPECT_EQ(statuses_of(goals, "goal-r1").back().state, GoalState::Reached)
      << states_text(statuses_of(goals, "goal-r1"));
  EXPECT_EQ(statuses_of(goals, "goal-r2").back().state, GoalState::Reached)
      << states_text(statuses_of(goals, "goal-r2"));

  const auto r2_states = states.matching([](const msg::RobotState& s) { return s.robot_id == "r2"; });
  ASSERT_FALSE(r2_states.empty());
  EXPECT_GE(r2_states.front().tick, tick_before_r2) << "r2's first state predates its attachment";
  EXPECT_NEAR(r2_states.front().x, 2.0, 1e-9);
  EXPECT_NEAR(r2_states.front().y, 5.0, 1e-9);
  const auto r2_last = *last_state_of(states, "r2");
  EXPECT_LE(std::hypot(r2_last.x - 2.5, r2_last.y - 9.0), kGoalTolerance + 0.05);
  expect_states_consistent(states.all(), "r1");
  expect_states_consistent(states.all(), "r2");

  // The world kept running: the clock only went forward, from before r2 to after both goals.
  int64_t previous = -1;
  for (const auto& c : clock.all()) {
    EXPECT_GT(c.tick, previous) << "clock did not increase";
    previous = c.tick;
  }
  const int64_t tick_after = world_tick(clock, sim_status);
  EXPECT_GT(tick_after, tick_before_r2);
  ASSERT_TRUE(await("the clock to go on after both goals", [&] {
    poll_all();
    return world_tick(clock, sim_status) > tick_after + 5;
  }));
  ASSERT_TRUE(await("a simulator status with 2 robots", [&] {
    poll_all();
    const auto s = last_status(sim_status);
    return s && s->robots == 2 && s->tick > tick_after;
  }));
  const auto status = *last_status(sim_status);
  EXPECT_TRUE(contains(status.lockstep_participants, "behavior/r1"));
  EXPECT_TRUE(contains(status.lockstep_participants, "behavior/r2"));
  EXPECT_EQ(status.commands_rejected, 0u);
}

// 3. A reader created late gets the current robot state and the map at once (transient-local).
TEST_F(SystemTest, DurabilityLateJoiningReaderGetsCurrentState) {
  join(kDomainLateJoiner);
  Recorder<msg::SimulatorStatus> sim_status(participant(), dds::topics::sim_status);
  // Held at tick 0 (nobody registers as behavior/r1): the robot state of tick 0 and the map are
  // each written once, at start, so only durability can bring them to a late reader.
  start_simulator({"--wait-for", "behavior/r1"});
  ASSERT_TRUE(await("simulator status (the simulator is up)", [&] { return !sim_status.poll().empty(); }));
  // Let the simulator's status go on for a while, so the readers below are clearly late.
  const auto first = std::chrono::steady_clock::now();
  ASSERT_TRUE(await("1 s of simulator status", [&] {
    sim_status.poll();
    return std::chrono::steady_clock::now() - first >= 1s;
  }));
  EXPECT_EQ(last_status(sim_status)->tick, 0) << "the simulator should hold tick 0";

  Recorder<msg::RobotState> states(participant(), dds::topics::robot_state);
  Recorder<msg::WorldMap> map(participant(), dds::topics::world_map);
  ASSERT_TRUE(await("r1's state and the map on the late readers", [&] {
    states.poll();
    map.poll();
    return last_state_of(states, "r1").has_value() && !map.all().empty();
  }));
  const auto r1 = *last_state_of(states, "r1");
  EXPECT_EQ(r1.tick, 0);
  EXPECT_DOUBLE_EQ(r1.x, 2.0);
  EXPECT_DOUBLE_EQ(r1.y, 2.0);
  EXPECT_DOUBLE_EQ(r1.radius, 0.3);
  EXPECT_DOUBLE_EQ(r1.max_speed, 1.0);
  EXPECT_EQ(r1.kinematics, msg::Kinematics::Unicycle);
  EXPECT_EQ(states.all().size(), 1u) << "only the current state of the single robot";

  ASSERT_EQ(map.all().size(), 1u);
  const auto& m = map.all().front();
  EXPECT_EQ(m.name, "demo");
  EXPECT_DOUBLE_EQ(m.width, 20.0);
  EXPECT_DOUBLE_EQ(m.height, 12.0);
  ASSERT_EQ(m.obstacles.size(), 4u);
  EXPECT_DOUBLE_EQ(m.obstacles[0].min_x, kWallMinX);
  EXPECT_DOUBLE_EQ(m.obstacles[0].max_x, kWallMaxX);
  EXPECT_DOUBLE_EQ(m.obstacles[0].min_y, kWallMinY);
  EXPECT_DOUBLE_EQ(m.obstacles[0].max_y, kWallMaxY);
}

// 4. `autonomy topic echo` prints the robot state as a JSON line.
TEST_F(SystemTest, ToolsTopicEchoPrintsRobotStateAsJson) {
  if (std::string(AUTONOMY_CLI_BIN).empty()) GTEST_SKIP() << "the autonomy tool is not part of this build";
  join(kDomainTopicEcho);
  Recorder<msg::SimulatorStatus> sim_status(participant(), dds::topics::sim_status);
  start_simulator();
  ASSERT_TRUE(await("simulator status (the simulator is up)", [&] { return !sim_status.poll().empty(); }));

  auto& echo = start("autonomy-echo", AUTONOMY_CLI_BIN,
                     {"topic", "echo", "autonomy/robot/state", "--count", "1", "--timeout", "30", "--domain",
                      std::to_string(domain_)},
                     /*must_keep_running=*/false, /*separate_stderr=*/true);
  const auto ended = echo.wait_for_exit(45s);
  ASSERT_TRUE(ended.has_value()) << "autonomy topic echo did not end within 45 s";
  ASSERT_TRUE(ended->exited && ended->code == 0) << "autonomy topic echo: " << ended->describe();

  std::istringstream out(read_file(echo.log_file()));
  std::vector<std::string> lines;
  for (std::string line; std::getline(out, line);)
    if (!line.empty()) lines.push_back(line);
  ASSERT_EQ(lines.size(), 1u) << "stdout:\n" << read_file(echo.log_file());
  nlohmann::json j;
  ASSERT_NO_THROW(j = nlohmann::json::parse(lines[0])) << lines[0];
  ASSERT_TRUE(j.is_object()) << lines[0];
  EXPECT_EQ(j.value("robot_id", ""), "r1") << lines[0];
  ASSERT_TRUE(j.contains("x") && j["x"].is_number()) << lines[0];
  ASSERT_TRUE(j.contains("y") && j["y"].is_number()) << lines[0];
  EXPECT_NEAR(j["x"].get<double>(), 2.0, 1e-9);
  EXPECT_NEAR(j["y"].get<double>(), 2.0, 1e-9);
}

// 5. A killed behavior does not hang the simulator; a new one re-attaches and reaches a goal.
TEST_F(SystemTest, LockstepKilledBehaviorDoesNotHangSimulator) {
  join(kDomainKilledBehavior);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  Recorder<msg::SimClock> clock(participant(), dds::topics::clock);
  Recorder<msg::SimulatorStatus> sim_status(participant(), dds::topics::sim_status);
  Recorder<msg::GoalStatus> goals(participant(), dds::topics::goal_status);
  Recorder<msg::RobotState> states(participant(), dds::topics::robot_state);
  dds::Topic<msg::NavGoal> goal_topic(participant(), dds::topics::nav_goal);
  dds::Writer<msg::NavGoal> goal_writer(participant(), goal_topic);
  auto poll_all = [&] {
    clock.poll();
    sim_status.poll();
    goals.poll();
    states.poll();
  };

  start_simulator({"--wait-for", "behavior/r1"});
  auto& first = start_behavior("r1", {}, true, "behavior-r1-first");
  ASSERT_TRUE(await_ready(beats, first));
  ASSERT_TRUE(await("lockstep running with behavior/r1 (tick > 20, listed in the status)", [&] {
    poll_all();
    const auto s = last_status(sim_status);
    return world_tick(clock, sim_status) > 20 && s && contains(s->lockstep_participants, "behavior/r1");
  }));

  stop_watching(first);
  first.signal(SIGKILL);
  const auto killed = first.wait_for_exit(10s);
  ASSERT_TRUE(killed.has_value());
  EXPECT_FALSE(killed->exited);
  EXPECT_EQ(killed->signal, SIGKILL);
  poll_all();
  const int64_t tick_at_kill = world_tick(clock, sim_status);

  ASSERT_TRUE(await("the simulator to let go of behavior/r1 (dropped or unregistered) and tick on", [&] {
    poll_all();
    const auto s = last_status(sim_status);
    return s && (s->participants_dropped >= 1 || !contains(s->lockstep_participants, "behavior/r1")) &&
           world_tick(clock, sim_status) > tick_at_kill + 20;
  }));
  // Ticks keep increasing afterwards, too.
  const int64_t tick_after_drop = world_tick(clock, sim_status);
  ASSERT_TRUE(await("the clock to go on without behavior/r1", [&] {
    poll_all();
    return world_tick(clock, sim_status) > tick_after_drop + 20;
  }));
  // The dead process's goal reader goes away with its lease; then the new one is the only reader.
  ASSERT_TRUE(await("the killed behavior's goal reader to be unmatched (lease expiry)",
                    [&] { return goal_writer.matched_readers() == 0; }));

  auto& second = start_behavior("r1", {}, true, "behavior-r1-second");
  ASSERT_TRUE(await_ready(beats, second));
  ASSERT_TRUE(await("behavior/r1 back in the simulator's lockstep participants", [&] {
    poll_all();
    const auto s = last_status(sim_status);
    return s && contains(s->lockstep_participants, "behavior/r1");
  }));
  ASSERT_TRUE(send_goal(goal_writer, 1, "r1", "after-restart", kGoalX, kGoalY));
  ASSERT_TRUE(await("goal after-restart to end", [&] {
    poll_all();
    return goal_ended(goals, "after-restart");
  }, 60s)) << states_text(statuses_of(goals, "after-restart"));
  EXPECT_EQ(statuses_of(goals, "after-restart").back().state, GoalState::Reached)
      << states_text(statuses_of(goals, "after-restart"));
  const auto last = *last_state_of(states, "r1");
  EXPECT_LE(std::hypot(last.x - kGoalX, last.y - kGoalY), kGoalTolerance + 0.05);
  expect_states_consistent(states.all(), "r1");
}

// A behavior frozen (SIGSTOP) past the ack timeout is dropped; once it runs again its next ack
// rejoins it and it stays in step. Its command for the rejoining tick may arrive before that ack
// (this once left the barrier owing a command: dropped again every tick, one tick per 2 s). The
// drop and the rejoin are published (autonomy/sim/status: the dropped list and the numbered
// changes, naming the participant and why) and `autonomy node watch` prints them.
TEST_F(SystemTest, LockstepStalledBehaviorRejoinsAndStaysInStep) {
  join(kDomainStalledBehavior);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  Recorder<msg::SimClock> clock(participant(), dds::topics::clock);
  Recorder<msg::SimulatorStatus> sim_status(participant(), dds::topics::sim_status);
  auto poll_all = [&] {
    clock.poll();
    sim_status.poll();
  };
  // Wandering forever keeps the behavior commanding every tick, so every ack announces a command.
  write_file(dir().file("wander.pbtxt"),
             "name: \"wander\" robot: \"r1\" initial_state: \"w\" states { name: \"w\" wander {} }\n");
  // The demo world with a 0.5 s ack timeout: the freeze below must outlast it but not the DDS
  // lease (2 s in loopback.xml), after which the process would count as gone, not slow.
  {
    std::string scenario = read_file(std::string(AUTONOMY_SOURCE_DIR) + "/deploy/scenarios/demo.pbtxt");
    const std::string from = "ack_timeout_s: 2.0";
    ASSERT_NE(scenario.find(from), std::string::npos);
    scenario.replace(scenario.find(from), from.size(), "ack_timeout_s: 0.5");
    write_file(dir().file("scenario.pbtxt"), scenario);
  }
  const bool with_tool = !std::string(AUTONOMY_CLI_BIN).empty();
  if (with_tool)
    start("autonomy-watch", AUTONOMY_CLI_BIN,
          {"node", "watch", "--domain", std::to_string(kDomainStalledBehavior), "--no-relay", "behavior/r1"});
  start_simulator({"--config", dir().file("scenario.pbtxt"), "--wait-for", "behavior/r1"});
  auto& behavior = start_behavior("r1", {"--mission", dir().file("wander.pbtxt")});
  ASSERT_TRUE(await_ready(beats, behavior));
  // With a 0.5 s ack timeout the behavior's start (spawn, map, mission) may already cost it a
  // drop and a rejoin at tick 0 or 1: the freeze's drop is the one after what the status says now.
  std::optional<msg::SimulatorStatus> before;
  ASSERT_TRUE(await("lockstep running with behavior/r1", [&] {
    poll_all();
    before = last_status(sim_status);
    return last_tick(clock) > 20 && before && contains(before->lockstep_participants, "behavior/r1") &&
           before->lockstep_dropped.empty();
  }));
  const uint64_t drops_before = before->participants_dropped;
  const uint64_t changes_before = before->lockstep_changes.empty() ? 0 : before->lockstep_changes.back().number;

  behavior.signal(SIGSTOP);
  // Woken as soon as the simulator has dropped it, well inside the DDS lease.
  std::optional<msg::SimulatorStatus> at_drop;
  const bool dropped = static_cast<bool>(await("the simulator to drop the frozen behavior/r1", [&] {
    poll_all();
    at_drop = last_status(sim_status);
    return at_drop && at_drop->participants_dropped > drops_before;
  }));
  behavior.signal(SIGCONT);
  ASSERT_TRUE(dropped);
  // The status written at the drop names it, as dropped now and as the run's first change, why.
  EXPECT_EQ(at_drop->lockstep_dropped, std::vector<std::string>{"behavior/r1"});
  ASSERT_FALSE(at_drop->lockstep_changes.empty());
  const msg::LockstepChange drop = at_drop->lockstep_changes.back();
  EXPECT_EQ(drop.number, changes_before + 1);
  EXPECT_EQ(drop.participant, "behavior/r1");
  EXPECT_TRUE(drop.dropped);
  EXPECT_NE(drop.reason.find("did not acknowledge tick " + std::to_string(drop.tick) + " within the ack timeout (0.5 s)"),
            std::string::npos)
      << drop.reason;
  // Stopped for less than its lease: still registered, and the reason says so.
  EXPECT_NE(drop.reason.find("still registered"), std::string::npos) << drop.reason;
  EXPECT_FALSE(contains(at_drop->lockstep_participants, "behavior/r1"));
  ASSERT_TRUE(await("behavior/r1 rejoined", [&] {
    poll_all();
    const auto s = last_status(sim_status);
    return s && contains(s->lockstep_participants, "behavior/r1");
  }));
  const int64_t tick_at_rejoin = last_tick(clock);
  const uint64_t drops_at_rejoin = last_status(sim_status)->participants_dropped;
  ASSERT_TRUE(await("200 more ticks in lockstep with behavior/r1", [&] {
    poll_all();
    return last_tick(clock) > tick_at_rejoin + 200;
  }));
  const auto s = last_status(sim_status);
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->participants_dropped, drops_at_rejoin) << "dropped again after rejoining";
  EXPECT_TRUE(contains(s->lockstep_participants, "behavior/r1"));
  // The rejoin is the change after the drop, and the last; nobody is dropped now.
  EXPECT_TRUE(s->lockstep_dropped.empty());
  ASSERT_FALSE(s->lockstep_changes.empty());
  const msg::LockstepChange& back = s->lockstep_changes.back();
  EXPECT_EQ(back.number, drop.number + 1);
  EXPECT_EQ(back.participant, "behavior/r1");
  EXPECT_FALSE(back.dropped);
  EXPECT_GE(back.tick, drop.tick);
  EXPECT_EQ(back.reason, "it acknowledged tick " + std::to_string(back.tick) + " again");
  if (with_tool) {
    // The tool prints both, in order, with the tick and the reason.
    const std::string watched = read_file(dir().file("autonomy-watch.out"));
    const auto dropped_line = watched.find("lockstep_dropped behavior/r1 at tick " + std::to_string(drop.tick) + ": " +
                                           drop.reason);
    ASSERT_NE(dropped_line, std::string::npos) << watched;
    EXPECT_NE(watched.find("lockstep_rejoined behavior/r1 at tick " + std::to_string(back.tick) + ": " + back.reason,
                           dropped_line),
              std::string::npos)
        << watched;
  }
}

// 6. Bad velocity commands are rejected with a reason and counted; the robot does not move.
TEST_F(SystemTest, CommandsBadVelocityCommandsAreRejectedAndCounted) {
  join(kDomainBadCommands);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  Recorder<msg::SimulatorStatus> sim_status(participant(), dds::topics::sim_status);
  Recorder<msg::RobotState> states(participant(), dds::topics::robot_state);
  Recorder<msg::CommandRejection> rejections(participant(), dds::topics::command_rejected);
  dds::Topic<msg::VelocityCommand> cmd_topic(participant(), dds::topics::cmd_vel);
  dds::Writer<msg::VelocityCommand> cmd_writer(participant(), cmd_topic);

  // No lockstep participant: the world idles forward in real time and applies outside commands.
  auto& sim = start_simulator();
  ASSERT_TRUE(await_ready(beats, sim));
  ASSERT_TRUE(await("r1's state", [&] {
    states.poll();
    return last_state_of(states, "r1").has_value();
  }));
  ASSERT_TRUE(cmd_writer.wait_for_readers(1, kDeadline)) << "the simulator's cmd_vel reader did not match";
  ASSERT_TRUE(rejections.reader().matched_writers() >= 1 ||
              await("the simulator's rejection writer to match", [&] { return rejections.reader().matched_writers() >= 1; }));

  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Distinct ticks tell the rejections apart.
  cmd_writer.write({"nobody", "integration-test", 1001, 0.5, 0.0, 0.0});
  cmd_writer.write({"r1", "integration-test", 1002, nan, 0.0, 0.0});
  cmd_writer.write({"r1", "integration-test", 1003, 50.0, 0.0, 0.0});
  cmd_writer.write({"r1", "integration-test", 1004, 0.0, 0.0, 5.0});  // max_omega is 2 rad/s

  ASSERT_TRUE(await("4 command rejections", [&] {
    rejections.poll();
    return rejections.all().size() >= 4;
  })) << rejections.all().size() << " rejection(s)";
  std::map<int64_t, msg::CommandRejection> by_tick;
  for (const auto& r : rejections.all()) by_tick[r.tick] = r;
  ASSERT_EQ(by_tick.size(), 4u);
  for (int64_t t = 1001; t <= 1004; ++t) {
    ASSERT_TRUE(by_tick.count(t)) << "no rejection for the command stamped " << t;
    EXPECT_EQ(by_tick[t].source, "integration-test");
  }
  auto lower = [](std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
  };
  EXPECT_EQ(by_tick[1001].robot_id, "nobody");
  EXPECT_NE(by_tick[1001].reason.find("nobody"), std::string::npos) << by_tick[1001].reason;
  EXPECT_NE(lower(by_tick[1001].reason).find("unknown"), std::string::npos) << by_tick[1001].reason;
  EXPECT_NE(by_tick[1002].reason.find("NaN"), std::string::npos) << by_tick[1002].reason;
  EXPECT_NE(by_tick[1002].reason.find("vx"), std::string::npos) << by_tick[1002].reason;
  EXPECT_NE(lower(by_tick[1003].reason).find("speed"), std::string::npos) << by_tick[1003].reason;
  EXPECT_NE(lower(by_tick[1003].reason).find("limit"), std::string::npos) << by_tick[1003].reason;
  EXPECT_NE(lower(by_tick[1004].reason).find("omega"), std::string::npos) << by_tick[1004].reason;
  EXPECT_NE(lower(by_tick[1004].reason).find("limit"), std::string::npos) << by_tick[1004].reason;

  ASSERT_TRUE(await("a simulator status counting 4 rejected commands", [&] {
    sim_status.poll();
    const auto s = last_status(sim_status);
    return s && s->commands_rejected >= 4;
  }));
  const int64_t tick_rejected = last_status(sim_status)->tick;
  // Still running: ticks go on, the status keeps the counts, the robot stands still.
  ASSERT_TRUE(await("the simulator to tick on after the rejections", [&] {
    sim_status.poll();
    states.poll();
    const auto r1 = last_state_of(states, "r1");
    return last_status(sim_status)->tick > tick_rejected + 10 && r1 && r1->tick > tick_rejected + 10;
  }));
  const auto status = *last_status(sim_status);
  EXPECT_EQ(status.commands_rejected, 4u);
  EXPECT_EQ(status.commands_applied, 0u);
  for (const auto& s : states.matching([](const msg::RobotState& s) { return s.robot_id == "r1"; })) {
    EXPECT_DOUBLE_EQ(s.x, 2.0) << "r1 moved at tick " << s.tick;
    EXPECT_DOUBLE_EQ(s.y, 2.0) << "r1 moved at tick " << s.tick;
    EXPECT_DOUBLE_EQ(s.theta, 0.0) << "r1 turned at tick " << s.tick;
    EXPECT_EQ(s.vx, 0.0);
    EXPECT_EQ(s.omega, 0.0);
  }
  EXPECT_TRUE(states.matching([](const msg::RobotState& s) { return s.robot_id == "nobody"; }).empty());
  EXPECT_TRUE(sim.running());
  // The heartbeat says the simulator still serves (a fresh heartbeat, after the rejections).
  beats.poll();
  const size_t beats_before = beats.all().size();
  ASSERT_TRUE(await("a new simulator heartbeat", [&] {
    beats.poll();
    return beats.all().size() > beats_before;
  }));
  const auto sim_beats = beats.matching([&](const msg::Heartbeat& h) { return h.pid == sim.pid(); });
  ASSERT_FALSE(sim_beats.empty());
  EXPECT_EQ(sim_beats.back().state, msg::ServiceState::Ready);
  EXPECT_EQ(sim_beats.back().service, "simulator");
}

// 7. SIGINT / SIGTERM stop simulator and behavior with exit code 0.

class ShutdownTest : public SystemTest {
 protected:
  void check_clean_shutdown(int sig) {
    Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
    Recorder<msg::SimClock> clock(participant(), dds::topics::clock);
    auto& sim = start_simulator({"--wait-for", "behavior/r1"});
    auto& behavior = start_behavior("r1", {"--goal", "18", "2"});
    ASSERT_TRUE(await_ready(beats, sim));
    ASSERT_TRUE(await_ready(beats, behavior));
    ASSERT_TRUE(await("lockstep running (tick > 10)", [&] {
      clock.poll();
      return last_tick(clock) > 10;
    }));
    stop_watching(sim);
    stop_watching(behavior);
    behavior.signal(sig);
    sim.signal(sig);
    const auto behavior_end = behavior.wait_for_exit(20s);
    const auto sim_end = sim.wait_for_exit(20s);
    ASSERT_TRUE(behavior_end.has_value()) << "behavior still running 20 s after signal " << sig;
    ASSERT_TRUE(sim_end.has_value()) << "simulator still running 20 s after signal " << sig;
    EXPECT_TRUE(behavior_end->exited && behavior_end->code == 0) << "behavior: " << behavior_end->describe();
    EXPECT_TRUE(sim_end->exited && sim_end->code == 0) << "simulator: " << sim_end->describe();
    // Both said goodbye with a "stopping" heartbeat.
    for (const ChildProcess* c : {&sim, &behavior}) {
      EXPECT_TRUE(eventually(c->name() + "'s stopping heartbeat", [&] {
        beats.poll();
        return !beats.matching([&](const msg::Heartbeat& h) {
                        return h.pid == c->pid() && h.state == msg::ServiceState::Stopping;
                      }).empty();
      }, 5s));
    }
  }
};

TEST_F(ShutdownTest, SigintStopsSimulatorAndBehaviorCleanly) {
  join(kDomainSigint);
  check_clean_shutdown(SIGINT);
}

TEST_F(ShutdownTest, SigtermStopsSimulatorAndBehaviorCleanly) {
  join(kDomainSigterm);
  check_clean_shutdown(SIGTERM);
}

// 8. Two identical lockstep runs write byte-identical trajectories.
TEST_F(SystemTest, DeterminismSameRunGivesIdenticalTrajectory) {
  join(kDomainDeterminism);
  constexpr int kTicks = 600;
  std::vector<std::string> csv;
  for (int run = 1; run <= 2; ++run) {
    const std::string file = dir().file("trajectory-" + std::to_string(run) + ".csv");
    csv.push_back(file);
    auto& sim = start_simulator({"--wait-for", "behavior/r1", "--max-ticks", std::to_string(kTicks), "--trajectory", file},
                                /*must_keep_running=*/false, "simulator-run" + std::to_string(run));
    auto& behavior = start_behavior("r1", {"--goal", "18", "2"}, true, "behavior-run" + std::to_string(run));
    const auto sim_end = sim.wait_for_exit(60s);
    ASSERT_TRUE(sim_end.has_value()) << "run " << run << ": simulator did not finish " << kTicks << " ticks in 60 s";
    ASSERT_TRUE(sim_end->exited && sim_end->code == 0) << "run " << run << ": simulator " << sim_end->describe();
    stop_watching(behavior);
    behavior.signal(SIGINT);
    const auto behavior_end = behavior.wait_for_exit(20s);
    ASSERT_TRUE(behavior_end.has_value()) << "run " << run << ": behavior did not stop on SIGINT";
    EXPECT_TRUE(behavior_end->exited && behavior_end->code == 0) << "run " << run << ": behavior " << behavior_end->describe();
  }
  const std::string a = read_file(csv[0]);
  const std::string b = read_file(csv[1]);
  ASSERT_FALSE(a.empty());
  EXPECT_TRUE(a == b) << "trajectories differ: " << csv[0] << " vs " << csv[1];

  // The robot moved: compare its first and last row.
  std::istringstream in(a);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "tick,time_s,robot,x,y,theta");
  std::vector<std::vector<std::string>> rows;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream ls(line);
    for (std::string c; std::getline(ls, c, ',');) cells.push_back(c);
    ASSERT_EQ(cells.size(), 6u) << line;
    rows.push_back(cells);
  }
  ASSERT_GE(rows.size(), static_cast<size_t>(kTicks));
  EXPECT_EQ(rows.front()[2], "r1");
  EXPECT_EQ(std::stoll(rows.back()[0]), kTicks);
  const double x0 = std::stod(rows.front()[3]), y0 = std::stod(rows.front()[4]);
  const double x1 = std::stod(rows.back()[3]), y1 = std::stod(rows.back()[4]);
  EXPECT_NEAR(x0, 2.0, 1e-9);
  EXPECT_NEAR(y0, 2.0, 1e-9);
  EXPECT_GT(std::hypot(x1 - x0, y1 - y0), 5.0) << "r1 barely moved: (" << x1 << ", " << y1 << ")";
  for (const auto& r : rows)
    EXPECT_GE(distance_to_rect(std::stod(r[3]), std::stod(r[4]), kWallMinX, kWallMinY, kWallMaxX, kWallMaxY),
              0.3 - 0.001)
        << "inside the wall at tick " << r[0];
}

// 9. A spawn inside the wall is rejected with a reason; behavior --start inside the wall exits 1.
TEST_F(SystemTest, SpawnBadPoseIsRejected) {
  join(kDomainBadSpawn);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  Recorder<msg::SpawnReply> replies(participant(), dds::topics::spawn_reply);
  Recorder<msg::SimulatorStatus> sim_status(participant(), dds::topics::sim_status);
  Recorder<msg::RobotState> states(participant(), dds::topics::robot_state);
  dds::Topic<msg::SpawnRequest> request_topic(participant(), dds::topics::spawn_request);
  dds::Writer<msg::SpawnRequest> request_writer(participant(), request_topic);

  auto& sim = start_simulator();
  ASSERT_TRUE(await_ready(beats, sim));
  ASSERT_TRUE(request_writer.wait_for_readers(1, kDeadline)) << "the simulator's spawn request reader did not match";

  msg::SpawnRequest request;
  request.request_id = "integration-test-1";
  request.requester = "integration-test";
  request.robot_id = "rX";
  request.has_pose = true;
  request.x = 10.0;
  request.y = 4.0;
  // Request/reply are volatile: repeat until answered (a repeat gets the first answer again).
  auto last_sent = std::chrono::steady_clock::time_point{};
  ASSERT_TRUE(await("a spawn reply to integration-test-1", [&] {
    if (std::chrono::steady_clock::now() - last_sent > 500ms) {
      request_writer.write(request);
      last_sent = std::chrono::steady_clock::now();
    }
    replies.poll();
    return !replies.matching([](const msg::SpawnReply& r) { return r.request_id == "integration-test-1"; }).empty();
  }));
  const auto reply = replies.matching([](const msg::SpawnReply& r) { return r.request_id == "integration-test-1"; }).front();
  EXPECT_EQ(reply.robot_id, "rX");
  EXPECT_EQ(reply.status, msg::RequestStatus::Rejected);
  EXPECT_FALSE(reply.reason.empty());
  EXPECT_NE(reply.reason.find("obstacle"), std::string::npos) << reply.reason;
  for (const auto& r : replies.all())
    if (r.request_id == "integration-test-1") {
      EXPECT_EQ(r.status, msg::RequestStatus::Rejected);
    }

  auto& behavior = start_behavior("rX", {"--start", "10", "4"}, /*must_keep_running=*/false);
  const auto ended = behavior.wait_for_exit(30s);
  ASSERT_TRUE(ended.has_value()) << "behavior --robot rX --start 10 4 still running after 30 s";
  EXPECT_TRUE(ended->exited && ended->code == 1) << "behavior: " << ended->describe();

  // The world is unchanged: still one robot, no state of rX, the simulator serves on.
  const int64_t tick_now = [&] {
    sim_status.poll();
    return sim_status.all().empty() ? 0 : sim_status.all().back().tick;
  }();
  ASSERT_TRUE(await("a simulator status after the refused spawns", [&] {
    sim_status.poll();
    return !sim_status.all().empty() && sim_status.all().back().tick > tick_now;
  }));
  EXPECT_EQ(last_status(sim_status)->robots, 1u);
  states.poll();
  EXPECT_TRUE(states.matching([](const msg::RobotState& s) { return s.robot_id == "rX"; }).empty());
  EXPECT_TRUE(sim.running());
}

}  // namespace
}  // namespace autonomy::test
