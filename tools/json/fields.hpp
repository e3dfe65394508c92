#pragma once
// The field tables of the message value types (common/msg): one Fields<T> per type, listing every
// field in IDL order with its JSON name and whether it is a DDS key. to_json, from_json and
// key_json (msg_json.hpp) are written once over these tables. A new message type needs one
// Fields specialisation here; a new enum needs one EnumValues specialisation.
#include <array>

#include "common/geometry/geometry.hpp"
#include "common/msg/clock.hpp"
#include "common/msg/courier.hpp"
#include "common/msg/navigation.hpp"
#include "common/msg/office.hpp"
#include "common/msg/executive.hpp"
#include "common/msg/planner.hpp"
#include "common/msg/robot.hpp"
#include "common/msg/simulation.hpp"
#include "common/msg/perception.hpp"
#include "common/msg/radio.hpp"
#include "common/msg/truth.hpp"
#include "common/msg/system.hpp"
#include "common/msg/spacecraft.hpp"

namespace autonomy::json {

// Every value of an enum; the JSON name of a value is msg::to_string(value).
template <typename E>
struct EnumValues;

template <>
struct EnumValues<msg::ServiceState> {
  static constexpr std::array values{msg::ServiceState::Starting, msg::ServiceState::Ready,
                                     msg::ServiceState::Stopping};
};
template <>
struct EnumValues<msg::ClockMode> {
  static constexpr std::array values{msg::ClockMode::Lockstep, msg::ClockMode::Paced};
};
template <>
struct EnumValues<msg::Kinematics> {
  static constexpr std::array values{msg::Kinematics::Holonomic, msg::Kinematics::Unicycle};
};
template <>
struct EnumValues<msg::RequestStatus> {
  static constexpr std::array values{msg::RequestStatus::Accepted, msg::RequestStatus::Rejected};
};
template <>
struct EnumValues<msg::GoalState> {
  static constexpr std::array values{msg::GoalState::Accepted, msg::GoalState::Active,    msg::GoalState::Reached,
                                     msg::GoalState::Blocked,  msg::GoalState::Preempted, msg::GoalState::Rejected,
                                     msg::GoalState::Cancelled};
};
template <>
struct EnumValues<msg::HandoverKind> {
  static constexpr std::array values{msg::HandoverKind::Load, msg::HandoverKind::Unload};
};
template <>
struct EnumValues<msg::HandoverState> {
  static constexpr std::array values{msg::HandoverState::Accepted, msg::HandoverState::Rejected,
                                     msg::HandoverState::Completed, msg::HandoverState::Failed};
};
template <>
struct EnumValues<msg::CourierCommandKind> {
  static constexpr std::array values{msg::CourierCommandKind::Text, msg::CourierCommandKind::Deliver,
                                     msg::CourierCommandKind::Cancel, msg::CourierCommandKind::Revise};
};
template <>
struct EnumValues<msg::JobState> {
  static constexpr std::array values{msg::JobState::Queued,    msg::JobState::Underway, msg::JobState::Opportunistic,
                                     msg::JobState::Completed, msg::JobState::Failed,   msg::JobState::Cancelled,
                                     msg::JobState::Stranded};
};

template <>
struct EnumValues<msg::PlanningStatus> {
  static constexpr std::array values{msg::PlanningStatus::Optimal,    msg::PlanningStatus::PlanFound,
                                     msg::PlanningStatus::Infeasible, msg::PlanningStatus::OutOfTime,
                                     msg::PlanningStatus::Cancelled,  msg::PlanningStatus::Rejected};
};

// visit(v, m) calls v.key(name, member) for key fields and v.field(name, member) for the others;
// M is T or const T.
template <typename T>
struct Fields;

template <>
struct Fields<msg::Heartbeat> {
  static constexpr const char* name = "Heartbeat";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("service", m.service);
    v.key("instance", m.instance);
    v.field("host", m.host);
    v.field("pid", m.pid);
    v.field("state", m.state);
    v.field("uptime_s", m.uptime_s);
    v.field("period_ms", m.period_ms);
    v.field("capabilities", m.capabilities);
    v.field("world_id", m.world_id);
    v.field("clock_samples_ignored", m.clock_samples_ignored);
    v.field("detail", m.detail);
  }
};

