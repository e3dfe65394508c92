// Fleet traffic (docs/traffic.md, issue 25) with the real simulator and one behavior per robot on
// the office floor, in lockstep: robots crossing one doorway from both sides all get through
// without touching (judged on the simulator's robot states, its ground truth), waiting visibly;
// a robot parked in, or killed in, the only doorway of a room ends the others' goals Blocked with
// a reason that names it; two robots meeting head-on in the hallway pass (one gives way); a robot
// standing in the hallway is driven around.
//
// One DDS domain per test; this file uses 49-51, 104-105 and 107 only:
//
//   domain  test
//   ------  -----------------------------------------------
//     49    TrafficTest.FourRobotsCrossOneDoorwayFromBothSides
//     50    TrafficDoorwayTest.ARobotParkedInTheOnlyDoorwayBlocksWithAReason
//     51    TrafficDoorwayTest.ARobotKilledInTheOnlyDoorwayBlocksWithAReason
//    104    TrafficTest.TwoRobotsHeadOnInTheHallwayBothArrive
//    105    TrafficDoorwayTest.ARobotKilledDrivingThroughTheOnlyDoorwayBlocksWithAReason
//    107    TrafficTest.ARobotStandingInTheHallwayIsDrivenAround
#include "tests/support/goal_statuses.hpp"
#include "tests/support/process_test.hpp"

#include <gtest/gtest.h>
#include <signal.h>

#include <cmath>
#include <map>
#include <thread>

