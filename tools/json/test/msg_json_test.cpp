#include "tools/json/msg_json.hpp"
#include "common/test/test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace autonomy::json {
namespace {

// Values with every field off its default, so a dropped field shows as a failed comparison.
msg::Heartbeat heartbeat() { return {"simulator", "main", "host1", 4242, msg::ServiceState::Ready, 12.5, 500}; }
msg::SimClock sim_clock() { return {17, 1'700'000'000, 100'000'000, msg::ClockMode::Paced, 2.5}; }
msg::LockstepRegistration registration() { return {"behavior/r1", false}; }
msg::TickAck tick_ack() { return {"behavior/r1", 99, 3, 140}; }
msg::RobotState robot_state() {
  return {"r1", 5, 500, 1.5, -2.25, 0.5, 0.1, -0.2, 0.3, msg::Kinematics::Unicycle, 0.3, 1.2, 2.0, true};
}
msg::VelocityCommand velocity() { return {"r1", "behavior/r1", 7, 0.5, 0.0, -0.25}; }
msg::CommandRejection rejection() { return {"r2", "behavior/r2", 8, "vy must be 0 for a unicycle"}; }
msg::SpawnRequest spawn_request() { return {"q1", "tester", "r3", true, 1.0, 2.0, 3.0}; }
msg::SpawnReply spawn_reply() { return {"q1", "r3", msg::RequestStatus::Accepted, "ok"}; }
msg::WorldMap world_map() { return {"office", 60.0, 20.0, {{0, 0, 1, 1}, {2.5, 3.5, 4.5, 5.5}}}; }
msg::SimulatorStatus sim_status() { return {10, 1000, 2, {"behavior/r1", "behavior/r2"}, 40, 2, 1, 33.3}; }
msg::NavGoal nav_goal() { return {"r1", "g1", 17.0, 9.0, 0.25, "comm_attenuation"}; }
msg::GoalStatus goal_status() { return {"r1", "g1", msg::GoalState::Preempted, "new goal", 44, 3.75}; }

// Compares through the field table, so the test needs no operator== on the message types.
template <typename T>
void expect_round_trip(const T& value) {
  const Json j = to_json(value);
  const T back = from_json<T>(j);
  EXPECT_EQ(to_json(back), j) << j.dump();
  EXPECT_EQ(j.size(), field_names<T>().size()) << "every field is printed: " << j.dump();
  // Through text as well: what echo prints, pub reads.
  EXPECT_EQ(to_json(from_json<T>(parse(j.dump()))), j);
}

TEST(MsgJson, EveryTypeRoundTrips) {
  expect_round_trip(heartbeat());
  expect_round_trip(sim_clock());
  expect_round_trip(registration());
  expect_round_trip(tick_ack());
  expect_round_trip(robot_state());
  expect_round_trip(velocity());
  expect_round_trip(rejection());
  expect_round_trip(spawn_request());
  expect_round_trip(spawn_reply());
  expect_round_trip(world_map());
  expect_round_trip(sim_status());
  expect_round_trip(nav_goal());
  expect_round_trip(goal_status());
  expect_round_trip(test::make_range_scan(test::Variant::Full));
  expect_round_trip(test::make_pose_estimate(test::Variant::Full));
  expect_round_trip(test::make_door_observation(test::Variant::Full));
  expect_round_trip(test::make_door_state(test::Variant::Full));
  expect_round_trip(test::make_radio_link(test::Variant::Full));
  expect_round_trip(test::make_team_connectivity(test::Variant::Full));
  expect_round_trip(test::make_team_message(test::Variant::Full));
  expect_round_trip(test::make_team_delivery(test::Variant::Full));
  expect_round_trip(test::make_door_command(test::Variant::Full));
  expect_round_trip(test::make_handover_request(test::Variant::Full));
  expect_round_trip(test::make_handover_status(test::Variant::Full));
  expect_round_trip(test::make_object_state(test::Variant::Full));
}

TEST(MsgJson, EnumsAreLowerCaseNames) {
  EXPECT_EQ(to_json(heartbeat())["state"], "ready");
  EXPECT_EQ(to_json(robot_state())["kinematics"], "unicycle");
  EXPECT_EQ(to_json(sim_clock())["mode"], "paced");
  EXPECT_EQ(to_json(goal_status())["state"], "preempted");
  EXPECT_EQ(to_json(spawn_reply())["status"], "accepted");
}

TEST(MsgJson, MapShapesRoundTripWithRasterCellsDecoded) {
  msg::WorldMap m = world_map();
  m.polygons = {{"hall", {{1.0, 2.0}, {3.0, 2.0}, {2.0, 4.5}}}};
  m.rasters = {{"floor.yaml", -1.0, 0.5, 0.25, 3, 1, {0, 1, 1}}};
  const Json j = to_json(m);
  EXPECT_EQ(j["polygons"][0]["vertices"][2].dump(), R"({"x":2.0,"y":4.5})");
  EXPECT_EQ(j["rasters"][0]["blocked"].dump(), "[0,1,1]");
  const auto back = from_json<msg::WorldMap>(j);
  ASSERT_EQ(back.polygons.size(), 1u);
  EXPECT_EQ(back.polygons[0].vertices[2].y, 4.5);
  ASSERT_EQ(back.rasters.size(), 1u);
  EXPECT_EQ(back.rasters[0].blocked, (std::vector<uint8_t>{0, 1, 1}));
  EXPECT_EQ(back.rasters[0].origin_x, -1.0);
}

TEST(MsgJson, FieldsKeepTheirTypesAndOrder) {
  const Json j = to_json(world_map());
  EXPECT_EQ(j.dump(),
            R"({"name":"office","width":60.0,"height":20.0,"obstacles":[{"min_x":0.0,"min_y":0.0,"max_x":1.0,)"
            R"("max_y":1.0},{"min_x":2.5,"min_y":3.5,"max_x":4.5,"max_y":5.5}],"polygons":[],"rasters":[],"doors":[]})");
  EXPECT_TRUE(to_json(heartbeat())["pid"].is_number_integer());
  EXPECT_TRUE(to_json(robot_state())["in_collision"].is_boolean());
}

TEST(MsgJson, KeyJsonHasOnlyTheKeys) {
  EXPECT_EQ(key_json(heartbeat()), (Json{{"service", "simulator"}, {"instance", "main"}}));
  EXPECT_EQ(key_json(nav_goal()), (Json{{"robot_id", "r1"}}));
  EXPECT_EQ(key_json(sim_clock()), Json::object());
}

TEST(MsgJson, OmittedFieldsKeepDefaults) {
  const auto goal = from_json<msg::NavGoal>(parse(R"({"robot_id":"r1","goal_id":"g1","x":17,"y":9})"));
  EXPECT_EQ(goal.robot_id, "r1");
  EXPECT_EQ(goal.goal_id, "g1");
  EXPECT_DOUBLE_EQ(goal.x, 17.0);
  EXPECT_DOUBLE_EQ(goal.y, 9.0);
  EXPECT_DOUBLE_EQ(goal.tolerance, msg::NavGoal{}.tolerance);

  const auto clock = from_json<msg::SimClock>(Json::object());  // no key: everything optional
  EXPECT_DOUBLE_EQ(clock.warp, 1.0);
  EXPECT_EQ(clock.mode, msg::ClockMode::Lockstep);
}

TEST(MsgJson, NonFiniteDoublesRoundTripAsStrings) {
  msg::GoalStatus s = goal_status();
  s.distance_to_goal = std::numeric_limits<double>::infinity();
  const Json j = to_json(s);
  EXPECT_EQ(j["distance_to_goal"], "inf");
  EXPECT_TRUE(std::isinf(from_json<msg::GoalStatus>(j).distance_to_goal));
  s.distance_to_goal = std::nan("");
  EXPECT_TRUE(std::isnan(from_json<msg::GoalStatus>(to_json(s)).distance_to_goal));
}

TEST(MsgJson, IntegralFloatsAreIntegers) { EXPECT_EQ(from_json<msg::TickAck>(parse(R"({"tick":12.0})")).tick, 12); }

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const JsonError& e) {
    return e.what();
  }
  return "(no error)";
}

template <typename T>
std::string error_for(const std::string& text) {
  return error_of([&] { (void)from_json<T>(parse(text)); });
}

TEST(MsgJsonErrors, InvalidJson) {
  const std::string e = error_for<msg::NavGoal>(R"({"robot_id":"r1",)");
  EXPECT_EQ(e.rfind("invalid JSON: ", 0), 0u) << e;
}

TEST(MsgJsonErrors, NotAnObject) {
  EXPECT_EQ(error_for<msg::NavGoal>("[1,2]"), "NavGoal: expected an object, got an array");
}

TEST(MsgJsonErrors, MissingKeyField) {
  EXPECT_EQ(error_for<msg::NavGoal>(R"({"goal_id":"g1","x":1})"), "NavGoal: missing key field \"robot_id\"");
  EXPECT_EQ(error_for<msg::Heartbeat>(R"({"service":"simulator"})"), "Heartbeat: missing key field \"instance\"");
}

TEST(MsgJsonErrors, WrongTypeNamesTheField) {
  EXPECT_EQ(error_for<msg::NavGoal>(R"({"robot_id":"r1","x":"abc"})"),
            "NavGoal.x: expected a number, got string \"abc\"");
  EXPECT_EQ(error_for<msg::NavGoal>(R"({"robot_id":7})"), "NavGoal.robot_id: expected a string, got number 7");
  EXPECT_EQ(error_for<msg::RobotState>(R"({"robot_id":"r1","in_collision":1})"),
            "RobotState.in_collision: expected true or false, got number 1");
}

TEST(MsgJsonErrors, UnknownFieldListsTheFields) {
  EXPECT_EQ(error_for<msg::NavGoal>(R"({"robot_id":"r1","z":1})"),
            "NavGoal: unknown field \"z\" (fields of NavGoal: robot_id, goal_id, x, y, tolerance, constraint_set)");
}

TEST(MsgJsonErrors, EnumNames) {
  EXPECT_EQ(error_for<msg::Heartbeat>(R"({"service":"a","instance":"b","state":"READY"})"),
            "Heartbeat.state: expected one of starting, ready, stopping, got string \"READY\"");
}

TEST(MsgJsonErrors, IntegerRanges) {
  EXPECT_EQ(error_for<msg::TickAck>(R"({"commands_sent":-1})"),
            "TickAck.commands_sent: expected an integer in [0, 4294967295], got number -1");
  EXPECT_EQ(error_for<msg::TickAck>(R"({"tick":1.5})"),
            "TickAck.tick: expected an integer in [-9223372036854775808, 9223372036854775807], got number 1.5");
  EXPECT_EQ(error_for<msg::Heartbeat>(R"({"service":"a","instance":"b","pid":4294967296})"),
            "Heartbeat.pid: expected an integer in [-2147483648, 2147483647], got number 4294967296");
}

TEST(MsgJsonErrors, NestedPaths) {
  EXPECT_EQ(error_for<msg::WorldMap>(R"({"obstacles":[{"min_x":0},{"max_y":"x"}]})"),
            "WorldMap.obstacles[1].max_y: expected a number, got string \"x\"");
  EXPECT_EQ(error_for<msg::SimulatorStatus>(R"({"lockstep_participants":["a",2]})"),
            "SimulatorStatus.lockstep_participants[1]: expected a string, got number 2");
  EXPECT_EQ(error_for<msg::WorldMap>(R"({"obstacles":{}})"), "WorldMap.obstacles: expected an array, got an object");
}


TEST(MsgJson, SpacecraftTypesRoundTrip) {
  msg::SpacecraftTelemetry t;
  t.spacecraft = "ds1";
  t.tick = 3;
  t.devices = {{"adcs", "turning", "turn", "t-1", 2}};
  t.readings = {{"battery_soc", 0.75}};
  t.attitude.turn_target = "asteroid-1";
  t.propulsion.thrust_level = 6;
  t.camera.images_taken = 2;
  t.telecom.ground_station = "dss-14";
  t.storage.capacity_mb = 64;
  t.fault_protection = {true, "no command or heartbeat of executive for 600 s", 600, 1, 601.0, 600.0};
  t.commands_busy = 3;
  expect_round_trip(t);
  expect_round_trip(msg::SpacecraftEvent{"ds1", 601, 600, "safed", "ips to standby"});
  expect_round_trip(msg::SpacecraftCommandStatus{"c-2", "tool", "ips", "thrust", false, "busy: ...", 4, 9, true});
  expect_round_trip(msg::SpacecraftCommand{"c-1", "executive", 4, "ips", "thrust", {"6"}});
  expect_round_trip(msg::SpacecraftCommandStatus{"c-1", "executive", "ips", "thrust", false, "out of range", 4, 9});
  expect_round_trip(msg::SpacecraftFaultInjection{"f", "test", "failed", "lpe", 0.0, true, false});
  expect_round_trip(msg::SpacecraftFaultState{"f", "failed", "lpe", 0.0, true, "injected by test", "", 5});
  EXPECT_EQ(key_json(t), (Json{{"spacecraft", "ds1"}}));
}

}  // namespace
}  // namespace autonomy::json