template <>
struct Fields<msg::SimClock> {
  static constexpr const char* name = "SimClock";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("tick", m.tick);
    v.field("sim_time_ns", m.sim_time_ns);
    v.field("step_ns", m.step_ns);
    v.field("mode", m.mode);
    v.field("warp", m.warp);
    v.field("world_id", m.world_id);
  }
};

template <>
struct Fields<msg::LockstepRegistration> {
  static constexpr const char* name = "LockstepRegistration";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("participant", m.participant);
    v.field("active", m.active);
  }
};

template <>
struct Fields<msg::TickAck> {
  static constexpr const char* name = "TickAck";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("participant", m.participant);
    v.field("tick", m.tick);
    v.field("commands_sent", m.commands_sent);
    v.field("quiet_until_tick", m.quiet_until_tick);
  }
};

template <>
struct Fields<msg::RobotState> {
  static constexpr const char* name = "RobotState";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("robot_id", m.robot_id);
    v.field("tick", m.tick);
    v.field("sim_time_ns", m.sim_time_ns);
    v.field("x", m.x);
    v.field("y", m.y);
    v.field("theta", m.theta);
    v.field("vx", m.vx);
    v.field("vy", m.vy);
    v.field("omega", m.omega);
    v.field("kinematics", m.kinematics);
    v.field("radius", m.radius);
    v.field("max_speed", m.max_speed);
    v.field("max_omega", m.max_omega);
    v.field("in_collision", m.in_collision);
  }
};

template <>
struct Fields<msg::VelocityCommand> {
  static constexpr const char* name = "VelocityCommand";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("robot_id", m.robot_id);
    v.field("source", m.source);
    v.field("tick", m.tick);
    v.field("vx", m.vx);
    v.field("vy", m.vy);
    v.field("omega", m.omega);
  }
};

template <>
struct Fields<msg::CommandRejection> {
  static constexpr const char* name = "CommandRejection";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("robot_id", m.robot_id);
    v.field("source", m.source);
    v.field("tick", m.tick);
    v.field("reason", m.reason);
  }
};

template <>
struct Fields<msg::SpawnRequest> {
  static constexpr const char* name = "SpawnRequest";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("request_id", m.request_id);
    v.field("requester", m.requester);
    v.field("robot_id", m.robot_id);
    v.field("has_pose", m.has_pose);
    v.field("x", m.x);
    v.field("y", m.y);
    v.field("theta", m.theta);
  }
};

template <>
struct Fields<msg::SpawnReply> {
  static constexpr const char* name = "SpawnReply";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("request_id", m.request_id);
    v.field("robot_id", m.robot_id);
    v.field("status", m.status);
    v.field("reason", m.reason);
  }
};

template <>
struct Fields<geometry::Rect> {
  static constexpr const char* name = "Rectangle";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("min_x", m.min_x);
    v.field("min_y", m.min_y);
    v.field("max_x", m.max_x);
    v.field("max_y", m.max_y);
  }
};

template <>
struct Fields<msg::MapPoint> {
  static constexpr const char* name = "MapPoint";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("x", m.x);
    v.field("y", m.y);
  }
};

template <>
struct Fields<msg::MapPolygon> {
  static constexpr const char* name = "MapPolygon";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("name", m.name);
    v.field("vertices", m.vertices);
  }
};

// JSON shows the cells decoded (one 0/1 per cell, row-major from the bottom row), not the
// run-length code of the wire.
template <>
struct Fields<msg::MapRaster> {
  static constexpr const char* name = "MapRaster";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("name", m.name);
    v.field("origin_x", m.origin_x);
    v.field("origin_y", m.origin_y);
    v.field("resolution", m.resolution);
    v.field("cols", m.cols);
    v.field("rows", m.rows);
    v.field("blocked", m.blocked);
  }
};

