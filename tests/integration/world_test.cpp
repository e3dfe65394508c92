// Integration tests of the simulator's world v2 over DDS: doors (ground truth, door commands,
// perception), the radio (links, team connectivity) and team messages relayed through it, with
// the real simulator and behavior processes and this test's own participant. Scenario files are
// written by each test into its own folder.
//
//   domain  test
//   ------  -----------------------------------------------
//     71    WorldTest.ClosedDoorStopsRobotUntilOpened
//     72    WorldTest.RadioLinkLostBehindBuildingAndRegained
//     73    WorldTest.TeamMessagesDroppedWhileDisconnected
//     74    WorldTest.OfficeLoadAtADeskWithThePersonPresentCompletes
//     75    WorldTest.OfficeRequestsNobodyCanServeAreRejectedWithReasons
//     76    WorldTest.DoorSeenClosedIsAvoidedThroughAnotherDoor
// (ctest names them integration.<suite>.<test>.)
#include "tests/support/process_test.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <list>
#include <memory>
#include <sstream>

namespace autonomy::test {
namespace {

using namespace std::chrono_literals;
using msg::GoalState;

enum Domain : int {
  kDomainDoor = 71,
  kDomainRadio = 72,
  kDomainTeamMessages = 73,
  kDomainOfficeLoad = 74,
  kDomainOfficeRejected = 75,
  kDomainDoorDetour = 76,
};

// Both door worlds: r1 on the west side at (2, 3), seeing doors within 4 m; lockstep.
constexpr const char* kDoorSensingRobot = R"pb(
robots {
  id: "r1"
  kinematics: HOLONOMIC
  radius: 0.3
  max_speed: 1.0
  max_omega: 2.0
  start { x: 2.0 y: 3.0 theta: 0.0 }
  spawn_at_start: true
  sensors {
    range { rays: 16 max_range_m: 6.0 }
    doors { range_m: 4.0 }
  }
}
simulation { mode: LOCKSTEP step_s: 0.05 seed: 3 }
)pb";

// A corridor split by a wall at x = 10 whose only opening is door d1 (closed at the start). The
// door swings clockwise, into the east room, away from a robot waiting on the west side.
const std::string kDoorScenario = std::string(R"pb(
name: "door-corridor"
world {
  width: 20.0
  height: 6.0
  obstacles { min_x: 9.9 min_y: 0.0 max_x: 10.1 max_y: 2.2 }
  obstacles { min_x: 9.9 min_y: 3.8 max_x: 10.1 max_y: 6.0 }
}
rooms { name: "west" }
rooms { name: "east" }
doors {
  id: "d1"
  position { x: 10.0 y: 3.0 }
  width: 1.6
  heading: 1.5707963267948966
  swing: CLOCKWISE
  rooms: "west"
  rooms: "east"
  angle: 0.0
}
)pb") + kDoorSensingRobot;

// A building between r1 (parked at (3, 10)) and the far side (25, 10); walls take 60 dB each, so
// a link through the building is lost while the open distance alone keeps it.
constexpr const char* kRadioScenario = R"pb(
name: "radio-shadow"
world {
  width: 30.0
  height: 20.0
  obstacles { min_x: 10.0 min_y: 4.0 max_x: 20.0 max_y: 16.0 }
}
robots {
  id: "r1"
  kinematics: HOLONOMIC
  start { x: 3.0 y: 10.0 theta: 0.0 }
  spawn_at_start: true
}
robots {
  id: "r2"
  kinematics: HOLONOMIC
  start { x: 6.0 y: 10.0 theta: 0.0 }
  spawn_at_start: true
}
radio { wall_loss_db: 60.0 }
simulation { mode: LOCKSTEP step_s: 0.05 seed: 5 }
)pb";

constexpr double kBehindX = 25.0, kBehindY = 10.0;  // r2's goal behind the building
constexpr double kHomeX = 6.0, kHomeY = 10.0;       // and back

class WorldTest : public ProcessTest {
 protected:
  ChildProcess& start_simulator(const std::string& scenario_file, std::vector<std::string> args) {
    args.insert(args.end(), {"--config", scenario_file, "--log-level", "debug"});
    return ProcessTest::start_simulator(args);
  }
  // The behavior takes the map from the simulator (autonomy/map), not from the scenario file.
  ChildProcess& start_behavior(const std::string& robot) { return ProcessTest::start_behavior(robot); }
};

