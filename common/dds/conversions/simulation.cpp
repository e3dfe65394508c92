#include "common/dds/message_types.hpp"

namespace autonomy::dds {

void DdsType<msg::SpawnRequest>::to_c(const msg::SpawnRequest& v, C& out, Arena&) {
  out.request_id = c_str(v.request_id);
  out.requester = c_str(v.requester);
  out.robot_id = c_str(v.robot_id);
  out.has_pose = v.has_pose;
  out.x = v.x;
  out.y = v.y;
  out.theta = v.theta;
}

msg::SpawnRequest DdsType<msg::SpawnRequest>::from_c(const C& in) {
  return {from_c_str(in.request_id), from_c_str(in.requester), from_c_str(in.robot_id), in.has_pose, in.x, in.y,
          in.theta};
}

void DdsType<msg::SpawnReply>::to_c(const msg::SpawnReply& v, C& out, Arena&) {
  out.request_id = c_str(v.request_id);
  out.robot_id = c_str(v.robot_id);
  out.status = static_cast<autonomy_RequestStatus>(v.status);
  out.reason = c_str(v.reason);
}

msg::SpawnReply DdsType<msg::SpawnReply>::from_c(const C& in) {
  return {from_c_str(in.request_id), from_c_str(in.robot_id), static_cast<msg::RequestStatus>(in.status),
          from_c_str(in.reason)};
}

void DdsType<msg::WorldMap>::to_c(const msg::WorldMap& v, C& out, Arena& arena) {
  out.name = c_str(v.name);
  out.width = v.width;
  out.height = v.height;
  const uint32_t n = static_cast<uint32_t>(v.obstacles.size());
  auto* rects = arena.allocate<autonomy_Rectangle>(n);
  for (uint32_t i = 0; i < n; ++i) {
    const auto& r = v.obstacles[i];
    rects[i] = {r.min_x, r.min_y, r.max_x, r.max_y};
  }
  out.obstacles = {n, n, rects, false};
}

msg::WorldMap DdsType<msg::WorldMap>::from_c(const C& in) {
  msg::WorldMap v;
  v.name = from_c_str(in.name);
  v.width = in.width;
  v.height = in.height;
  v.obstacles.reserve(in.obstacles._length);
  for (uint32_t i = 0; i < in.obstacles._length; ++i) {
    const auto& r = in.obstacles._buffer[i];
    v.obstacles.push_back({r.min_x, r.min_y, r.max_x, r.max_y});
  }
  return v;
}

void DdsType<msg::SimulatorStatus>::to_c(const msg::SimulatorStatus& v, C& out, Arena& arena) {
  out.tick = v.tick;
  out.sim_time_ns = v.sim_time_ns;
  out.robots = v.robots;
  const uint32_t n = static_cast<uint32_t>(v.lockstep_participants.size());
  auto* names = arena.allocate<char*>(n);
  for (uint32_t i = 0; i < n; ++i) names[i] = c_str(v.lockstep_participants[i]);
  out.lockstep_participants = {n, n, names, false};
  out.commands_applied = v.commands_applied;
  out.commands_rejected = v.commands_rejected;
  out.participants_dropped = v.participants_dropped;
  out.mean_step_us = v.mean_step_us;
  out.team_messages_delivered = v.team_messages_delivered;
  out.team_messages_dropped_no_route = v.team_messages_dropped_no_route;
  out.team_messages_dropped_lost = v.team_messages_dropped_lost;
  out.team_messages_dropped_invalid = v.team_messages_dropped_invalid;
}

msg::SimulatorStatus DdsType<msg::SimulatorStatus>::from_c(const C& in) {
  msg::SimulatorStatus v;
  v.tick = in.tick;
  v.sim_time_ns = in.sim_time_ns;
  v.robots = in.robots;
  for (uint32_t i = 0; i < in.lockstep_participants._length; ++i)
    v.lockstep_participants.push_back(from_c_str(in.lockstep_participants._buffer[i]));
  v.commands_applied = in.commands_applied;
  v.commands_rejected = in.commands_rejected;
  v.participants_dropped = in.participants_dropped;
  v.mean_step_us = in.mean_step_us;
  v.team_messages_delivered = in.team_messages_delivered;
  v.team_messages_dropped_no_route = in.team_messages_dropped_no_route;
  v.team_messages_dropped_lost = in.team_messages_dropped_lost;
  v.team_messages_dropped_invalid = in.team_messages_dropped_invalid;
  return v;
}

void DdsType<msg::DoorCommand>::to_c(const msg::DoorCommand& v, C& out, Arena&) {
  out.door_id = c_str(v.door_id);
  out.angle = v.angle;
  out.source = c_str(v.source);
}

msg::DoorCommand DdsType<msg::DoorCommand>::from_c(const C& in) {
  return {from_c_str(in.door_id), in.angle, from_c_str(in.source)};
}

}  // namespace autonomy::dds