template <>
struct Fields<msg::MapDoor> {
  static constexpr const char* name = "MapDoor";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("id", m.id);
    v.field("x", m.x);
    v.field("y", m.y);
    v.field("width", m.width);
    v.field("heading", m.heading);
    v.field("open_angle", m.open_angle);
  }
};

template <>
struct Fields<msg::WorldMap> {
  static constexpr const char* name = "WorldMap";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("name", m.name);
    v.field("width", m.width);
    v.field("height", m.height);
    v.field("obstacles", m.obstacles);
    v.field("polygons", m.polygons);
    v.field("rasters", m.rasters);
    v.field("doors", m.doors);
  }
};

template <>
struct Fields<msg::LockstepChange> {
  static constexpr const char* name = "LockstepChange";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("number", m.number);
    v.field("tick", m.tick);
    v.field("participant", m.participant);
    v.field("dropped", m.dropped);
    v.field("reason", m.reason);
  }
};

template <>
struct Fields<msg::SimulatorStatus> {
  static constexpr const char* name = "SimulatorStatus";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("tick", m.tick);
    v.field("sim_time_ns", m.sim_time_ns);
    v.field("robots", m.robots);
    v.field("lockstep_participants", m.lockstep_participants);
    v.field("commands_applied", m.commands_applied);
    v.field("commands_rejected", m.commands_rejected);
    v.field("participants_dropped", m.participants_dropped);
    v.field("mean_step_us", m.mean_step_us);
    v.field("team_messages_delivered", m.team_messages_delivered);
    v.field("team_messages_dropped_no_route", m.team_messages_dropped_no_route);
    v.field("team_messages_dropped_lost", m.team_messages_dropped_lost);
    v.field("team_messages_dropped_invalid", m.team_messages_dropped_invalid);
    v.field("lockstep_dropped", m.lockstep_dropped);
    v.field("lockstep_changes", m.lockstep_changes);
  }
};

template <>
struct Fields<msg::NavGoal> {
  static constexpr const char* name = "NavGoal";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("robot_id", m.robot_id);
    v.field("goal_id", m.goal_id);
    v.field("x", m.x);
    v.field("y", m.y);
    v.field("tolerance", m.tolerance);
    v.field("constraint_set", m.constraint_set);
  }
};

template <>
struct Fields<msg::NavCancel> {
  static constexpr const char* name = "NavCancel";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("robot_id", m.robot_id);
    v.field("goal_id", m.goal_id);
    v.field("reason", m.reason);
  }
};

template <>
struct Fields<msg::MissionStatus> {
  static constexpr const char* name = "MissionStatus";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("robot_id", m.robot_id);
    v.field("mission", m.mission);
    v.field("state", m.state);
    v.field("event", m.event);
    v.field("reason", m.reason);
    v.field("finished", m.finished);
    v.field("tick", m.tick);
  }
};

template <>
struct Fields<msg::ItineraryPoint> {
  static constexpr const char* name = "ItineraryPoint";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("x", m.x);
    v.field("y", m.y);
    v.field("t_ns", m.t_ns);
  }
};

template <>
struct Fields<msg::Itinerary> {
  static constexpr const char* name = "Itinerary";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("robot_id", m.robot_id);
    v.field("tick", m.tick);
    v.field("sim_time_ns", m.sim_time_ns);
    v.field("radius", m.radius);
    v.field("x", m.x);
    v.field("y", m.y);
    v.field("path", m.path);
    v.field("passage", m.passage);
    v.field("claim", m.claim);
    v.field("request_time_ns", m.request_time_ns);
    v.field("waiting_for", m.waiting_for);
  }
};

template <>
struct Fields<msg::GoalStatus> {
  static constexpr const char* name = "GoalStatus";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("robot_id", m.robot_id);
    v.field("goal_id", m.goal_id);
    v.field("state", m.state);
    v.field("reason", m.reason);
    v.field("tick", m.tick);
    v.field("distance_to_goal", m.distance_to_goal);
  }
};