::testing::AssertionResult send_goal(const dds::Writer<msg::NavGoal>& writer, const std::string& robot,
                                     const std::string& goal_id, double x, double y) {
  if (!writer.wait_for_readers(1, kDeadline))
    return ::testing::AssertionFailure() << "no reader of autonomy/nav/goal";
  msg::NavGoal goal;
  goal.robot_id = robot;
  goal.goal_id = goal_id;
  goal.x = x;
  goal.y = y;
  writer.write(goal);
  return ::testing::AssertionSuccess();
}

std::optional<msg::RobotState> last_state_of(const Recorder<msg::RobotState>& r, const std::string& robot) {
  std::optional<msg::RobotState> last;
  for (const auto& s : r.all())
    if (s.robot_id == robot && (!last || s.tick >= last->tick)) last = s;
  return last;
}

std::optional<GoalState> last_goal_state(const Recorder<msg::GoalStatus>& r, const std::string& goal_id) {
  std::optional<GoalState> last;
  for (const auto& s : r.all())
    if (s.goal_id == goal_id) last = s.state;
  return last;
}

bool ended(std::optional<GoalState> s) { return s && *s != GoalState::Accepted && *s != GoalState::Active; }

// The connected flags of the r1-r2 link, in order, with repeats collapsed.
std::vector<bool> link_history(const Recorder<msg::RadioLink>& links) {
  std::vector<bool> out;
  for (const auto& l : links.all()) {
    if (l.robot_a != "r1" || l.robot_b != "r2") continue;
    if (out.empty() || out.back() != l.connected) out.push_back(l.connected);
  }
  return out;
}

std::string text(const std::vector<bool>& v) {
  std::string out;
  for (bool b : v) out += std::string(out.empty() ? "" : " -> ") + (b ? "connected" : "disconnected");
  return out.empty() ? "(none)" : out;
}

// One room with two desks. The run starts at 09:00: Anna is in (all day), Bob only from 14:00.
// r1 starts at Bob's desk.
constexpr const char* kOfficeScenario = R"pb(
name: "office-handover"
world { width: 20.0 height: 8.0 }
rooms { name: "A-1" bounds { min_x: 0 min_y: 0 max_x: 20 max_y: 8 } }
places { name: "anna-desk" room: "A-1" position { x: 12.0 y: 4.0 } radius: 0.6 }
places { name: "bob-desk" room: "A-1" position { x: 3.0 y: 6.0 } }
day_start: "09:00"
people {
  name: "Anna"
  desk: "anna-desk"
  presence { start: "08:00" end: "18:00" }
  handover_time { fixed_s: 2.5 }
}
people {
  name: "Bob"
  desk: "bob-desk"
  presence { start: "14:00" end: "18:00" }
}
objects { id: "letter-1" kind: "letter" colour: "red" place: "anna-desk" }
objects { id: "book-1" kind: "book" colour: "green" place: "bob-desk" }
objects { id: "envelope-1" kind: "envelope" colour: "white" place: "anna-desk" }
robots {
  id: "r1"
  kinematics: HOLONOMIC
  start { x: 3.0 y: 6.0 theta: 0.0 }
  spawn_at_start: true
  capacity: 1
}
simulation { mode: LOCKSTEP step_s: 0.05 seed: 11 }
)pb";

msg::HandoverRequest handover(const std::string& id, const std::string& robot, msg::HandoverKind kind,
                              const std::string& place, const std::string& object) {
  return {id, "world_test", robot, kind, place, object};
}

std::vector<msg::HandoverStatus> answers_to(const Recorder<msg::HandoverStatus>& r, const std::string& request_id) {
  return r.matching([&](const msg::HandoverStatus& s) { return s.request_id == request_id; });
}

std::optional<msg::ObjectState> last_object_state(const Recorder<msg::ObjectState>& r, const std::string& id) {
  std::optional<msg::ObjectState> last;
  for (const auto& o : r.all())
    if (o.object_id == id) last = o;
  return last;
}

