#pragma once
// Shared by the tests of common/: sample values of every message (every field distinct and not
// its default), a field-wise view for comparing them, and the loopback DDS profile.
#include "common/msg/clock.hpp"
#include "common/msg/courier.hpp"
#include "common/msg/navigation.hpp"
#include "common/msg/office.hpp"
#include "common/msg/robot.hpp"
#include "common/msg/simulation.hpp"
#include "common/msg/perception.hpp"
#include "common/msg/radio.hpp"
#include "common/msg/truth.hpp"
#include "common/msg/system.hpp"

#include <array>
#include <chrono>
#include <cstdlib>
#include <functional>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

namespace autonomy::test {

// Strings used in the "full" variants: non-ASCII UTF-8 of several byte lengths.
inline const std::string kUtf8A = "r\xC3\xB6" "bot-\xE3\x83\xAD\xE3\x83\x9C";  // "röbot-ロボ"
inline const std::string kUtf8B = "\xF0\x9F\xA4\x96 source \xE2\x9C\x93";     // "🤖 source ✓"
inline const std::string kUtf8C = "Gr\xC3\xBC\xC3\x9F" "e \xCE\xB1\xCE\xB2";  // "Grüße αβ"

// Full: non-empty (non-ASCII) strings and sequences of several elements. Empty: every string
// and sequence empty, the other fields still distinct and non-default.
enum class Variant { Full, Empty };

inline std::string s(Variant v, const std::string& text) { return v == Variant::Full ? text : std::string(); }

inline msg::Heartbeat make_heartbeat(Variant v) {
  msg::Heartbeat m;
  m.service = s(v, kUtf8A);
  m.instance = s(v, kUtf8B);
  m.host = s(v, kUtf8C);
  m.pid = 4242;
  m.state = msg::ServiceState::Stopping;
  m.uptime_s = 12.75;
  m.period_ms = 333;
  if (v == Variant::Full) m.capabilities = {"courier", kUtf8C};
  m.world_id = 0x8000000000000001ULL;
  m.clock_samples_ignored = 17;
  m.detail = s(v, kUtf8A);
  return m;
}

inline msg::SimClock make_sim_clock(Variant) {
  msg::SimClock m;
  m.tick = 7'000'000'001;
  m.sim_time_ns = 123'456'789'012;
  m.step_ns = 20'000'001;
  m.mode = msg::ClockMode::Paced;
  m.warp = 2.5;
  m.world_id = 0xfedcba9876543210ULL;
  return m;
}

inline msg::LockstepRegistration make_registration(Variant v) {
  msg::LockstepRegistration m;
  m.participant = s(v, kUtf8A);
  m.active = false;  // default is true
  return m;
}

inline msg::TickAck make_tick_ack(Variant v) {
  msg::TickAck m;
  m.participant = s(v, kUtf8B);
  m.tick = -5'000'000'003;
  m.commands_sent = 4'000'000'000u;
  m.quiet_until_tick = 7'000'000'001;
  return m;
}

inline msg::RobotState make_robot_state(Variant v) {
  msg::RobotState m;
  m.robot_id = s(v, kUtf8A);
  m.tick = 101;
  m.sim_time_ns = 202'000'000'003;
  m.x = 1.25;
  m.y = -2.5;
  m.theta = 0.375;
  m.vx = 0.5;
  m.vy = -0.625;
  m.omega = 0.0625;
  m.kinematics = msg::Kinematics::Unicycle;
  m.radius = 0.3;
  m.max_speed = 1.75;
  m.max_omega = 2.25;
  m.in_collision = true;
  return m;
}

inline msg::VelocityCommand make_velocity_command(Variant v) {
  msg::VelocityCommand m;
  m.robot_id = s(v, kUtf8A);
  m.source = s(v, kUtf8B);
  m.tick = 303;
  m.vx = 0.11;
  m.vy = -0.22;
  m.omega = 0.33;
  return m;
}

inline msg::CommandRejection make_command_rejection(Variant v) {
  msg::CommandRejection m;
  m.robot_id = s(v, kUtf8A);
  m.source = s(v, kUtf8B);
  m.tick = 404;
  m.reason = s(v, kUtf8C);
  return m;
}

inline msg::SpawnRequest make_spawn_request(Variant v) {
  msg::SpawnRequest m;
  m.request_id = s(v, kUtf8A);
  m.requester = s(v, kUtf8B);
  m.robot_id = s(v, kUtf8C);
  m.has_pose = true;
  m.x = 3.5;
  m.y = -4.5;
  m.theta = -1.5;
  return m;
}

inline msg::SpawnReply make_spawn_reply(Variant v) {
  msg::SpawnReply m;
  m.request_id = s(v, kUtf8A);
  m.robot_id = s(v, kUtf8B);
  m.status = msg::RequestStatus::Accepted;  // default is Rejected
  m.reason = s(v, kUtf8C);
  return m;
}

inline msg::WorldMap make_world_map(Variant v) {
  msg::WorldMap m;
  m.name = s(v, kUtf8C);
  m.width = 40.5;
  m.height = 30.25;
  if (v == Variant::Full) {
    m.obstacles = {{1.0, 2.0, 3.0, 4.0}, {5.5, 6.5, 7.5, 8.5}, {-1.0, -2.0, 0.5, 0.25}};
    m.polygons = {{kUtf8A, {{1.0, 1.0}, {4.0, 1.5}, {2.0, 5.25}}}, {"", {}}};
    // First cell blocked (a leading empty run on the wire), runs of several lengths, last free.
    m.rasters = {{kUtf8B, -2.5, 3.0, 0.05, 4, 3, {1, 1, 0, 0, 0, 1, 0, 1, 1, 1, 1, 0}},
                 {"all free", 0.0, 0.0, 1.0, 2, 2, {0, 0, 0, 0}}};
    m.doors = {{kUtf8C, 10.0, 3.0, 1.6, 1.5707963267948966}, {"", -1.5, 0.0, 0.9, -3.0}};
  }
  return m;
}

inline msg::SimulatorStatus make_sim_status(Variant v) {
  msg::SimulatorStatus m;
  m.tick = 505;
  m.sim_time_ns = 606'000'000'007;
  m.robots = 3;
  if (v == Variant::Full) m.lockstep_participants = {kUtf8A, "", "behavior/r2", kUtf8B};
  m.commands_applied = 10'000'000'000ull;
  m.commands_rejected = 11;
  m.participants_dropped = 12;
  m.mean_step_us = 45.5;
  m.team_messages_delivered = 13;
  m.team_messages_dropped_no_route = 14;
  m.team_messages_dropped_lost = 15;
  m.team_messages_dropped_invalid = 16;
  if (v == Variant::Full) {
    m.lockstep_dropped = {"behavior/r2", kUtf8B};
    m.lockstep_changes = {{1, 40, "behavior/r2", true, "did not acknowledge tick 40 within 2 s"},
                          {2, 77, kUtf8A, false, ""}};
  }
  return m;
}

inline msg::NavGoal make_nav_goal(Variant v) {
  msg::NavGoal m;
  m.robot_id = s(v, kUtf8A);
  m.goal_id = s(v, kUtf8B);
  m.x = 9.5;
  m.y = -8.25;
  m.tolerance = 0.125;
  m.constraint_set = s(v, kUtf8C);
  return m;
}

inline msg::NavCancel make_nav_cancel(Variant v) {
  msg::NavCancel m;
  m.robot_id = s(v, kUtf8A);
  m.goal_id = s(v, kUtf8B);
  m.reason = s(v, kUtf8C);
  return m;
}

inline msg::MissionStatus make_mission_status(Variant v) {
  msg::MissionStatus m;
  m.robot_id = s(v, kUtf8A);
  m.mission = s(v, kUtf8B);
  m.state = s(v, kUtf8C);
  m.event = s(v, kUtf8A);
  m.reason = s(v, kUtf8B);
  m.finished = v == Variant::Full;
  m.tick = 808;
  return m;
}

inline msg::Itinerary make_itinerary(Variant v) {
  msg::Itinerary m;
  m.robot_id = s(v, kUtf8A);
  m.tick = 909;
  m.sim_time_ns = 90'900'000'000;
  m.radius = 0.3;
  m.x = 1.25;
  m.y = -2.5;
  if (v == Variant::Full) m.path = {{1.0, 2.0, 91'000'000'000}, {3.5, 4.25, 92'000'000'000}};
  m.passage = s(v, kUtf8B);
  m.claim = s(v, kUtf8C);
  m.request_time_ns = 90'000'000'000;
  m.waiting_for = s(v, kUtf8A);
  return m;
}

inline msg::GoalStatus make_goal_status(Variant v) {
  msg::GoalStatus m;
  m.robot_id = s(v, kUtf8A);
  m.goal_id = s(v, kUtf8B);
  m.state = msg::GoalState::Preempted;
  m.reason = s(v, kUtf8C);
  m.tick = 707;
  m.distance_to_goal = 6.125;
  return m;
}

// --- Simulator world v2: perception, ground truth, radio, team messages, door commands ---

inline msg::RangeScan make_range_scan(Variant v) {
  msg::RangeScan m;
  m.robot_id = s(v, kUtf8A);
  m.tick = 808;
  m.angle_min = -1.5;
  m.angle_increment = 0.0625;
  m.max_range = 7.5;
  if (v == Variant::Full) m.ranges = {0.5f, 7.5f, 1.25f, 0.0f, 3.75f};
  return m;
}

inline msg::PoseEstimate make_pose_estimate(Variant v) {
  msg::PoseEstimate m;
  m.robot_id = s(v, kUtf8B);
  m.tick = 809;
  m.x = 4.125;
  m.y = -3.5;
  m.theta = 2.75;
  return m;
}

inline msg::DoorObservation make_door_observation(Variant v) {
  msg::DoorObservation m;
  m.robot_id = s(v, kUtf8A);
  m.tick = 810;
  if (v == Variant::Full) m.doors = {{kUtf8C, 1.25, 2.5, -0.75}, {"", 0.0, 3.5, 3.0}, {"d-3", 0.5, 0.25, 0.125}};
  return m;
}

inline msg::DoorState make_door_state(Variant v) {
  msg::DoorState m;
  m.door_id = s(v, kUtf8C);
  m.tick = 811;
  m.angle = 0.625;
  m.target_angle = 1.5;
  m.closed = true;
  m.blocked = true;
  return m;
}

inline msg::RadioLink make_radio_link(Variant v) {
  msg::RadioLink m;
  m.robot_a = s(v, kUtf8A);
  m.robot_b = s(v, kUtf8B);
  m.tick = 812;
  m.signal_dbm = -71.25;
  m.margin_db = 18.75;
  m.connected = true;
  return m;
}

inline msg::TeamConnectivity make_team_connectivity(Variant v) {
  msg::TeamConnectivity m;
  m.tick = 813;
  if (v == Variant::Full) m.components = {{{kUtf8A, "r2"}}, {{}}, {{kUtf8B}}};
  m.fully_connected = false;  // default is true
  return m;
}

inline msg::TeamMessage make_team_message(Variant v) {
  msg::TeamMessage m;
  m.from = s(v, kUtf8A);
  m.to = s(v, kUtf8B);
  m.message_id = s(v, "m-17");
  m.payload = s(v, kUtf8C);
  return m;
}

inline msg::TeamDelivery make_team_delivery(Variant v) {
  msg::TeamDelivery m;
  m.recipient = s(v, kUtf8B);
  m.from = s(v, kUtf8A);
  m.to = s(v, "*");
  m.message_id = s(v, "m-18");
  m.payload = s(v, kUtf8C);
  m.sent_time_ns = 900'000'000'001;
  m.delivered_time_ns = 900'003'000'002;
  m.hops = 3;
  return m;
}

inline msg::DoorCommand make_door_command(Variant v) {
  msg::DoorCommand m;
  m.door_id = s(v, kUtf8C);
  m.angle = 1.375;
  m.source = s(v, kUtf8B);
  return m;
}

inline msg::HandoverRequest make_handover_request(Variant v) {
  msg::HandoverRequest m;
  m.request_id = s(v, kUtf8A);
  m.requester = s(v, kUtf8B);
  m.robot_id = s(v, kUtf8C);
  m.kind = msg::HandoverKind::Unload;  // default is Load
  m.place = s(v, "michael-desk");
  m.object_id = s(v, "letter-1");
  return m;
}

inline msg::HandoverStatus make_handover_status(Variant v) {
  msg::HandoverStatus m;
  m.request_id = s(v, kUtf8A);
  m.robot_id = s(v, kUtf8B);
  m.kind = msg::HandoverKind::Unload;
  m.place = s(v, kUtf8C);
  m.object_id = s(v, "book-2");
  m.state = msg::HandoverState::Completed;  // default is Rejected
  m.reason = s(v, "robot_moved_away");
  m.detail = s(v, kUtf8A);
  m.helper = s(v, "Michael");
  m.tick = 909;
  m.sim_time_ns = 45'000'000'001;
  m.completes_at_ns = 45'000'000'002;
  return m;
}

inline msg::ObjectState make_object_state(Variant v) {
  msg::ObjectState m;
  m.object_id = s(v, kUtf8A);
  m.kind = s(v, "book");
  m.colour = s(v, kUtf8B);
  m.place = s(v, kUtf8C);
  m.carrier = s(v, "rhino");
  m.tick = 1001;
  return m;
}

// Field-wise views: tuples compare with == and GoogleTest prints them field by field.
inline msg::CourierCommand make_courier_command(Variant v) {
  msg::CourierCommand m;
  m.command_id = s(v, kUtf8A);
  m.requester = s(v, kUtf8B);
  m.kind = msg::CourierCommandKind::Revise;  // default is Text
  m.text = s(v, "deliver it");
  m.job_id = s(v, "job-3");
  m.object_id = s(v, "letter-1");
  m.object_kind = s(v, "letter");
  m.object_colour = s(v, "red");
  m.from = s(v, "A-111");
  m.to = s(v, kUtf8C);
  m.deadline = s(v, "10:30");
  return m;
}

inline msg::CourierReply make_courier_reply(Variant v) {
  msg::CourierReply m;
  m.command_id = s(v, kUtf8A);
  m.accepted = true;
  m.job_id = s(v, "job-3");
  m.action = s(v, "deliver");
  m.object = s(v, "the red letter");
  m.from = s(v, "meeting-table");
  m.to = s(v, kUtf8B);
  m.deadline = s(v, "10:30");
  if (v == Variant::Full) m.assumptions = {"a", kUtf8C};
  m.reason = s(v, "unknown_place");
  m.detail = s(v, "no place 'A-112'");
  m.word = s(v, "A-112");
  m.column = 17;
  if (v == Variant::Full) m.suggestions = {"A-111", "A-121"};
  m.tick = 77;
  return m;
}

inline msg::CourierJobStatus make_courier_job_status(Variant v) {
  msg::CourierJobStatus m;
  m.job_id = s(v, kUtf8A);
  m.command_id = s(v, "c1");
  m.state = msg::JobState::Opportunistic;  // default is Queued
  m.phase = s(v, "to_destination");
  m.robot_id = s(v, "rhino");
  m.object_id = s(v, "letter-1");
  m.object_kind = s(v, "letter");
  m.object_colour = s(v, "red");
  m.from = s(v, "meeting-table");
  m.to = s(v, "michael-desk");
  m.deadline = s(v, "10:30:00");
  m.estimated_completion = s(v, "10:14:05");
  m.reason = s(v, kUtf8B);
  m.allocation = s(v, "assigned to rhino2: 3 min earlier than rhino1");
  m.tick = 88;
  return m;
}

inline msg::CourierSchedule make_courier_schedule(Variant v) {
  msg::CourierSchedule m;
  m.robot_id = s(v, kUtf8A);
  m.engine = s(v, "exact");
  m.proved_optimal = true;
  if (v == Variant::Full) {
    m.stops = {{"job-1", "load", "meeting-table", "A-111", 10.5, 22.5}, {"job-1", "unload", kUtf8B, "A-120", 80, 95}};
    m.assumptions = {"A-111 open at 08:31:00", kUtf8C};
  }
  m.late_jobs = 2;
  m.total_lateness_s = 12.5;
  m.tick = 99;
  return m;
}

inline msg::CourierReport make_courier_report(Variant v) {
  msg::CourierReport m;
  m.command_id = s(v, kUtf8A);
  m.job_id = s(v, kUtf8B);
  m.success = true;
  m.text = s(v, kUtf8C);
  m.tick = 111;
  return m;
}

inline auto fields(const msg::Heartbeat& m) {
  return std::make_tuple(m.service, m.instance, m.host, m.pid, static_cast<int>(m.state), m.uptime_s, m.period_ms,
                         m.capabilities, m.world_id, m.clock_samples_ignored, m.detail);
}
inline auto fields(const msg::SimClock& m) {
  return std::make_tuple(m.tick, m.sim_time_ns, m.step_ns, static_cast<int>(m.mode), m.warp, m.world_id);
}
inline auto fields(const msg::LockstepRegistration& m) { return std::make_tuple(m.participant, m.active); }
inline auto fields(const msg::TickAck& m) { return std::make_tuple(m.participant, m.tick, m.commands_sent, m.quiet_until_tick); }
inline auto fields(const msg::RobotState& m) {
  return std::make_tuple(m.robot_id, m.tick, m.sim_time_ns, m.x, m.y, m.theta, m.vx, m.vy, m.omega,
                         static_cast<int>(m.kinematics), m.radius, m.max_speed, m.max_omega, m.in_collision);
}
inline auto fields(const msg::VelocityCommand& m) {
  return std::make_tuple(m.robot_id, m.source, m.tick, m.vx, m.vy, m.omega);
}
inline auto fields(const msg::CommandRejection& m) { return std::make_tuple(m.robot_id, m.source, m.tick, m.reason); }
inline auto fields(const msg::SpawnRequest& m) {
  return std::make_tuple(m.request_id, m.requester, m.robot_id, m.has_pose, m.x, m.y, m.theta);
}
inline auto fields(const msg::SpawnReply& m) {
  return std::make_tuple(m.request_id, m.robot_id, static_cast<int>(m.status), m.reason);
}
inline auto fields(const msg::WorldMap& m) {
  std::vector<std::array<double, 4>> rects;
  for (const auto& r : m.obstacles) rects.push_back({r.min_x, r.min_y, r.max_x, r.max_y});
  std::vector<std::pair<std::string, std::vector<std::array<double, 2>>>> polygons;
  for (const auto& p : m.polygons) {
    polygons.push_back({p.name, {}});
    for (const auto& v : p.vertices) polygons.back().second.push_back({v.x, v.y});
  }
  std::vector<std::tuple<std::string, double, double, double, uint32_t, uint32_t, std::vector<uint8_t>>> rasters;
  for (const auto& r : m.rasters) rasters.emplace_back(r.name, r.origin_x, r.origin_y, r.resolution, r.cols, r.rows, r.blocked);
  std::vector<std::tuple<std::string, double, double, double, double>> doors;
  for (const auto& d : m.doors) doors.emplace_back(d.id, d.x, d.y, d.width, d.heading);
  return std::make_tuple(m.name, m.width, m.height, rects, polygons, rasters, doors);
}
inline auto fields(const msg::SimulatorStatus& m) {
  std::vector<std::tuple<uint64_t, int64_t, std::string, bool, std::string>> changes;
  for (const auto& c : m.lockstep_changes) changes.emplace_back(c.number, c.tick, c.participant, c.dropped, c.reason);
  return std::make_tuple(m.tick, m.sim_time_ns, m.robots, m.lockstep_participants, m.commands_applied,
                         m.commands_rejected, m.participants_dropped, m.mean_step_us, m.team_messages_delivered,
                         m.team_messages_dropped_no_route, m.team_messages_dropped_lost,
                         m.team_messages_dropped_invalid, m.lockstep_dropped, changes);
}
inline auto fields(const msg::NavGoal& m) {
  return std::make_tuple(m.robot_id, m.goal_id, m.x, m.y, m.tolerance, m.constraint_set);
}
inline auto fields(const msg::NavCancel& m) { return std::make_tuple(m.robot_id, m.goal_id, m.reason); }
inline auto fields(const msg::MissionStatus& m) {
  return std::make_tuple(m.robot_id, m.mission, m.state, m.event, m.reason, m.finished, m.tick);
}
inline auto fields(const msg::Itinerary& m) {
  std::vector<std::tuple<double, double, int64_t>> path;
  for (const auto& p : m.path) path.emplace_back(p.x, p.y, p.t_ns);
  return std::make_tuple(m.robot_id, m.tick, m.sim_time_ns, m.radius, m.x, m.y, path, m.passage, m.claim,
                         m.request_time_ns, m.waiting_for);
}
inline auto fields(const msg::GoalStatus& m) {
  return std::make_tuple(m.robot_id, m.goal_id, static_cast<int>(m.state), m.reason, m.tick, m.distance_to_goal);
}

inline auto fields(const msg::RangeScan& m) {
  return std::make_tuple(m.robot_id, m.tick, m.angle_min, m.angle_increment, m.max_range, m.ranges);
}
inline auto fields(const msg::PoseEstimate& m) { return std::make_tuple(m.robot_id, m.tick, m.x, m.y, m.theta); }
inline auto fields(const msg::DoorObservation& m) {
  std::vector<std::tuple<std::string, double, double, double>> doors;
  for (const auto& d : m.doors) doors.emplace_back(d.door_id, d.angle_estimate, d.distance, d.bearing);
  return std::make_tuple(m.robot_id, m.tick, doors);
}
inline auto fields(const msg::DoorState& m) {
  return std::make_tuple(m.door_id, m.tick, m.angle, m.target_angle, m.closed, m.blocked);
}
inline auto fields(const msg::RadioLink& m) {
  return std::make_tuple(m.robot_a, m.robot_b, m.tick, m.signal_dbm, m.margin_db, m.connected);
}
inline auto fields(const msg::TeamConnectivity& m) {
  std::vector<std::vector<std::string>> components;
  for (const auto& c : m.components) components.push_back(c.robots);
  return std::make_tuple(m.tick, components, m.fully_connected);
}
inline auto fields(const msg::TeamMessage& m) { return std::make_tuple(m.from, m.to, m.message_id, m.payload); }
inline auto fields(const msg::TeamDelivery& m) {
  return std::make_tuple(m.recipient, m.from, m.to, m.message_id, m.payload, m.sent_time_ns, m.delivered_time_ns,
                         m.hops);
}
inline auto fields(const msg::DoorCommand& m) { return std::make_tuple(m.door_id, m.angle, m.source); }
inline auto fields(const msg::HandoverRequest& m) {
  return std::make_tuple(m.request_id, m.requester, m.robot_id, static_cast<int>(m.kind), m.place, m.object_id);
}
inline auto fields(const msg::HandoverStatus& m) {
  return std::make_tuple(m.request_id, m.robot_id, static_cast<int>(m.kind), m.place, m.object_id,
                         static_cast<int>(m.state), m.reason, m.detail, m.helper, m.tick, m.sim_time_ns,
                         m.completes_at_ns);
}
inline auto fields(const msg::ObjectState& m) {
  return std::make_tuple(m.object_id, m.kind, m.colour, m.place, m.carrier, m.tick);
}
inline auto fields(const msg::CourierCommand& m) {
  return std::make_tuple(m.command_id, m.requester, static_cast<int>(m.kind), m.text, m.job_id, m.object_id,
                         m.object_kind, m.object_colour, m.from, m.to, m.deadline);
}
inline auto fields(const msg::CourierReply& m) {
  return std::make_tuple(m.command_id, m.accepted, m.job_id, m.action, m.object, m.from, m.to, m.deadline,
                         m.assumptions, m.reason, m.detail, m.word, m.column, m.suggestions, m.tick);
}
inline auto fields(const msg::CourierJobStatus& m) {
  return std::make_tuple(m.job_id, m.command_id, static_cast<int>(m.state), m.phase, m.robot_id, m.object_id,
                         m.object_kind, m.object_colour, m.from, m.to, m.deadline, m.estimated_completion, m.reason,
                         m.allocation, m.tick);
}
inline auto fields(const msg::CourierSchedule& m) {
  std::vector<std::tuple<std::string, std::string, std::string, std::string, double, double>> stops;
  for (const auto& x : m.stops) stops.emplace_back(x.job_id, x.action, x.place, x.room, x.arrival_s, x.finish_s);
  return std::make_tuple(m.robot_id, m.engine, m.proved_optimal, stops, m.assumptions, m.late_jobs,
                         m.total_lateness_s, m.tick);
}
inline auto fields(const msg::CourierReport& m) {
  return std::make_tuple(m.command_id, m.job_id, m.success, m.text, m.tick);
}

#ifdef AUTONOMY_LOOPBACK_URI
// The loopback Cyclone profile (deploy/dds/loopback.xml); call before creating a participant.
inline void use_loopback_profile() { ::setenv("CYCLONEDDS_URI", AUTONOMY_LOOPBACK_URI, 1); }
#endif

// Polls pred every 2 ms until it holds or timeout passes; returns its last value.
inline bool eventually(const std::function<bool()>& pred,
                       std::chrono::milliseconds timeout = std::chrono::milliseconds(2000)) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    if (pred()) return true;
    if (std::chrono::steady_clock::now() >= deadline) return pred();
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

}  // namespace autonomy::test