// --- Simulator world v2: perception, ground truth, radio, team messages, door commands ---------

template <>
struct Fields<msg::RangeScan> {
  static constexpr const char* name = "RangeScan";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("robot_id", m.robot_id);
    v.field("tick", m.tick);
    v.field("angle_min", m.angle_min);
    v.field("angle_increment", m.angle_increment);
    v.field("max_range", m.max_range);
    v.field("ranges", m.ranges);
  }
};

template <>
struct Fields<msg::PoseEstimate> {
  static constexpr const char* name = "PoseEstimate";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("robot_id", m.robot_id);
    v.field("tick", m.tick);
    v.field("x", m.x);
    v.field("y", m.y);
    v.field("theta", m.theta);
  }
};

template <>
struct Fields<msg::DoorSighting> {
  static constexpr const char* name = "DoorSighting";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("door_id", m.door_id);
    v.field("angle_estimate", m.angle_estimate);
    v.field("distance", m.distance);
    v.field("bearing", m.bearing);
  }
};

template <>
struct Fields<msg::DoorObservation> {
  static constexpr const char* name = "DoorObservation";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("robot_id", m.robot_id);
    v.field("tick", m.tick);
    v.field("doors", m.doors);
  }
};

template <>
struct Fields<msg::DoorState> {
  static constexpr const char* name = "DoorState";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("door_id", m.door_id);
    v.field("tick", m.tick);
    v.field("angle", m.angle);
    v.field("target_angle", m.target_angle);
    v.field("closed", m.closed);
    v.field("blocked", m.blocked);
  }
};

template <>
struct Fields<msg::RadioLink> {
  static constexpr const char* name = "RadioLink";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("robot_a", m.robot_a);
    v.key("robot_b", m.robot_b);
    v.field("tick", m.tick);
    v.field("signal_dbm", m.signal_dbm);
    v.field("margin_db", m.margin_db);
    v.field("connected", m.connected);
  }
};

template <>
struct Fields<msg::TeamComponent> {
  static constexpr const char* name = "TeamComponent";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("robots", m.robots);
  }
};

template <>
struct Fields<msg::TeamConnectivity> {
  static constexpr const char* name = "TeamConnectivity";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("tick", m.tick);
    v.field("components", m.components);
    v.field("fully_connected", m.fully_connected);
  }
};

template <>
struct Fields<msg::TeamMessage> {
  static constexpr const char* name = "TeamMessage";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("from", m.from);
    v.field("to", m.to);
    v.field("message_id", m.message_id);
    v.field("payload", m.payload);
  }
};

template <>
struct Fields<msg::TeamDelivery> {
  static constexpr const char* name = "TeamDelivery";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("recipient", m.recipient);
    v.field("from", m.from);
    v.field("to", m.to);
    v.field("message_id", m.message_id);
    v.field("payload", m.payload);
    v.field("sent_time_ns", m.sent_time_ns);
    v.field("delivered_time_ns", m.delivered_time_ns);
    v.field("hops", m.hops);
  }
};

template <>
struct Fields<msg::DoorCommand> {
  static constexpr const char* name = "DoorCommand";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("door_id", m.door_id);
    v.field("angle", m.angle);
    v.field("source", m.source);
  }
};

// --- The office: load/unload requests and answers, object ground truth ------------------------

template <>
struct Fields<msg::HandoverRequest> {
  static constexpr const char* name = "HandoverRequest";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("request_id", m.request_id);
    v.field("requester", m.requester);
    v.field("robot_id", m.robot_id);
    v.field("kind", m.kind);
    v.field("place", m.place);
    v.field("object_id", m.object_id);
  }
};