// (a) A closed door stops a robot whose planner does not know about doors; opened by a door
// command, it lets the robot through to its goal. Also: perception and door ground truth.
TEST_F(WorldTest, ClosedDoorStopsRobotUntilOpened) {
  join(kDomainDoor);
  const std::string scenario = dir().file("door.pbtxt");
  write_file(scenario, kDoorScenario);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  Recorder<msg::RobotState> states(participant(), dds::topics::robot_state);
  Recorder<msg::GoalStatus> goals(participant(), dds::topics::goal_status);
  Recorder<msg::DoorState> doors(participant(), dds::topics::truth_door);
  Recorder<msg::RangeScan> scans(participant(), dds::topics::range_scan);
  Recorder<msg::DoorObservation> sightings(participant(), dds::topics::door_observation);
  Recorder<msg::CommandRejection> rejections(participant(), dds::topics::command_rejected);
  Recorder<msg::SimulatorStatus> sim_status(participant(), dds::topics::sim_status);
  dds::Topic<msg::NavGoal> goal_topic(participant(), dds::topics::nav_goal);
  dds::Writer<msg::NavGoal> goal_writer(participant(), goal_topic);
  dds::Topic<msg::DoorCommand> door_topic(participant(), dds::topics::door_command);
  dds::Writer<msg::DoorCommand> door_writer(participant(), door_topic);
  const auto poll_all = [&] {
    states.poll();
    goals.poll();
    doors.poll();
    scans.poll();
    sightings.poll();
    rejections.poll();
  };

  start_simulator(scenario, {"--wait-for", "behavior/r1"});
  auto& behavior = start_behavior("r1");
  ASSERT_TRUE(await_ready(beats, behavior));
  ASSERT_TRUE(await("door d1 ground truth: closed", [&] {
    poll_all();
    return !doors.all().empty();
  }));
  EXPECT_EQ(doors.all().front().door_id, "d1");
  EXPECT_TRUE(doors.all().front().closed);
  ASSERT_TRUE(send_goal(goal_writer, "r1", "through-door", 18.0, 3.0));

  // The robot heads for the doorway (doors are open until seen closed), sees d1 closed once within
  // its door sensor's 4 m, has no other way east and gives the goal up with the door as reason.
  ASSERT_TRUE(await("goal through-door blocked by the closed door", [&] {
    poll_all();
    return ended(last_goal_state(goals, "through-door"));
  }, 60s));
  const auto blocked = goals.matching([](const msg::GoalStatus& g) { return g.goal_id == "through-door"; }).back();
  EXPECT_EQ(blocked.state, GoalState::Blocked);
  EXPECT_EQ(blocked.reason, "no route to goal (18.00, 3.00): door d1 closed");
  const int64_t stopped_tick = last_state_of(states, "r1")->tick;
  // The world's own tick: with the robot standing and nothing to do, the ticks are quiet (not
  // published, idl/clock.idl), and the robot's last state is its state.
  ASSERT_TRUE(await("40 more ticks with the door closed", [&] {
    poll_all();
    sim_status.poll();
    return !sim_status.all().empty() && sim_status.all().back().tick >= stopped_tick + 40;
  }));
  for (const auto& s : states.all()) {
    if (s.robot_id != "r1") continue;
    ASSERT_LT(s.x, 10.0 - 0.025 - 0.3 + 1e-6) << "r1 passed the closed door at tick " << s.tick;
    ASSERT_FALSE(s.in_collision) << "r1 ran into the door it had seen closed, at tick " << s.tick;
  }
  const auto stopped = last_state_of(states, "r1");
  EXPECT_NEAR(stopped->vx, 0.0, 1e-9);
  EXPECT_NEAR(stopped->vy, 0.0, 1e-9);
  EXPECT_LE(std::hypot(stopped->x - 10.0, stopped->y - 3.0), 4.0 + 1e-6) << "stopped where it saw the door";
  // What r1 perceived: range scans every tick, and the door (closed) once within range.
  ASSERT_FALSE(scans.all().empty());
  EXPECT_EQ(scans.all().back().ranges.size(), 16u);
  EXPECT_EQ(scans.all().back().robot_id, "r1");
  ASSERT_FALSE(sightings.all().empty()) << "r1 never observed door d1";
  EXPECT_EQ(sightings.all().back().doors.at(0).door_id, "d1");
  EXPECT_NEAR(sightings.all().back().doors.at(0).angle_estimate, 0.0, 1e-9);

  // A bad door command is rejected with a reason; a good one opens the door.
  ASSERT_TRUE(door_writer.wait_for_readers(1, kDeadline));
  door_writer.write({"no-such-door", 1.0, "world_test"});
  ASSERT_TRUE(await("the rejection of the unknown door", [&] {
    poll_all();
    return !rejections.matching([](const msg::CommandRejection& r) {
                        return r.source == "world_test" && r.reason.find("no-such-door") != std::string::npos;
                      }).empty();
  }));
  door_writer.write({"d1", M_PI / 2, "world_test"});
  ASSERT_TRUE(await("door d1 ground truth: open", [&] {
    poll_all();
    return !doors.matching([](const msg::DoorState& d) { return d.door_id == "d1" && !d.closed; }).empty();
  }));

  // The robot, still in sensor range, sees the door open: a new goal goes through it.
  ASSERT_TRUE(await("r1 seeing d1 open", [&] {
    poll_all();
    return !sightings.all().empty() && sightings.all().back().doors.at(0).angle_estimate > 0.5;
  }));
  const std::string goal_id = "through-door-again";
  ASSERT_TRUE(send_goal(goal_writer, "r1", goal_id, 18.0, 3.0));
  ASSERT_TRUE(await("r1 through the door and at its goal", [&] {
    poll_all();
    return last_goal_state(goals, goal_id) == GoalState::Reached;
  }, 90s)) << "last goal state: "
           << (last_goal_state(goals, goal_id) ? msg::to_string(*last_goal_state(goals, goal_id)) : "none");
  const auto last = last_state_of(states, "r1");
  ASSERT_TRUE(last);
  EXPECT_GT(last->x, 17.0);
}