namespace autonomy::test {
namespace {

using namespace std::chrono_literals;
using msg::GoalState;

const std::string kOffice = std::string(AUTONOMY_SOURCE_DIR) + "/deploy/scenarios/office.pbtxt";

class TrafficTest : public ProcessTest {
 protected:
  // The closest two robots came at one tick (centre distance), and how many states said a robot's
  // motion was stopped by something (the simulator's in_collision).
  struct Contact {
    double closest_m = 1e9;
    std::string where;
    int collisions = 0;
  };
  static Contact contacts(const std::vector<msg::RobotState>& states) {
    Contact c;
    std::map<int64_t, std::vector<const msg::RobotState*>> by_tick;
    for (const auto& s : states) {
      by_tick[s.tick].push_back(&s);
      if (s.in_collision) ++c.collisions;
    }
    for (const auto& [tick, v] : by_tick)
      for (std::size_t i = 0; i < v.size(); ++i)
        for (std::size_t j = i + 1; j < v.size(); ++j) {
          const double d = std::hypot(v[i]->x - v[j]->x, v[i]->y - v[j]->y);
          if (d < c.closest_m) {
            c.closest_m = d;
            c.where = v[i]->robot_id + " and " + v[j]->robot_id + " at tick " + std::to_string(tick);
          }
        }
    return c;
  }
  static std::vector<msg::GoalStatus> of(const Recorder<msg::GoalStatus>& goals, const std::string& robot) {
    return goals.matching([&](const msg::GoalStatus& g) { return g.robot_id == robot; });
  }
  static bool ended(const std::vector<msg::GoalStatus>& v) {
    return !v.empty() && v.back().state != GoalState::Accepted && v.back().state != GoalState::Active;
  }
};

// Two robots in A-114 leave through its door for the classroom across the hallway while two in
// the hallway east of the door come in: all four reach their goals, never closer than two radii
// (0.6 m), and someone waited for the doorway saying so.
TEST_F(TrafficTest, FourRobotsCrossOneDoorwayFromBothSides) {
  join(49);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  Recorder<msg::RobotState> states(participant(), dds::topics::robot_state);
  Recorder<msg::GoalStatus> goals(participant(), dds::topics::goal_status);
  start_simulator({"--config", kOffice, "--without-robots", "--wait-for", "behavior/r1", "behavior/r2", "behavior/r3",
                   "behavior/r4"});
  start_behavior("r1", {"--start", "16.8", "4.0", "1.57", "--goal", "14.5", "12.0"});
  start_behavior("r2", {"--start", "18.4", "4.0", "1.57", "--goal", "13.0", "12.5"});
  start_behavior("r3", {"--start", "21.0", "8.0", "3.14", "--goal", "17.0", "3.0"});
  start_behavior("r4", {"--start", "23.0", "8.0", "3.14", "--goal", "18.5", "2.5"});
  const std::vector<std::string> robots{"r1", "r2", "r3", "r4"};
  ASSERT_TRUE(await("every goal ended", [&] {
    goals.poll();
    for (const auto& r : robots)
      if (!ended(of(goals, r))) return false;
    return true;
  }, 180s));
  states.poll();
  bool someone_waited = false;
  for (const auto& r : robots) {
    const auto v = of(goals, r);
    EXPECT_EQ(v.back().state, GoalState::Reached) << r << ": " << states_text(v);
    for (const auto& g : v) someone_waited |= g.reason.find("to clear doorway A-114") != std::string::npos;
  }
  EXPECT_TRUE(someone_waited);
  const Contact c = contacts(states.all());
  EXPECT_GE(c.closest_m, 0.6 - 1e-6) << c.where;
  EXPECT_EQ(c.collisions, 0);
}

// Two robots drive the 1.8 m hallway towards each other (wide enough for two side by side, so
// no passage): the later in the order (r2) steps aside, saying whom it gives way to, and both
// arrive without touching.
TEST_F(TrafficTest, TwoRobotsHeadOnInTheHallwayBothArrive) {
  join(104);
  Recorder<msg::RobotState> states(participant(), dds::topics::robot_state);
  Recorder<msg::GoalStatus> goals(participant(), dds::topics::goal_status);
  start_simulator({"--config", kOffice, "--without-robots", "--wait-for", "behavior/r1", "behavior/r2"});
  start_behavior("r1", {"--start", "10.0", "8.0", "0", "--goal", "26.0", "8.0"});
  start_behavior("r2", {"--start", "26.0", "8.0", "3.14", "--goal", "10.0", "8.0"});
  ASSERT_TRUE(await("both goals ended", [&] {
    goals.poll();
    return ended(of(goals, "r1")) && ended(of(goals, "r2"));
  }, 120s));
  states.poll();
  for (const std::string r : {"r1", "r2"}) EXPECT_EQ(of(goals, r).back().state, GoalState::Reached) << r << ": " << states_text(of(goals, r));
  bool gave_way = false;
  for (const auto& g : of(goals, "r2")) gave_way |= g.reason == "giving way to r1";
  EXPECT_TRUE(gave_way) << states_text(of(goals, "r2"));
  const Contact c = contacts(states.all());
  EXPECT_GE(c.closest_m, 0.6 + 0.01) << c.where;
  EXPECT_EQ(c.collisions, 0);
}

// r2 stands in the hallway where the courier's lookouts are (0.6 m off the south wall, beside
// A-120's door) with nothing to do; r1 comes along the same side of the hallway from the east and
// must pass it: it plans around the standing robot (1 m is left beside it) instead of driving up
// to it until its brake stalls it ("no progress for 10 s", as in the courier fleet's day).
TEST_F(TrafficTest, ARobotStandingInTheHallwayIsDrivenAround) {
  join(107);
  Recorder<msg::RobotState> states(participant(), dds::topics::robot_state);
  Recorder<msg::GoalStatus> goals(participant(), dds::topics::goal_status);
  start_simulator({"--config", kOffice, "--without-robots", "--wait-for", "behavior/r1", "behavior/r2"});
  start_behavior("r2", {"--start", "12.8", "7.6", "0"});
  start_behavior("r1", {"--start", "22.0", "7.6", "3.14", "--goal", "4.0", "7.6"});
  ASSERT_TRUE(await("r1's goal ended", [&] {
    goals.poll();
    return ended(of(goals, "r1"));
  }, 120s));
  states.poll();
  EXPECT_EQ(of(goals, "r1").back().state, GoalState::Reached) << states_text(of(goals, "r1"));
  for (const auto& g : of(goals, "r1")) EXPECT_EQ(g.reason.find("no progress"), std::string::npos) << g.reason;
  const Contact c = contacts(states.all());
  EXPECT_GE(c.closest_m, 0.6 + 0.01) << c.where;
  EXPECT_EQ(c.collisions, 0);
}

// r1 stands in A-114's doorway, alive with nothing to do, or killed there; r2 in A-114 is sent
// to the hallway. A-114 has no other door: r2's goal ends Blocked within the test's bound, the
// reason naming r1 and the doorway, and r2 never touches r1.
class TrafficDoorwayTest : public TrafficTest {
 protected:
  void run(int domain, bool kill) {
    join(domain);
    Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
    Recorder<msg::RobotState> states(participant(), dds::topics::robot_state);
    Recorder<msg::GoalStatus> goals(participant(), dds::topics::goal_status);
    dds::Topic<msg::NavGoal> goal_topic(participant(), dds::topics::nav_goal);
    dds::Writer<msg::NavGoal> goal_writer(participant(), goal_topic);
    start_simulator({"--config", kOffice, "--without-robots", "--wait-for", "behavior/r1", "behavior/r2",
                     "--ack-timeout", "2"});
    auto& r1 = start_behavior("r1", {"--start", "17.6", "7.0", "1.57"});
    auto& r2 = start_behavior("r2", {"--start", "17.6", "3.0", "1.57"});
    ASSERT_TRUE(await_ready(beats, r1));
    ASSERT_TRUE(await_ready(beats, r2));
    if (kill) {
      stop_watching(r1);
      r1.signal(SIGKILL);
      ASSERT_TRUE(r1.wait_for_exit(10s));
    }
    ASSERT_TRUE(goal_writer.wait_for_readers(kill ? 1 : 2, kDeadline));
    goal_writer.write({"r2", "out", 17.6, 8.3, 0.0, ""});
    ASSERT_TRUE(await("r2's goal ended", [&] {
      goals.poll();
      return ended(of(goals, "r2"));
    }, 120s));
    const auto v = of(goals, "r2");
    ASSERT_EQ(v.back().state, GoalState::Blocked) << states_text(v);
    // Killed with nothing to do, r1 is parked by its last itinerary until that ages 2 s of sim
    // time ("(parked)" or "(no itinerary for ...)"): either way it holds nothing.
    EXPECT_NE(v.back().reason.find("robot r1 ("), std::string::npos) << v.back().reason;
    EXPECT_NE(v.back().reason.find("in doorway A-114"), std::string::npos) << v.back().reason;
    states.poll();
    EXPECT_GE(contacts(states.all()).closest_m, 0.6 - 1e-6);
  }
};

TEST_F(TrafficDoorwayTest, ARobotParkedInTheOnlyDoorwayBlocksWithAReason) { run(50, false); }

TEST_F(TrafficDoorwayTest, ARobotKilledInTheOnlyDoorwayBlocksWithAReason) { run(51, true); }

// r1 drives out of A-114 through its doorway and is killed (SIGKILL) in it, holding the passage;
// the lockstep world waits for its ack, so it dies where it was seen (the robots drive at 0.1 m/s
// here, so that the test sees r1 in the doorway's box before it has left it). r2, in A-114, is then sent
// to the hallway: it first waits for r1 (fresh itinerary), then, once r1's itinerary aged past
// the expiry, ends Blocked naming r1 and the doorway instead of waiting for ever.
TEST_F(TrafficDoorwayTest, ARobotKilledDrivingThroughTheOnlyDoorwayBlocksWithAReason) {
  join(105);
  Recorder<msg::RobotState> states(participant(), dds::topics::robot_state);
  Recorder<msg::GoalStatus> goals(participant(), dds::topics::goal_status);
  dds::Topic<msg::NavGoal> goal_topic(participant(), dds::topics::nav_goal);
  dds::Writer<msg::NavGoal> goal_writer(participant(), goal_topic);
  std::string slow = read_file(kOffice);
  for (std::size_t at = slow.find("max_speed: 0.9"); at != std::string::npos; at = slow.find("max_speed: 0.9", at))
    slow.replace(at, 14, "max_speed: 0.1");
  const std::string scenario = dir().file("office-slow.pbtxt");
  write_file(scenario, slow);
  start_simulator({"--config", scenario, "--without-robots", "--wait-for", "behavior/r1", "behavior/r2",
                   "--ack-timeout", "2"});
  auto& r1 = start_behavior("r1", {"--config", scenario, "--start", "17.6", "4.0", "1.57", "--goal", "17.6", "8.3"});
  start_behavior("r2", {"--config", scenario, "--start", "19.5", "3.0", "1.57"});
  // Polled every millisecond: r1 is in the doorway's box (y 6.3 ... 7.7) for about 140 ticks.
  double r1_y = 0.0;
  const auto give_up = std::chrono::steady_clock::now() + 60s;
  while (r1_y < 6.6 && std::chrono::steady_clock::now() < give_up) {
    for (const auto& s : states.poll())
      if (s.robot_id == "r1") r1_y = s.y;
    std::this_thread::sleep_for(1ms);
  }
  ASSERT_GE(r1_y, 6.6) << "r1 never reached the doorway";
  stop_watching(r1);
  r1.signal(SIGKILL);
  ASSERT_TRUE(r1.wait_for_exit(10s));
  ASSERT_TRUE(goal_writer.wait_for_readers(1, kDeadline));
  goal_writer.write({"r2", "out", 20.5, 8.0, 0.0, ""});
  ASSERT_TRUE(await("r2's goal ended", [&] {
    goals.poll();
    return ended(of(goals, "r2"));
  }, 120s));
  states.poll();
  for (const auto& s : states.all())
    if (s.robot_id == "r1") r1_y = s.y;
  ASSERT_GT(r1_y, 6.3);  // r1 died in the box: the case this test is about
  ASSERT_LT(r1_y, 7.7);
  const auto v = of(goals, "r2");
  ASSERT_EQ(v.back().state, GoalState::Blocked) << states_text(v);
  EXPECT_NE(v.back().reason.find("robot r1 ("), std::string::npos) << v.back().reason;
  EXPECT_NE(v.back().reason.find("in doorway A-114"), std::string::npos) << v.back().reason;
  EXPECT_GE(contacts(states.all()).closest_m, 0.6 - 1e-6);
}

}  // namespace
}  // namespace autonomy::test