template <>
struct Fields<msg::HandoverStatus> {
  static constexpr const char* name = "HandoverStatus";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("request_id", m.request_id);
    v.field("robot_id", m.robot_id);
    v.field("kind", m.kind);
    v.field("place", m.place);
    v.field("object_id", m.object_id);
    v.field("state", m.state);
    v.field("reason", m.reason);
    v.field("detail", m.detail);
    v.field("helper", m.helper);
    v.field("tick", m.tick);
    v.field("sim_time_ns", m.sim_time_ns);
    v.field("completes_at_ns", m.completes_at_ns);
  }
};

template <>
struct Fields<msg::ObjectState> {
  static constexpr const char* name = "ObjectState";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("object_id", m.object_id);
    v.field("kind", m.kind);
    v.field("colour", m.colour);
    v.field("place", m.place);
    v.field("carrier", m.carrier);
    v.field("tick", m.tick);
  }
};

// --- The courier scheduler -------------------------------------------------------------------

template <>
struct Fields<msg::CourierCommand> {
  static constexpr const char* name = "CourierCommand";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("command_id", m.command_id);
    v.field("requester", m.requester);
    v.field("kind", m.kind);
    v.field("text", m.text);
    v.field("job_id", m.job_id);
    v.field("object_id", m.object_id);
    v.field("object_kind", m.object_kind);
    v.field("object_colour", m.object_colour);
    v.field("from", m.from);
    v.field("to", m.to);
    v.field("deadline", m.deadline);
  }
};

template <>
struct Fields<msg::CourierReply> {
  static constexpr const char* name = "CourierReply";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("command_id", m.command_id);
    v.field("accepted", m.accepted);
    v.field("job_id", m.job_id);
    v.field("action", m.action);
    v.field("object", m.object);
    v.field("from", m.from);
    v.field("to", m.to);
    v.field("deadline", m.deadline);
    v.field("assumptions", m.assumptions);
    v.field("reason", m.reason);
    v.field("detail", m.detail);
    v.field("word", m.word);
    v.field("column", m.column);
    v.field("suggestions", m.suggestions);
    v.field("tick", m.tick);
  }
};

template <>
struct Fields<msg::CourierJobStatus> {
  static constexpr const char* name = "CourierJobStatus";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("job_id", m.job_id);
    v.field("command_id", m.command_id);
    v.field("state", m.state);
    v.field("phase", m.phase);
    v.field("robot_id", m.robot_id);
    v.field("object_id", m.object_id);
    v.field("object_kind", m.object_kind);
    v.field("object_colour", m.object_colour);
    v.field("from", m.from);
    v.field("to", m.to);
    v.field("deadline", m.deadline);
    v.field("estimated_completion", m.estimated_completion);
    v.field("reason", m.reason);
    v.field("allocation", m.allocation);
    v.field("tick", m.tick);
  }
};

template <>
struct Fields<msg::CourierStop> {
  static constexpr const char* name = "CourierStop";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("job_id", m.job_id);
    v.field("action", m.action);
    v.field("place", m.place);
    v.field("room", m.room);
    v.field("arrival_s", m.arrival_s);
    v.field("finish_s", m.finish_s);
  }
};

template <>
struct Fields<msg::CourierSchedule> {
  static constexpr const char* name = "CourierSchedule";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("robot_id", m.robot_id);
    v.field("engine", m.engine);
    v.field("proved_optimal", m.proved_optimal);
    v.field("stops", m.stops);
    v.field("assumptions", m.assumptions);
    v.field("late_jobs", m.late_jobs);
    v.field("total_lateness_s", m.total_lateness_s);
    v.field("tick", m.tick);
  }
};

template <>
struct Fields<msg::CourierReport> {
  static constexpr const char* name = "CourierReport";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("command_id", m.command_id);
    v.field("job_id", m.job_id);
    v.field("success", m.success);
    v.field("text", m.text);
    v.field("tick", m.tick);
  }
};

// --- The spacecraft (idl/spacecraft.idl) ------------------------------------------------------