// A wall at x = 10 with two doorways: d1 at y = 3 (closed) on the straight way from r1 to its goal,
// d2 at y = 9 (open). Both swing into the east room; d2's open leaf lies along the wall north of
// its doorway, out of the way of a robot heading south-east (plans do not know door leaves).
const std::string kTwoDoorScenario = std::string(R"pb(
name: "two-doors"
world {
  width: 20.0
  height: 12.0
  obstacles { min_x: 9.9 min_y: 0.0 max_x: 10.1 max_y: 2.2 }
  obstacles { min_x: 9.9 min_y: 3.8 max_x: 10.1 max_y: 8.2 }
  obstacles { min_x: 9.9 min_y: 9.8 max_x: 10.1 max_y: 12.0 }
}
rooms { name: "west" }
rooms { name: "east" }
doors { id: "d1" position { x: 10.0 y: 3.0 } width: 1.6 heading: 1.5707963267948966 swing: CLOCKWISE
        rooms: "west" rooms: "east" angle: 0.0 }
doors { id: "d2" position { x: 10.0 y: 9.0 } width: 1.6 heading: -1.5707963267948966 swing: COUNTER_CLOCKWISE
        rooms: "west" rooms: "east" }
)pb") + kDoorSensingRobot;

// Navigation for other services: a door seen closed on the way is planned around; the goal stays
// active (no blocked status) and is reached through the other door.
TEST_F(WorldTest, DoorSeenClosedIsAvoidedThroughAnotherDoor) {
  join(kDomainDoorDetour);
  const std::string scenario = dir().file("two-doors.pbtxt");
  write_file(scenario, kTwoDoorScenario);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  Recorder<msg::RobotState> states(participant(), dds::topics::robot_state);
  Recorder<msg::GoalStatus> goals(participant(), dds::topics::goal_status);
  Recorder<msg::WorldMap> maps(participant(), dds::topics::world_map);
  dds::Topic<msg::NavGoal> goal_topic(participant(), dds::topics::nav_goal);
  dds::Writer<msg::NavGoal> goal_writer(participant(), goal_topic);
  const auto poll_all = [&] {
    states.poll();
    goals.poll();
    maps.poll();
  };

  start_simulator(scenario, {"--wait-for", "behavior/r1"});
  auto& behavior = start_behavior("r1");
  ASSERT_TRUE(await_ready(beats, behavior));
  // The map tells where the doors are (not whether they are open).
  ASSERT_TRUE(await("the map", [&] {
    poll_all();
    return !maps.all().empty();
  }));
  ASSERT_EQ(maps.all().back().doors.size(), 2u);
  EXPECT_EQ(maps.all().back().doors[0].id, "d1");
  EXPECT_DOUBLE_EQ(maps.all().back().doors[1].y, 9.0);

  ASSERT_TRUE(send_goal(goal_writer, "r1", "east", 18.0, 3.0));
  ASSERT_TRUE(await("goal east to end", [&] {
    poll_all();
    return ended(last_goal_state(goals, "east"));
  }, 90s));
  std::vector<GoalState> seen;
  for (const auto& g : goals.matching([](const msg::GoalStatus& g) { return g.goal_id == "east"; }))
    if (seen.empty() || seen.back() != g.state) seen.push_back(g.state);
  EXPECT_EQ(seen, (std::vector<GoalState>{GoalState::Accepted, GoalState::Active, GoalState::Reached}));

  bool passed_d2 = false;
  double closest_to_d1 = 1e9;
  for (const auto& s : states.all()) {
    if (s.robot_id != "r1") continue;
    EXPECT_FALSE(s.in_collision) << "tick " << s.tick;
    if (std::fabs(s.x - 10.0) < 0.3) passed_d2 = passed_d2 || s.y > 8.0;
    if (std::fabs(s.x - 10.0) < 0.3) {
      EXPECT_GT(s.y, 8.0) << "through d1's doorway at tick " << s.tick;
    }
    closest_to_d1 = std::min(closest_to_d1, std::hypot(s.x - 10.0, s.y - 3.0));
  }
  EXPECT_TRUE(passed_d2);
  // It set out for d1 (doors are open until seen) and turned away once it saw it closed.
  EXPECT_LT(closest_to_d1, 4.0);
  EXPECT_GT(closest_to_d1, 1.0);
  const auto last = last_state_of(states, "r1");
  EXPECT_LE(std::hypot(last->x - 18.0, last->y - 3.0), 0.2 + 0.05);
}

