// The C <-> C++ conversions of every message (common/dds/conversions/*.cpp): to_c writes every
// field where the generated C type has it, from_c reads it back, enums map by name.
#include "common/dds/message_types.hpp"
#include "common/test/test_support.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace autonomy::dds {
namespace {

using test::fields;
using test::Variant;

template <typename T>
T round_trip(const T& value) {
  typename DdsType<T>::C c{};
  Arena arena;
  DdsType<T>::to_c(value, c, arena);
  return DdsType<T>::from_c(c);
}

template <typename T>
void expect_round_trip(const T& value) {
  EXPECT_EQ(fields(round_trip(value)), fields(value));
}

std::string str(const char* c) { return c ? std::string(c) : std::string("<null>"); }

// ---- round trips, both variants ----

TEST(ConversionsTest, HeartbeatRoundTrip) {
  expect_round_trip(test::make_heartbeat(Variant::Full));
  expect_round_trip(test::make_heartbeat(Variant::Empty));
}

TEST(ConversionsTest, SimClockRoundTrip) { expect_round_trip(test::make_sim_clock(Variant::Full)); }

TEST(ConversionsTest, LockstepRegistrationRoundTrip) {
  expect_round_trip(test::make_registration(Variant::Full));
  expect_round_trip(test::make_registration(Variant::Empty));
  auto active = test::make_registration(Variant::Full);
  active.active = true;
  expect_round_trip(active);
}

TEST(ConversionsTest, TickAckRoundTrip) {
  expect_round_trip(test::make_tick_ack(Variant::Full));
  expect_round_trip(test::make_tick_ack(Variant::Empty));
}

TEST(ConversionsTest, RobotStateRoundTrip) {
  expect_round_trip(test::make_robot_state(Variant::Full));
  expect_round_trip(test::make_robot_state(Variant::Empty));
}

TEST(ConversionsTest, VelocityCommandRoundTrip) {
  expect_round_trip(test::make_velocity_command(Variant::Full));
  expect_round_trip(test::make_velocity_command(Variant::Empty));
}

TEST(ConversionsTest, CommandRejectionRoundTrip) {
  expect_round_trip(test::make_command_rejection(Variant::Full));
  expect_round_trip(test::make_command_rejection(Variant::Empty));
}

TEST(ConversionsTest, SpawnRequestRoundTrip) {
  expect_round_trip(test::make_spawn_request(Variant::Full));
  expect_round_trip(test::make_spawn_request(Variant::Empty));
}

TEST(ConversionsTest, SpawnReplyRoundTrip) {
  expect_round_trip(test::make_spawn_reply(Variant::Full));
  expect_round_trip(test::make_spawn_reply(Variant::Empty));
}

TEST(ConversionsTest, WorldMapRoundTrip) {
  expect_round_trip(test::make_world_map(Variant::Full));
  expect_round_trip(test::make_world_map(Variant::Empty));
  auto one = test::make_world_map(Variant::Full);
  one.obstacles.resize(1);
  expect_round_trip(one);
}

TEST(ConversionsTest, WorldMapRastersTravelAsRunsThatAlternateFromFree) {
  autonomy_WorldMap c{};
  Arena arena;
  const auto value = test::make_world_map(Variant::Full);
  DdsType<msg::WorldMap>::to_c(value, c, arena);
  ASSERT_EQ(c.rasters._length, 2u);
  // 1 1 0 0 0 1 0 1 1 1 1 0 -> free 0, blocked 2, free 3, blocked 1, free 1, blocked 4, free 1.
  const std::vector<uint32_t> expected = {0, 2, 3, 1, 1, 4, 1};
  const auto& runs = c.rasters._buffer[0].runs;
  EXPECT_EQ(std::vector<uint32_t>(runs._buffer, runs._buffer + runs._length), expected);
  EXPECT_EQ(c.rasters._buffer[1].runs._length, 1u);  // all free: one run
  EXPECT_EQ(c.rasters._buffer[1].runs._buffer[0], 4u);
}

TEST(ConversionsTest, WorldMapRasterWhoseRunsDoNotCoverItArrivesEmpty) {
  // A sample that claims 1000 x 1000 cells but codes only 10 must not turn into a million
  // guessed cells; one whose runs overshoot is cut to its size.
  uint32_t short_runs[] = {4, 6};
  uint32_t long_runs[] = {1, 10};
  autonomy_MapRaster rasters[2] = {};
  rasters[0].name = const_cast<char*>("short");
  rasters[0].resolution = 1.0;
  rasters[0].cols = 1000;
  rasters[0].rows = 1000;
  rasters[0].runs = {2, 2, short_runs, false};
  rasters[1].name = const_cast<char*>("long");
  rasters[1].resolution = 1.0;
  rasters[1].cols = 2;
  rasters[1].rows = 2;
  rasters[1].runs = {2, 2, long_runs, false};
  autonomy_WorldMap c{};
  c.name = const_cast<char*>("m");
  c.rasters = {2, 2, rasters, false};
  const msg::WorldMap v = DdsType<msg::WorldMap>::from_c(c);
  ASSERT_EQ(v.rasters.size(), 2u);
  EXPECT_EQ(v.rasters[0].cols, 0u);
  EXPECT_TRUE(v.rasters[0].blocked.empty());
  EXPECT_EQ(v.rasters[1].blocked, (std::vector<uint8_t>{0, 1, 1, 1}));
}

TEST(ConversionsTest, WorldMapRasterBeyondTheCellLimitArrivesEmpty) {
  // 100,000 x 100,000 cells coded by three runs: 10 GB of cells if decoded.
  uint32_t runs[] = {4000000000u, 4000000000u, 2000000000u};
  autonomy_MapRaster raster{};
  raster.name = const_cast<char*>("huge");
  raster.resolution = 0.01;
  raster.cols = 100000;
  raster.rows = 100000;
  raster.runs = {3, 3, runs, false};
  autonomy_WorldMap c{};
  c.name = const_cast<char*>("m");
  c.rasters = {1, 1, &raster, false};
  const msg::WorldMap v = DdsType<msg::WorldMap>::from_c(c);
  ASSERT_EQ(v.rasters.size(), 1u);
  EXPECT_EQ(v.rasters[0].cols, 0u);
  EXPECT_TRUE(v.rasters[0].blocked.empty());
}

TEST(ConversionsTest, SimulatorStatusRoundTrip) {
  expect_round_trip(test::make_sim_status(Variant::Full));
  expect_round_trip(test::make_sim_status(Variant::Empty));
}

TEST(ConversionsTest, NavGoalRoundTrip) {
  expect_round_trip(test::make_nav_goal(Variant::Full));
  expect_round_trip(test::make_nav_goal(Variant::Empty));
}

TEST(ConversionsTest, GoalStatusRoundTrip) {
  expect_round_trip(test::make_goal_status(Variant::Full));
  expect_round_trip(test::make_goal_status(Variant::Empty));
}

TEST(ConversionsTest, NavCancelRoundTrip) {
  expect_round_trip(test::make_nav_cancel(Variant::Full));
  expect_round_trip(test::make_nav_cancel(Variant::Empty));
}

TEST(ConversionsTest, MissionStatusRoundTrip) {
  expect_round_trip(test::make_mission_status(Variant::Full));
  expect_round_trip(test::make_mission_status(Variant::Empty));
}

TEST(ConversionsTest, ItineraryRoundTrip) {
  expect_round_trip(test::make_itinerary(Variant::Full));
  expect_round_trip(test::make_itinerary(Variant::Empty));
}

TEST(ConversionsTest, WorldV2TypesRoundTrip) {
  for (const Variant v : {Variant::Full, Variant::Empty}) {
    expect_round_trip(test::make_range_scan(v));
    expect_round_trip(test::make_pose_estimate(v));
    expect_round_trip(test::make_door_observation(v));
    expect_round_trip(test::make_door_state(v));
    expect_round_trip(test::make_radio_link(v));
    expect_round_trip(test::make_team_connectivity(v));
    expect_round_trip(test::make_team_message(v));
    expect_round_trip(test::make_team_delivery(v));
    expect_round_trip(test::make_door_command(v));
  }
}

TEST(ConversionsTest, OfficeTypesRoundTrip) {
  for (const Variant v : {Variant::Full, Variant::Empty}) {
    expect_round_trip(test::make_handover_request(v));
    expect_round_trip(test::make_handover_status(v));
    expect_round_trip(test::make_object_state(v));
  }
}

TEST(ConversionsTest, CourierTypesRoundTrip) {
  for (const Variant v : {Variant::Full, Variant::Empty}) {
    expect_round_trip(test::make_courier_command(v));
    expect_round_trip(test::make_courier_reply(v));
    expect_round_trip(test::make_courier_job_status(v));
    expect_round_trip(test::make_courier_schedule(v));
    expect_round_trip(test::make_courier_report(v));
  }
  for (const msg::JobState state : {msg::JobState::Queued, msg::JobState::Underway, msg::JobState::Opportunistic,
                                    msg::JobState::Completed, msg::JobState::Failed, msg::JobState::Cancelled,
                                    msg::JobState::Stranded}) {
    msg::CourierJobStatus m;
    m.state = state;
    EXPECT_EQ(round_trip(m).state, state) << msg::to_string(state);
  }
  EXPECT_EQ(DdsType<msg::CourierJobStatus>::descriptor()->m_nkeys, 1u);  // job_id
  EXPECT_EQ(DdsType<msg::CourierSchedule>::descriptor()->m_nkeys, 1u);   // robot_id
  EXPECT_EQ(DdsType<msg::CourierReply>::descriptor()->m_nkeys, 0u);
  EXPECT_STREQ(DdsType<msg::CourierCommand>::type_name(), "autonomy::CourierCommand");
}

TEST(ConversionsTest, OfficeTypesToCFieldsKeysAndEnums) {
  {
    autonomy_HandoverRequest c{};
    Arena arena;
    const auto value = test::make_handover_request(Variant::Full);  // outlives c, which points into it
    DdsType<msg::HandoverRequest>::to_c(value, c, arena);
    EXPECT_EQ(str(c.request_id), test::kUtf8A);
    EXPECT_EQ(str(c.requester), test::kUtf8B);
    EXPECT_EQ(str(c.robot_id), test::kUtf8C);
    EXPECT_EQ(c.kind, autonomy_HANDOVER_UNLOAD);
    EXPECT_EQ(str(c.place), "michael-desk");
    EXPECT_EQ(str(c.object_id), "letter-1");
  }
  {
    autonomy_HandoverStatus c{};
    Arena arena;
    const auto value = test::make_handover_status(Variant::Full);  // outlives c, which points into it
    DdsType<msg::HandoverStatus>::to_c(value, c, arena);
    EXPECT_EQ(c.state, autonomy_HANDOVER_COMPLETED);
    EXPECT_EQ(str(c.reason), "robot_moved_away");
    EXPECT_EQ(str(c.helper), "Michael");
    EXPECT_EQ(c.sim_time_ns, 45'000'000'001);
    EXPECT_EQ(c.completes_at_ns, 45'000'000'002);
  }
  {
    autonomy_ObjectState c{};
    Arena arena;
    const auto value = test::make_object_state(Variant::Full);  // outlives c, which points into it
    DdsType<msg::ObjectState>::to_c(value, c, arena);
    EXPECT_EQ(str(c.object_id), test::kUtf8A);
    EXPECT_EQ(str(c.carrier), "rhino");
    EXPECT_EQ(c.tick, 1001);
  }
  for (const auto& [value, c] : {std::pair{msg::HandoverState::Accepted, autonomy_HANDOVER_ACCEPTED},
                                 std::pair{msg::HandoverState::Rejected, autonomy_HANDOVER_REJECTED},
                                 std::pair{msg::HandoverState::Completed, autonomy_HANDOVER_COMPLETED},
                                 std::pair{msg::HandoverState::Failed, autonomy_HANDOVER_FAILED}}) {
    msg::HandoverStatus m;
    m.state = value;
    EXPECT_EQ(round_trip(m).state, value);
    autonomy_HandoverStatus out{};
    Arena arena;
    DdsType<msg::HandoverStatus>::to_c(m, out, arena);
    EXPECT_EQ(out.state, c) << msg::to_string(value);
  }
  EXPECT_EQ(DdsType<msg::HandoverRequest>::descriptor()->m_nkeys, 0u);
  EXPECT_EQ(DdsType<msg::HandoverStatus>::descriptor()->m_nkeys, 0u);
  EXPECT_EQ(DdsType<msg::ObjectState>::descriptor()->m_nkeys, 1u);  // object_id
  EXPECT_STREQ(DdsType<msg::ObjectState>::type_name(), "autonomy::ObjectState");
}

TEST(ConversionsTest, WorldV2TypesToCFields) {
  {
    autonomy_RangeScan c{};
    Arena arena;
    const auto v = test::make_range_scan(Variant::Full);
    DdsType<msg::RangeScan>::to_c(v, c, arena);
    EXPECT_EQ(str(c.robot_id), test::kUtf8A);
    EXPECT_EQ(c.tick, 808);
    EXPECT_EQ(c.angle_min, -1.5);
    EXPECT_EQ(c.angle_increment, 0.0625);
    EXPECT_EQ(c.max_range, 7.5);
    ASSERT_EQ(c.ranges._length, 5u);
    EXPECT_EQ(c.ranges._buffer[2], 1.25f);
  }
  {
    autonomy_DoorObservation c{};
    Arena arena;
    const auto value = test::make_door_observation(Variant::Full);  // outlives c, which points into it
    DdsType<msg::DoorObservation>::to_c(value, c, arena);
    ASSERT_EQ(c.doors._length, 3u);
    EXPECT_EQ(str(c.doors._buffer[0].door_id), test::kUtf8C);
    EXPECT_EQ(c.doors._buffer[0].angle_estimate, 1.25);
    EXPECT_EQ(c.doors._buffer[0].distance, 2.5);
    EXPECT_EQ(c.doors._buffer[0].bearing, -0.75);
  }
  {
    autonomy_DoorState c{};
    Arena arena;
    const auto value = test::make_door_state(Variant::Full);  // outlives c, which points into it
    DdsType<msg::DoorState>::to_c(value, c, arena);
    EXPECT_EQ(c.angle, 0.625);
    EXPECT_EQ(c.target_angle, 1.5);
  }
  {
    autonomy_RadioLink c{};
    Arena arena;
    const auto value = test::make_radio_link(Variant::Full);  // outlives c, which points into it
    DdsType<msg::RadioLink>::to_c(value, c, arena);
    EXPECT_EQ(str(c.robot_a), test::kUtf8A);
    EXPECT_EQ(str(c.robot_b), test::kUtf8B);
    EXPECT_EQ(c.signal_dbm, -71.25);
    EXPECT_EQ(c.margin_db, 18.75);
  }
  {
    autonomy_TeamConnectivity c{};
    Arena arena;
    const auto value = test::make_team_connectivity(Variant::Full);  // outlives c, which points into it
    DdsType<msg::TeamConnectivity>::to_c(value, c, arena);
    ASSERT_EQ(c.components._length, 3u);
    ASSERT_EQ(c.components._buffer[0].robots._length, 2u);
    EXPECT_EQ(str(c.components._buffer[0].robots._buffer[1]), "r2");
    EXPECT_EQ(c.components._buffer[1].robots._length, 0u);
  }
  {
    autonomy_TeamDelivery c{};
    Arena arena;
    const auto value = test::make_team_delivery(Variant::Full);  // outlives c, which points into it
    DdsType<msg::TeamDelivery>::to_c(value, c, arena);
    EXPECT_EQ(str(c.recipient), test::kUtf8B);
    EXPECT_EQ(str(c.from), test::kUtf8A);
    EXPECT_EQ(str(c.to), "*");
    EXPECT_EQ(c.sent_time_ns, 900'000'000'001);
    EXPECT_EQ(c.delivered_time_ns, 900'003'000'002);
    EXPECT_EQ(c.hops, 3u);
  }
  {
    autonomy_DoorCommand c{};
    Arena arena;
    const auto value = test::make_door_command(Variant::Full);  // outlives c, which points into it
    DdsType<msg::DoorCommand>::to_c(value, c, arena);
    EXPECT_EQ(str(c.door_id), test::kUtf8C);
    EXPECT_EQ(c.angle, 1.375);
  }
}

TEST(ConversionsTest, WorldV2KeysAreTheDocumentedOnes) {
  EXPECT_EQ(DdsType<msg::RangeScan>::descriptor()->m_nkeys, 1u);
  EXPECT_EQ(DdsType<msg::RadioLink>::descriptor()->m_nkeys, 2u);  // robot_a, robot_b
  EXPECT_EQ(DdsType<msg::TeamConnectivity>::descriptor()->m_nkeys, 0u);
  EXPECT_EQ(DdsType<msg::TeamDelivery>::descriptor()->m_nkeys, 1u);
  EXPECT_STREQ(DdsType<msg::DoorState>::type_name(), "autonomy::DoorState");
  EXPECT_STREQ(DdsType<msg::TeamDelivery>::type_name(), "autonomy::TeamDelivery");
}

// ---- to_c puts each value in the C field of the same name (a swap in both directions would
// still round-trip) ----

TEST(ConversionsTest, HeartbeatToCFields) {
  const auto v = test::make_heartbeat(Variant::Full);
  autonomy_Heartbeat c{};
  Arena arena;
  DdsType<msg::Heartbeat>::to_c(v, c, arena);
  EXPECT_EQ(str(c.service), test::kUtf8A);
  EXPECT_EQ(str(c.instance), test::kUtf8B);
  EXPECT_EQ(str(c.host), test::kUtf8C);
  EXPECT_EQ(c.pid, 4242);
  EXPECT_EQ(c.state, autonomy_SERVICE_STOPPING);
  EXPECT_EQ(c.uptime_s, 12.75);
  EXPECT_EQ(c.period_ms, 333u);
}

TEST(ConversionsTest, ClockTypesToCFields) {
  {
    autonomy_SimClock c{};
    Arena arena;
    const auto value = test::make_sim_clock(Variant::Full);  // outlives c, which points into it
    DdsType<msg::SimClock>::to_c(value, c, arena);
    EXPECT_EQ(c.tick, 7'000'000'001);
    EXPECT_EQ(c.sim_time_ns, 123'456'789'012);
    EXPECT_EQ(c.step_ns, 20'000'001);
    EXPECT_EQ(c.mode, autonomy_CLOCK_PACED);
    EXPECT_EQ(c.warp, 2.5);
  }
  {
    autonomy_LockstepRegistration c{};
    c.active = true;
    Arena arena;
    const auto value = test::make_registration(Variant::Full);  // outlives c, which points into it
    DdsType<msg::LockstepRegistration>::to_c(value, c, arena);
    EXPECT_EQ(str(c.participant), test::kUtf8A);
    EXPECT_FALSE(c.active);
  }
  {
    autonomy_TickAck c{};
    Arena arena;
    const auto value = test::make_tick_ack(Variant::Full);  // outlives c, which points into it
    DdsType<msg::TickAck>::to_c(value, c, arena);
    EXPECT_EQ(str(c.participant), test::kUtf8B);
    EXPECT_EQ(c.tick, -5'000'000'003);
    EXPECT_EQ(c.commands_sent, 4'000'000'000u);
  }
}

TEST(ConversionsTest, RobotTypesToCFields) {
  {
    autonomy_RobotState c{};
    Arena arena;
    const auto value = test::make_robot_state(Variant::Full);  // outlives c, which points into it
    DdsType<msg::RobotState>::to_c(value, c, arena);
    EXPECT_EQ(str(c.robot_id), test::kUtf8A);
    EXPECT_EQ(c.tick, 101);
    EXPECT_EQ(c.sim_time_ns, 202'000'000'003);
    EXPECT_EQ(c.x, 1.25);
    EXPECT_EQ(c.y, -2.5);
    EXPECT_EQ(c.theta, 0.375);
    EXPECT_EQ(c.vx, 0.5);
    EXPECT_EQ(c.vy, -0.625);
    EXPECT_EQ(c.omega, 0.0625);
    EXPECT_EQ(c.kinematics, autonomy_KINEMATICS_UNICYCLE);
    EXPECT_EQ(c.radius, 0.3);
    EXPECT_EQ(c.max_speed, 1.75);
    EXPECT_EQ(c.max_omega, 2.25);
    EXPECT_TRUE(c.in_collision);
  }
  {
    autonomy_VelocityCommand c{};
    Arena arena;
    const auto value = test::make_velocity_command(Variant::Full);  // outlives c, which points into it
    DdsType<msg::VelocityCommand>::to_c(value, c, arena);
    EXPECT_EQ(str(c.robot_id), test::kUtf8A);
    EXPECT_EQ(str(c.source), test::kUtf8B);
    EXPECT_EQ(c.tick, 303);
    EXPECT_EQ(c.vx, 0.11);
    EXPECT_EQ(c.vy, -0.22);
    EXPECT_EQ(c.omega, 0.33);
  }
  {
    autonomy_CommandRejection c{};
    Arena arena;
    const auto value = test::make_command_rejection(Variant::Full);  // outlives c, which points into it
    DdsType<msg::CommandRejection>::to_c(value, c, arena);
    EXPECT_EQ(str(c.robot_id), test::kUtf8A);
    EXPECT_EQ(str(c.source), test::kUtf8B);
    EXPECT_EQ(c.tick, 404);
    EXPECT_EQ(str(c.reason), test::kUtf8C);
  }
}

TEST(ConversionsTest, SimulationTypesToCFields) {
  {
    autonomy_SpawnRequest c{};
    Arena arena;
    const auto value = test::make_spawn_request(Variant::Full);  // outlives c, which points into it
    DdsType<msg::SpawnRequest>::to_c(value, c, arena);
    EXPECT_EQ(str(c.request_id), test::kUtf8A);
    EXPECT_EQ(str(c.requester), test::kUtf8B);
    EXPECT_EQ(str(c.robot_id), test::kUtf8C);
    EXPECT_TRUE(c.has_pose);
    EXPECT_EQ(c.x, 3.5);
    EXPECT_EQ(c.y, -4.5);
    EXPECT_EQ(c.theta, -1.5);
  }
  {
    autonomy_SpawnReply c{};
    Arena arena;
    const auto value = test::make_spawn_reply(Variant::Full);  // outlives c, which points into it
    DdsType<msg::SpawnReply>::to_c(value, c, arena);
    EXPECT_EQ(str(c.request_id), test::kUtf8A);
    EXPECT_EQ(str(c.robot_id), test::kUtf8B);
    EXPECT_EQ(c.status, autonomy_REQUEST_ACCEPTED);
    EXPECT_EQ(str(c.reason), test::kUtf8C);
  }
  {
    autonomy_WorldMap c{};
    Arena arena;
    const auto value = test::make_world_map(Variant::Full);  // outlives c, which points into it
    DdsType<msg::WorldMap>::to_c(value, c, arena);
    EXPECT_EQ(str(c.name), test::kUtf8C);
    EXPECT_EQ(c.width, 40.5);
    EXPECT_EQ(c.height, 30.25);
    ASSERT_EQ(c.obstacles._length, 3u);
    EXPECT_GE(c.obstacles._maximum, c.obstacles._length);
    EXPECT_FALSE(c.obstacles._release);  // the arena owns the buffer, not Cyclone
    ASSERT_NE(c.obstacles._buffer, nullptr);
    EXPECT_EQ(c.obstacles._buffer[1].min_x, 5.5);
    EXPECT_EQ(c.obstacles._buffer[1].min_y, 6.5);
    EXPECT_EQ(c.obstacles._buffer[1].max_x, 7.5);
    EXPECT_EQ(c.obstacles._buffer[1].max_y, 8.5);
    EXPECT_EQ(c.obstacles._buffer[2].min_x, -1.0);
    EXPECT_EQ(c.obstacles._buffer[2].max_y, 0.25);
  }
  {
    autonomy_WorldMap c{};
    Arena arena;
    const auto value = test::make_world_map(Variant::Empty);  // outlives c, which points into it
    DdsType<msg::WorldMap>::to_c(value, c, arena);
    EXPECT_EQ(str(c.name), "");
    EXPECT_EQ(c.obstacles._length, 0u);
  }
  {
    autonomy_SimulatorStatus c{};
    Arena arena;
    const auto value = test::make_sim_status(Variant::Full);  // outlives c, which points into it
    DdsType<msg::SimulatorStatus>::to_c(value, c, arena);
    EXPECT_EQ(c.tick, 505);
    EXPECT_EQ(c.sim_time_ns, 606'000'000'007);
    EXPECT_EQ(c.robots, 3u);
    ASSERT_EQ(c.lockstep_participants._length, 4u);
    EXPECT_GE(c.lockstep_participants._maximum, c.lockstep_participants._length);
    EXPECT_FALSE(c.lockstep_participants._release);
    EXPECT_EQ(str(c.lockstep_participants._buffer[0]), test::kUtf8A);
    EXPECT_EQ(str(c.lockstep_participants._buffer[1]), "");
    EXPECT_EQ(str(c.lockstep_participants._buffer[2]), "behavior/r2");
    EXPECT_EQ(str(c.lockstep_participants._buffer[3]), test::kUtf8B);
    EXPECT_EQ(c.commands_applied, 10'000'000'000ull);
    EXPECT_EQ(c.commands_rejected, 11u);
    EXPECT_EQ(c.participants_dropped, 12u);
    EXPECT_EQ(c.mean_step_us, 45.5);
  }
}

TEST(ConversionsTest, NavigationTypesToCFields) {
  {
    autonomy_NavGoal c{};
    Arena arena;
    const auto value = test::make_nav_goal(Variant::Full);  // outlives c, which points into it
    DdsType<msg::NavGoal>::to_c(value, c, arena);
    EXPECT_EQ(str(c.robot_id), test::kUtf8A);
    EXPECT_EQ(str(c.goal_id), test::kUtf8B);
    EXPECT_EQ(c.x, 9.5);
    EXPECT_EQ(c.y, -8.25);
    EXPECT_EQ(c.tolerance, 0.125);
    EXPECT_EQ(str(c.constraint_set), test::kUtf8C);
  }
  {
    autonomy_GoalStatus c{};
    Arena arena;
    const auto value = test::make_goal_status(Variant::Full);  // outlives c, which points into it
    DdsType<msg::GoalStatus>::to_c(value, c, arena);
    EXPECT_EQ(str(c.robot_id), test::kUtf8A);
    EXPECT_EQ(str(c.goal_id), test::kUtf8B);
    EXPECT_EQ(c.state, autonomy_GOAL_PREEMPTED);
    EXPECT_EQ(str(c.reason), test::kUtf8C);
    EXPECT_EQ(c.tick, 707);
    EXPECT_EQ(c.distance_to_goal, 6.125);
  }
}

// Received samples may carry null strings (e.g. a key-only sample); they read as empty.
TEST(ConversionsTest, FromCReadsNullStringsAsEmpty) {
  autonomy_CommandRejection c{};
  c.tick = 9;
  const auto v = DdsType<msg::CommandRejection>::from_c(c);
  EXPECT_EQ(v.robot_id, "");
  EXPECT_EQ(v.source, "");
  EXPECT_EQ(v.reason, "");
  EXPECT_EQ(v.tick, 9);
}

// ---- enums: every enumerator maps to the C enumerator of the same name, both ways ----

template <typename T, typename E, typename CE>
void expect_enum_maps(T value, E T::*field, CE DdsType<T>::C::*c_field, E e, CE ce) {
  value.*field = e;
  typename DdsType<T>::C c{};
  Arena arena;
  DdsType<T>::to_c(value, c, arena);
  EXPECT_EQ(static_cast<long>(c.*c_field), static_cast<long>(ce)) << "C++ enumerator " << static_cast<int>(e);
  typename DdsType<T>::C in{};
  in.*c_field = ce;
  EXPECT_EQ(static_cast<int>(DdsType<T>::from_c(in).*field), static_cast<int>(e))
      << "C enumerator " << static_cast<long>(ce);
}

TEST(ConversionsTest, ServiceStateMapsByName) {
  using msg::ServiceState;
  const auto v = test::make_heartbeat(Variant::Full);
  const auto f = &msg::Heartbeat::state;
  const auto cf = &autonomy_Heartbeat::state;
  expect_enum_maps(v, f, cf, ServiceState::Starting, autonomy_SERVICE_STARTING);
  expect_enum_maps(v, f, cf, ServiceState::Ready, autonomy_SERVICE_READY);
  expect_enum_maps(v, f, cf, ServiceState::Stopping, autonomy_SERVICE_STOPPING);
}

TEST(ConversionsTest, ClockModeMapsByName) {
  const auto v = test::make_sim_clock(Variant::Full);
  expect_enum_maps(v, &msg::SimClock::mode, &autonomy_SimClock::mode, msg::ClockMode::Lockstep,
                   autonomy_CLOCK_LOCKSTEP);
  expect_enum_maps(v, &msg::SimClock::mode, &autonomy_SimClock::mode, msg::ClockMode::Paced, autonomy_CLOCK_PACED);
}

TEST(ConversionsTest, KinematicsMapsByName) {
  const auto v = test::make_robot_state(Variant::Full);
  const auto f = &msg::RobotState::kinematics;
  const auto cf = &autonomy_RobotState::kinematics;
  expect_enum_maps(v, f, cf, msg::Kinematics::Holonomic, autonomy_KINEMATICS_HOLONOMIC);
  expect_enum_maps(v, f, cf, msg::Kinematics::Unicycle, autonomy_KINEMATICS_UNICYCLE);
}

TEST(ConversionsTest, RequestStatusMapsByName) {
  const auto v = test::make_spawn_reply(Variant::Full);
  const auto f = &msg::SpawnReply::status;
  const auto cf = &autonomy_SpawnReply::status;
  expect_enum_maps(v, f, cf, msg::RequestStatus::Accepted, autonomy_REQUEST_ACCEPTED);
  expect_enum_maps(v, f, cf, msg::RequestStatus::Rejected, autonomy_REQUEST_REJECTED);
}

TEST(ConversionsTest, GoalStateMapsByName) {
  using msg::GoalState;
  const auto v = test::make_goal_status(Variant::Full);
  const auto f = &msg::GoalStatus::state;
  const auto cf = &autonomy_GoalStatus::state;
  expect_enum_maps(v, f, cf, GoalState::Accepted, autonomy_GOAL_ACCEPTED);
  expect_enum_maps(v, f, cf, GoalState::Active, autonomy_GOAL_ACTIVE);
  expect_enum_maps(v, f, cf, GoalState::Reached, autonomy_GOAL_REACHED);
  expect_enum_maps(v, f, cf, GoalState::Blocked, autonomy_GOAL_BLOCKED);
  expect_enum_maps(v, f, cf, GoalState::Preempted, autonomy_GOAL_PREEMPTED);
  expect_enum_maps(v, f, cf, GoalState::Rejected, autonomy_GOAL_REJECTED);
  expect_enum_maps(v, f, cf, GoalState::Cancelled, autonomy_GOAL_CANCELLED);
}

// ---- type names and descriptors ----

TEST(ConversionsTest, TypeNamesAreScopedIdlNames) {
  EXPECT_STREQ(DdsType<msg::Heartbeat>::type_name(), "autonomy::Heartbeat");
  EXPECT_STREQ(DdsType<msg::SimClock>::type_name(), "autonomy::SimClock");
  EXPECT_STREQ(DdsType<msg::LockstepRegistration>::type_name(), "autonomy::LockstepRegistration");
  EXPECT_STREQ(DdsType<msg::TickAck>::type_name(), "autonomy::TickAck");
  EXPECT_STREQ(DdsType<msg::RobotState>::type_name(), "autonomy::RobotState");
  EXPECT_STREQ(DdsType<msg::VelocityCommand>::type_name(), "autonomy::VelocityCommand");
  EXPECT_STREQ(DdsType<msg::CommandRejection>::type_name(), "autonomy::CommandRejection");
  EXPECT_STREQ(DdsType<msg::SpawnRequest>::type_name(), "autonomy::SpawnRequest");
  EXPECT_STREQ(DdsType<msg::SpawnReply>::type_name(), "autonomy::SpawnReply");
  EXPECT_STREQ(DdsType<msg::WorldMap>::type_name(), "autonomy::WorldMap");
  EXPECT_STREQ(DdsType<msg::SimulatorStatus>::type_name(), "autonomy::SimulatorStatus");
  EXPECT_STREQ(DdsType<msg::NavGoal>::type_name(), "autonomy::NavGoal");
  EXPECT_STREQ(DdsType<msg::GoalStatus>::type_name(), "autonomy::GoalStatus");
}

TEST(ConversionsTest, DescriptorsMatchTheCTypes) {
  EXPECT_EQ(DdsType<msg::RobotState>::descriptor(), &autonomy_RobotState_desc);
  EXPECT_EQ(DdsType<msg::RobotState>::descriptor()->m_size, sizeof(autonomy_RobotState));
  EXPECT_EQ(DdsType<msg::WorldMap>::descriptor()->m_size, sizeof(autonomy_WorldMap));
  EXPECT_EQ(DdsType<msg::Heartbeat>::descriptor()->m_nkeys, 2u);  // service, instance
  EXPECT_EQ(DdsType<msg::RobotState>::descriptor()->m_nkeys, 1u);
  EXPECT_EQ(DdsType<msg::SimClock>::descriptor()->m_nkeys, 0u);
}

}  // namespace
}  // namespace autonomy::dds