template <>
struct Fields<msg::SpacecraftCommand> {
  static constexpr const char* name = "SpacecraftCommand";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("command_id", m.command_id);
    v.field("source", m.source);
    v.field("tick", m.tick);
    v.field("device", m.device);
    v.field("command", m.command);
    v.field("arguments", m.arguments);
  }
};

template <>
struct Fields<msg::SpacecraftCommandStatus> {
  static constexpr const char* name = "SpacecraftCommandStatus";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("command_id", m.command_id);
    v.field("source", m.source);
    v.field("device", m.device);
    v.field("command", m.command);
    v.field("accepted", m.accepted);
    v.field("reason", m.reason);
    v.field("tick", m.tick);
    v.field("sim_time_ns", m.sim_time_ns);
    v.field("busy", m.busy);
  }
};

template <>
struct Fields<msg::DeviceReport> {
  static constexpr const char* name = "DeviceReport";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("device", m.device);
    v.field("mode", m.mode);
    v.field("confirmed_command", m.confirmed_command);
    v.field("confirmed_command_id", m.confirmed_command_id);
    v.field("confirmed_tick", m.confirmed_tick);
  }
};

template <>
struct Fields<msg::SensorReading> {
  static constexpr const char* name = "SensorReading";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("sensor", m.sensor);
    v.field("value", m.value);
  }
};

template <>
struct Fields<msg::AttitudeTelemetry> {
  static constexpr const char* name = "AttitudeTelemetry";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("qw", m.qw);
    v.field("qx", m.qx);
    v.field("qy", m.qy);
    v.field("qz", m.qz);
    v.field("pointing_target", m.pointing_target);
    v.field("turn_target", m.turn_target);
    v.field("control_mode", m.control_mode);
    v.field("rate_deg_s", m.rate_deg_s);
    v.field("remaining_deg", m.remaining_deg);
  }
};

template <>
struct Fields<msg::PropulsionTelemetry> {
  static constexpr const char* name = "PropulsionTelemetry";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("thrust_level", m.thrust_level);
    v.field("power_w", m.power_w);
    v.field("thrust_time_s", m.thrust_time_s);
  }
};

template <>
struct Fields<msg::CameraTelemetry> {
  static constexpr const char* name = "CameraTelemetry";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("power_w", m.power_w);
    v.field("images_taken", m.images_taken);
    v.field("images_on_target", m.images_on_target);
    v.field("last_image_target", m.last_image_target);
  }
};

template <>
struct Fields<msg::PowerTelemetry> {
  static constexpr const char* name = "PowerTelemetry";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("solar_array_w", m.solar_array_w);
    v.field("load_w", m.load_w);
    v.field("battery_soc", m.battery_soc);
    v.field("battery_wh", m.battery_wh);
  }
};

template <>
struct Fields<msg::TelecomTelemetry> {
  static constexpr const char* name = "TelecomTelemetry";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("ground_station", m.ground_station);
    v.field("downlink_rate_kbps", m.downlink_rate_kbps);
    v.field("downlinked_mb", m.downlinked_mb);
  }
};

template <>
struct Fields<msg::StorageTelemetry> {
  static constexpr const char* name = "StorageTelemetry";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("used_mb", m.used_mb);
    v.field("capacity_mb", m.capacity_mb);
  }
};

template <>
struct Fields<msg::FaultProtectionTelemetry> {
  static constexpr const char* name = "FaultProtectionTelemetry";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("safe_mode", m.safe_mode);
    v.field("reason", m.reason);
    v.field("safed_at_ns", m.safed_at_ns);
    v.field("safings", m.safings);
    v.field("commander_silent_s", m.commander_silent_s);
    v.field("commander_timeout_s", m.commander_timeout_s);
  }
};