// (b) r2 drives behind a building: its link to r1 is lost, and comes back as it returns. The run
// writes its metrics and a picture at exit.
TEST_F(WorldTest, RadioLinkLostBehindBuildingAndRegained) {
  join(kDomainRadio);
  const std::string scenario = dir().file("radio.pbtxt");
  write_file(scenario, kRadioScenario);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  Recorder<msg::GoalStatus> goals(participant(), dds::topics::goal_status);
  Recorder<msg::RadioLink> links(participant(), dds::topics::radio_link);
  Recorder<msg::TeamConnectivity> team(participant(), dds::topics::radio_team);
  dds::Topic<msg::NavGoal> goal_topic(participant(), dds::topics::nav_goal);
  dds::Writer<msg::NavGoal> goal_writer(participant(), goal_topic);
  const auto poll_all = [&] {
    goals.poll();
    links.poll();
    team.poll();
  };

  auto& simulator = start_simulator(scenario, {"--wait-for", "behavior/r2", "--metrics", dir().file("run"), "--svg",
                                               dir().file("run.svg")});
  auto& behavior = start_behavior("r2");
  ASSERT_TRUE(await_ready(beats, behavior));
  ASSERT_TRUE(await("the r1-r2 link, connected", [&] {
    poll_all();
    return link_history(links) == std::vector<bool>{true};
  }));
  ASSERT_TRUE(await("a connected team", [&] {
    poll_all();
    return !team.all().empty() && team.all().back().fully_connected;
  }));

  ASSERT_TRUE(send_goal(goal_writer, "r2", "behind", kBehindX, kBehindY));
  ASSERT_TRUE(await("r2 behind the building", [&] {
    poll_all();
    return ended(last_goal_state(goals, "behind"));
  }, 90s));
  ASSERT_EQ(last_goal_state(goals, "behind"), GoalState::Reached);
  ASSERT_TRUE(await("the r1-r2 link lost", [&] {
    poll_all();
    return link_history(links) == std::vector<bool>{true, false};
  })) << text(link_history(links));
  EXPECT_FALSE(team.all().back().fully_connected);
  EXPECT_EQ(team.all().back().components.size(), 2u);

  ASSERT_TRUE(send_goal(goal_writer, "r2", "home", kHomeX, kHomeY));
  ASSERT_TRUE(await("r2 back home", [&] {
    poll_all();
    return ended(last_goal_state(goals, "home"));
  }, 90s));
  ASSERT_TRUE(await("the r1-r2 link regained", [&] {
    poll_all();
    return link_history(links) == std::vector<bool>{true, false, true};
  })) << text(link_history(links));
  EXPECT_TRUE(team.all().back().fully_connected);

  // At exit: metrics (both robots and the team) and a picture.
  stop_watching(simulator);
  stop_watching(behavior);
  simulator.signal(SIGINT);
  const auto status = simulator.wait_for_exit(20s);
  ASSERT_TRUE(status) << "the simulator did not stop";
  EXPECT_TRUE(status->exited && status->code == 0) << status->describe();
  const std::string csv = read_file(dir().file("run.csv"));
  EXPECT_NE(csv.find("\nr1,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\nr2,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\nteam,"), std::string::npos) << csv;
  EXPECT_NE(read_file(dir().file("run.json")).find("\"robots\""), std::string::npos);
  EXPECT_NE(read_file(dir().file("run.svg")).find("<svg"), std::string::npos);
}

// (c) Team messages through the simulator's radio: delivered while r1 and r2 are connected,
// dropped (and counted) while the building is between them.
TEST_F(WorldTest, TeamMessagesDroppedWhileDisconnected) {
  join(kDomainTeamMessages);
  const std::string scenario = dir().file("radio.pbtxt");
  write_file(scenario, kRadioScenario);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  Recorder<msg::GoalStatus> goals(participant(), dds::topics::goal_status);
  Recorder<msg::RadioLink> links(participant(), dds::topics::radio_link);
  Recorder<msg::TeamDelivery> inbox(participant(), dds::topics::team_inbox);
  Recorder<msg::SimulatorStatus> sim_status(participant(), dds::topics::sim_status);
  dds::Topic<msg::NavGoal> goal_topic(participant(), dds::topics::nav_goal);
  dds::Writer<msg::NavGoal> goal_writer(participant(), goal_topic);
  dds::Topic<msg::TeamMessage> outbox_topic(participant(), dds::topics::team_outbox);
  dds::Writer<msg::TeamMessage> outbox(participant(), outbox_topic);
  const auto poll_all = [&] {
    goals.poll();
    links.poll();
    inbox.poll();
    sim_status.poll();
  };
  const auto delivered = [&](const std::string& id) {
    return inbox.matching([&](const msg::TeamDelivery& d) { return d.message_id == id; });
  };

  start_simulator(scenario, {"--wait-for", "behavior/r2"});
  auto& behavior = start_behavior("r2");
  ASSERT_TRUE(await_ready(beats, behavior));
  ASSERT_TRUE(await("the r1-r2 link, connected", [&] {
    poll_all();
    return link_history(links) == std::vector<bool>{true};
  }));
  ASSERT_TRUE(outbox.wait_for_readers(1, kDeadline));

  outbox.write({"r1", "r2", "hello-1", "while connected"});
  outbox.write({"r1", "*", "hello-all", "broadcast while connected"});
  ASSERT_TRUE(await("hello-1 and hello-all in r2's inbox", [&] {
    poll_all();
    return !delivered("hello-1").empty() && !delivered("hello-all").empty();
  }));
  const msg::TeamDelivery d = delivered("hello-1").front();
  EXPECT_EQ(d.recipient, "r2");
  EXPECT_EQ(d.from, "r1");
  EXPECT_EQ(d.payload, "while connected");
  EXPECT_EQ(d.hops, 1u);
  EXPECT_GE(d.delivered_time_ns, d.sent_time_ns);
  EXPECT_EQ(delivered("hello-all").front().to, "*");

  ASSERT_TRUE(send_goal(goal_writer, "r2", "behind", kBehindX, kBehindY));
  ASSERT_TRUE(await("r2 behind the building, link lost", [&] {
    poll_all();
    return ended(last_goal_state(goals, "behind")) && link_history(links) == std::vector<bool>{true, false};
  }, 90s)) << text(link_history(links));
  uint64_t dropped_before = 0;
  ASSERT_TRUE(await("a simulator status", [&] {
    poll_all();
    return !sim_status.all().empty();
  }));
  dropped_before = sim_status.all().back().team_messages_dropped_no_route;

  outbox.write({"r1", "r2", "lost-1", "while disconnected"});
  ASSERT_TRUE(await("the drop counted in autonomy/sim/status", [&] {
    poll_all();
    return sim_status.all().back().team_messages_dropped_no_route > dropped_before;
  }));
  // Give a delivery every chance to show up: it must not.
  const int64_t seen_at = sim_status.all().back().tick;
  ASSERT_TRUE(await("20 more ticks", [&] {
    poll_all();
    return sim_status.all().back().tick >= seen_at + 20;
  }));
  EXPECT_TRUE(delivered("lost-1").empty()) << "a message crossed the building";
  EXPECT_GE(sim_status.all().back().team_messages_delivered, 2u);
}