template <>
struct Fields<msg::SpacecraftTelemetry> {
  static constexpr const char* name = "SpacecraftTelemetry";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("spacecraft", m.spacecraft);
    v.field("tick", m.tick);
    v.field("sim_time_ns", m.sim_time_ns);
    v.field("devices", m.devices);
    v.field("readings", m.readings);
    v.field("attitude", m.attitude);
    v.field("propulsion", m.propulsion);
    v.field("camera", m.camera);
    v.field("power", m.power);
    v.field("telecom", m.telecom);
    v.field("storage", m.storage);
    v.field("commands_accepted", m.commands_accepted);
    v.field("commands_rejected", m.commands_rejected);
    v.field("fault_protection", m.fault_protection);
    v.field("commands_busy", m.commands_busy);
  }
};

template <>
struct Fields<msg::SpacecraftFaultInjection> {
  static constexpr const char* name = "SpacecraftFaultInjection";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("fault_id", m.fault_id);
    v.field("source", m.source);
    v.field("kind", m.kind);
    v.field("subject", m.subject);
    v.field("value", m.value);
    v.field("reset_cures", m.reset_cures);
    v.field("clear", m.clear);
  }
};

template <>
struct Fields<msg::SpacecraftFaultState> {
  static constexpr const char* name = "SpacecraftFaultState";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("fault_id", m.fault_id);
    v.field("kind", m.kind);
    v.field("subject", m.subject);
    v.field("value", m.value);
    v.field("active", m.active);
    v.field("trigger", m.trigger);
    v.field("ended_by", m.ended_by);
    v.field("since_ns", m.since_ns);
  }
};

template <>
struct Fields<msg::SpacecraftEvent> {
  static constexpr const char* name = "SpacecraftEvent";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("spacecraft", m.spacecraft);
    v.field("tick", m.tick);
    v.field("sim_time_ns", m.sim_time_ns);
    v.field("kind", m.kind);
    v.field("detail", m.detail);
  }
};

// --- The planner ---------------------------------------------------------------------------

template <>
struct Fields<msg::PlannerTimelineValue> {
  static constexpr const char* name = "PlannerTimelineValue";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("timeline", m.timeline);
    v.field("predicate", m.predicate);
    v.field("parameters", m.parameters);
  }
};

template <>
struct Fields<msg::PlanningRequest> {
  static constexpr const char* name = "PlanningRequest";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("request_id", m.request_id);
    v.field("requester", m.requester);
    v.field("model_file", m.model_file);
    v.field("model_text", m.model_text);
    v.field("model_protobuf", m.model_protobuf);
    v.field("problem_file", m.problem_file);
    v.field("problem_text", m.problem_text);
    v.field("problem_protobuf", m.problem_protobuf);
    v.field("state", m.state);
    v.field("plan_origin", m.plan_origin);
    v.field("engine", m.engine);
    v.field("seed", m.seed);
    v.field("budget_ms", m.budget_ms);
    v.field("max_decisions", m.max_decisions);
  }
};

template <>
struct Fields<msg::PlannerDiagnostic> {
  static constexpr const char* name = "PlannerDiagnostic";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("file", m.file);
    v.field("line", m.line);
    v.field("column", m.column);
    v.field("message", m.message);
  }
};

template <>
struct Fields<msg::PlanningStatistics> {
  static constexpr const char* name = "PlanningStatistics";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("decisions", m.decisions);
    v.field("backtracks", m.backtracks);
    v.field("dead_ends", m.dead_ends);
    v.field("temporal_propagations", m.temporal_propagations);
    v.field("procedure_calls", m.procedure_calls);
    v.field("improvements", m.improvements);
    v.field("elapsed_ms", m.elapsed_ms);
  }
};

template <>
struct Fields<msg::PlanToken> {
  static constexpr const char* name = "PlanToken";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("id", m.id);
    v.field("object", m.object);
    v.field("attribute", m.attribute);
    v.field("predicate", m.predicate);
    v.field("parameters", m.parameters);
    v.field("parameter_lo", m.parameter_lo);
    v.field("parameter_hi", m.parameter_hi);
    v.field("start_lb", m.start_lb);
    v.field("start_ub", m.start_ub);
    v.field("end_lb", m.end_lb);
    v.field("end_ub", m.end_ub);
    v.field("duration_lb", m.duration_lb);
    v.field("duration_ub", m.duration_ub);
    v.field("origin", m.origin);
    v.field("fact", m.fact);
  }
};