// (d) The office: r1 drives to Anna's desk, asks for the letter lying there, and gets it after
// Anna's handover time (2.5 s of simulated time); the object's ground truth then names r1.
TEST_F(WorldTest, OfficeLoadAtADeskWithThePersonPresentCompletes) {
  join(kDomainOfficeLoad);
  const std::string scenario = dir().file("office.pbtxt");
  write_file(scenario, kOfficeScenario);
  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  Recorder<msg::GoalStatus> goals(participant(), dds::topics::goal_status);
  Recorder<msg::RobotState> states(participant(), dds::topics::robot_state);
  Recorder<msg::HandoverStatus> answers(participant(), dds::topics::handover_status);
  Recorder<msg::ObjectState> objects(participant(), dds::topics::truth_object);
  dds::Topic<msg::NavGoal> goal_topic(participant(), dds::topics::nav_goal);
  dds::Writer<msg::NavGoal> goal_writer(participant(), goal_topic);
  dds::Topic<msg::HandoverRequest> request_topic(participant(), dds::topics::handover_request);
  dds::Writer<msg::HandoverRequest> requests(participant(), request_topic);
  const auto poll_all = [&] {
    goals.poll();
    states.poll();
    answers.poll();
    objects.poll();
  };

  start_simulator(scenario, {"--wait-for", "behavior/r1"});
  auto& behavior = start_behavior("r1");
  ASSERT_TRUE(await_ready(beats, behavior));
  ASSERT_TRUE(await("the ground truth of both objects", [&] {
    poll_all();
    return last_object_state(objects, "letter-1") && last_object_state(objects, "book-1");
  }));
  EXPECT_EQ(last_object_state(objects, "letter-1")->place, "anna-desk");
  EXPECT_EQ(last_object_state(objects, "letter-1")->carrier, "");
  EXPECT_EQ(last_object_state(objects, "letter-1")->kind, "letter");
  EXPECT_EQ(last_object_state(objects, "letter-1")->colour, "red");

  ASSERT_TRUE(send_goal(goal_writer, "r1", "to-anna", 12.0, 4.0));
  ASSERT_TRUE(await("r1 at Anna's desk", [&] {
    poll_all();
    return ended(last_goal_state(goals, "to-anna"));
  }, 90s));
  ASSERT_EQ(last_goal_state(goals, "to-anna"), GoalState::Reached);

  ASSERT_TRUE(requests.wait_for_readers(1, kDeadline));
  requests.write(handover("load-1", "r1", msg::HandoverKind::Load, "anna-desk", "letter-1"));
  ASSERT_TRUE(await("load-1 accepted, then finished", [&] {
    poll_all();
    const auto a = answers_to(answers, "load-1");
    return a.size() >= 2 || (a.size() == 1 && a[0].state == msg::HandoverState::Rejected);
  })) << answers_to(answers, "load-1").size() << " answers";
  const auto a = answers_to(answers, "load-1");
  ASSERT_EQ(a.size(), 2u);
  const msg::HandoverStatus& accepted = a[0];
  const msg::HandoverStatus& completed = a[1];
  ASSERT_EQ(accepted.state, msg::HandoverState::Accepted) << accepted.reason << ": " << accepted.detail;
  EXPECT_EQ(accepted.robot_id, "r1");
  EXPECT_EQ(accepted.kind, msg::HandoverKind::Load);
  EXPECT_EQ(accepted.place, "anna-desk");
  EXPECT_EQ(accepted.object_id, "letter-1");
  EXPECT_EQ(accepted.helper, "Anna");
  EXPECT_EQ(accepted.completes_at_ns - accepted.sim_time_ns, 2'500'000'000);
  ASSERT_EQ(completed.state, msg::HandoverState::Completed) << completed.reason << ": " << completed.detail;
  EXPECT_EQ(completed.reason, "");
  EXPECT_EQ(completed.helper, "Anna");
  EXPECT_EQ(completed.sim_time_ns, accepted.completes_at_ns);
  EXPECT_GT(completed.sim_time_ns, accepted.sim_time_ns);
  EXPECT_GT(completed.tick, accepted.tick);

  ASSERT_TRUE(await("letter-1 carried by r1 in the ground truth", [&] {
    poll_all();
    return last_object_state(objects, "letter-1")->carrier == "r1";
  }));
  EXPECT_EQ(last_object_state(objects, "letter-1")->place, "");
  EXPECT_EQ(last_object_state(objects, "letter-1")->tick, completed.tick);
  EXPECT_EQ(last_object_state(objects, "book-1")->place, "bob-desk");  // untouched

  // r1 can carry one object: a second load is refused, and the answer says why.
  requests.write(handover("load-2", "r1", msg::HandoverKind::Load, "anna-desk", "envelope-1"));
  ASSERT_TRUE(await("load-2 answered", [&] {
    poll_all();
    return !answers_to(answers, "load-2").empty();
  }));
  EXPECT_EQ(answers_to(answers, "load-2")[0].state, msg::HandoverState::Rejected);
  EXPECT_EQ(answers_to(answers, "load-2")[0].reason, "robot_full");
  EXPECT_EQ(answers_to(answers, "load-2")[0].detail, "robot r1 carries 1 objects, its capacity is 1");
}

// (e) Requests nobody can serve are rejected at once with their reason, and the simulator keeps
// running: nobody at Bob's desk at 09:00, r1 away from Anna's desk, an unknown robot, a malformed
// robot id. A repeated request id gets the same answer again.
TEST_F(WorldTest, OfficeRequestsNobodyCanServeAreRejectedWithReasons) {
  join(kDomainOfficeRejected);
  const std::string scenario = dir().file("office.pbtxt");
  write_file(scenario, kOfficeScenario);
  Recorder<msg::HandoverStatus> answers(participant(), dds::topics::handover_status);
  Recorder<msg::ObjectState> objects(participant(), dds::topics::truth_object);
  Recorder<msg::SimulatorStatus> sim_status(participant(), dds::topics::sim_status);
  dds::Topic<msg::HandoverRequest> request_topic(participant(), dds::topics::handover_request);
  dds::Writer<msg::HandoverRequest> requests(participant(), request_topic);
  const auto poll_all = [&] {
    answers.poll();
    objects.poll();
    sim_status.poll();
  };
  const auto only_answer = [&](const std::string& id) {
    const auto a = answers_to(answers, id);
    return a.empty() ? msg::HandoverStatus{} : a.front();
  };

  start_simulator(scenario, {});
  ASSERT_TRUE(requests.wait_for_readers(1, kDeadline));
  requests.write(handover("nobody", "r1", msg::HandoverKind::Load, "bob-desk", "book-1"));
  requests.write(handover("away", "r1", msg::HandoverKind::Load, "anna-desk", "letter-1"));
  requests.write(handover("ghost", "r9", msg::HandoverKind::Load, "anna-desk", "letter-1"));
  requests.write(handover("malformed", "r 1", msg::HandoverKind::Unload, "anna-desk", "letter-1"));
  ASSERT_TRUE(await("four answers", [&] {
    poll_all();
    return answers.all().size() >= 4;
  }));
  for (const auto& a : answers.all()) {
    EXPECT_EQ(a.state, msg::HandoverState::Rejected) << a.request_id;
    EXPECT_EQ(a.helper, "") << a.request_id;
    EXPECT_EQ(a.completes_at_ns, 0) << a.request_id;
  }
  EXPECT_EQ(only_answer("nobody").reason, "nobody_present");
  EXPECT_NE(only_answer("nobody").detail.find("nobody at bob-desk at 09:"), std::string::npos)
      << only_answer("nobody").detail;
  EXPECT_NE(only_answer("nobody").detail.find("(somebody is back at 14:00)"), std::string::npos)
      << only_answer("nobody").detail;
  EXPECT_EQ(only_answer("away").reason, "robot_not_at_place");
  EXPECT_NE(only_answer("away").detail.find("from anna-desk (must be within 0.6 m)"), std::string::npos)
      << only_answer("away").detail;
  EXPECT_EQ(only_answer("ghost").reason, "unknown_robot");
  EXPECT_EQ(only_answer("malformed").reason, "invalid_request");
  EXPECT_EQ(only_answer("malformed").kind, msg::HandoverKind::Unload);

  // Asked again: the same answer, nothing started.
  requests.write(handover("nobody", "r1", msg::HandoverKind::Load, "bob-desk", "book-1"));
  ASSERT_TRUE(await("the repeated answer", [&] {
    poll_all();
    return answers_to(answers, "nobody").size() == 2;
  }));
  EXPECT_EQ(answers_to(answers, "nobody")[1].reason, "nobody_present");
  EXPECT_EQ(answers_to(answers, "nobody")[1].sim_time_ns, answers_to(answers, "nobody")[0].sim_time_ns);

  // Still running, and nothing moved.
  ASSERT_TRUE(await("a simulator status", [&] {
    poll_all();
    return !sim_status.all().empty();
  }));
  const int64_t seen_at = sim_status.all().back().tick;
  ASSERT_TRUE(await("20 more ticks", [&] {
    poll_all();
    return sim_status.all().back().tick >= seen_at + 20;
  }));
  ASSERT_TRUE(last_object_state(objects, "book-1"));
  EXPECT_EQ(last_object_state(objects, "book-1")->place, "bob-desk");
  EXPECT_EQ(last_object_state(objects, "letter-1")->place, "anna-desk");
  EXPECT_EQ(answers.all().size(), 5u);
}

}  // namespace
}  // namespace autonomy::test