template <>
struct Fields<msg::PlanTimeline> {
  static constexpr const char* name = "PlanTimeline";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("name", m.name);
    v.field("tokens", m.tokens);
  }
};

template <>
struct Fields<msg::PlanConstraint> {
  static constexpr const char* name = "PlanConstraint";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("from", m.from);
    v.field("to", m.to);
    v.field("lb", m.lb);
    v.field("ub", m.ub);
  }
};

template <>
struct Fields<msg::FlexiblePlan> {
  static constexpr const char* name = "FlexiblePlan";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("horizon", m.horizon);
    v.field("makespan", m.makespan);
    v.field("penalty", m.penalty);
    v.field("omitted_goals", m.omitted_goals);
    v.field("timelines", m.timelines);
    v.field("tokens", m.tokens);
    v.field("constraints", m.constraints);
  }
};

template <>
struct Fields<msg::PlanningReply> {
  static constexpr const char* name = "PlanningReply";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("request_id", m.request_id);
    v.field("requester", m.requester);
    v.field("status", m.status);
    v.field("reason", m.reason);
    v.field("detail", m.detail);
    v.field("diagnostics", m.diagnostics);
    v.field("conflicts", m.conflicts);
    v.field("engine", m.engine);
    v.field("has_plan", m.has_plan);
    v.field("plan", m.plan);
    v.field("violations", m.violations);
    v.field("statistics", m.statistics);
    v.field("plan_origin", m.plan_origin);
  }
};

template <>
struct Fields<msg::PlanningProgress> {
  static constexpr const char* name = "PlanningProgress";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("request_id", m.request_id);
    v.field("improvement", m.improvement);
    v.field("makespan", m.makespan);
    v.field("penalty", m.penalty);
    v.field("tokens", m.tokens);
    v.field("elapsed_ms", m.elapsed_ms);
  }
};

template <>
struct Fields<msg::PlanningCancel> {
  static constexpr const char* name = "PlanningCancel";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("request_id", m.request_id);
    v.field("requester", m.requester);
  }
};

template <>
struct Fields<msg::LatestPlan> {
  static constexpr const char* name = "LatestPlan";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("requester", m.requester);
    v.field("request_id", m.request_id);
    v.field("status", m.status);
    v.field("engine", m.engine);
    v.field("plan_origin", m.plan_origin);
    v.field("plan", m.plan);
  }
};

template <>
struct Fields<msg::ExecutiveEvent> {
  static constexpr const char* name = "ExecutiveEvent";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.field("executive", m.executive);
    v.field("number", m.number);
    v.field("tick", m.tick);
    v.field("sim_time_ns", m.sim_time_ns);
    v.field("kind", m.kind);
    v.field("text", m.text);
    v.field("plan_id", m.plan_id);
  }
};

template <>
struct Fields<msg::ExecutiveStatus> {
  static constexpr const char* name = "ExecutiveStatus";
  template <typename V, typename M>
  static void visit(V& v, M& m) {
    v.key("executive", m.executive);
    v.field("state", m.state);
    v.field("plan_id", m.plan_id);
    v.field("tick", m.tick);
    v.field("plan_origin_s", m.plan_origin_s);
    v.field("horizon_end_s", m.horizon_end_s);
    v.field("executing", m.executing);
    v.field("goals_achieved", m.goals_achieved);
    v.field("goals_lost", m.goals_lost);
    v.field("disabled_devices", m.disabled_devices);
    v.field("ignored_sensors", m.ignored_sensors);
    v.field("replans", m.replans);
    v.field("horizons", m.horizons);
    v.field("decision_us_mean", m.decision_us_mean);
    v.field("decision_us_max", m.decision_us_max);
    v.field("watchdog_alarm", m.watchdog_alarm);
  }
};

}  // namespace autonomy::json
