#include "common/dds/message_types.hpp"

namespace autonomy::dds {

void DdsType<msg::NavGoal>::to_c(const msg::NavGoal& v, C& out, Arena&) {
  out.robot_id = c_str(v.robot_id);
  out.goal_id = c_str(v.goal_id);
  out.x = v.x;
  out.y = v.y;
  out.tolerance = v.tolerance;
  out.constraint_set = c_str(v.constraint_set);
}

msg::NavGoal DdsType<msg::NavGoal>::from_c(const C& in) {
  return {from_c_str(in.robot_id), from_c_str(in.goal_id), in.x, in.y, in.tolerance, from_c_str(in.constraint_set)};
}

void DdsType<msg::NavCancel>::to_c(const msg::NavCancel& v, C& out, Arena&) {
  out.robot_id = c_str(v.robot_id);
  out.goal_id = c_str(v.goal_id);
  out.reason = c_str(v.reason);
}

msg::NavCancel DdsType<msg::NavCancel>::from_c(const C& in) {
  return {from_c_str(in.robot_id), from_c_str(in.goal_id), from_c_str(in.reason)};
}

void DdsType<msg::GoalStatus>::to_c(const msg::GoalStatus& v, C& out, Arena&) {
  out.robot_id = c_str(v.robot_id);
  out.goal_id = c_str(v.goal_id);
  out.state = static_cast<autonomy_GoalState>(v.state);
  out.reason = c_str(v.reason);
  out.tick = v.tick;
  out.distance_to_goal = v.distance_to_goal;
}

msg::GoalStatus DdsType<msg::GoalStatus>::from_c(const C& in) {
  return {from_c_str(in.robot_id), from_c_str(in.goal_id), static_cast<msg::GoalState>(in.state),
          from_c_str(in.reason), in.tick, in.distance_to_goal};
}

void DdsType<msg::MissionStatus>::to_c(const msg::MissionStatus& v, C& out, Arena&) {
  out.robot_id = c_str(v.robot_id);
  out.mission = c_str(v.mission);
  out.state = c_str(v.state);
  out.event = c_str(v.event);
  out.reason = c_str(v.reason);
  out.finished = v.finished;
  out.tick = v.tick;
}

msg::MissionStatus DdsType<msg::MissionStatus>::from_c(const C& in) {
  return {from_c_str(in.robot_id), from_c_str(in.mission), from_c_str(in.state), from_c_str(in.event),
          from_c_str(in.reason), in.finished, in.tick};
}

void DdsType<msg::Itinerary>::to_c(const msg::Itinerary& v, C& out, Arena& arena) {
  out.robot_id = c_str(v.robot_id);
  out.tick = v.tick;
  out.sim_time_ns = v.sim_time_ns;
  out.radius = v.radius;
  out.x = v.x;
  out.y = v.y;
  const uint32_t n = static_cast<uint32_t>(v.path.size());
  auto* points = arena.allocate<autonomy_ItineraryPoint>(n);
  for (uint32_t i = 0; i < n; ++i) points[i] = {v.path[i].x, v.path[i].y, v.path[i].t_ns};
  out.path = {n, n, points, false};
  out.passage = c_str(v.passage);
  out.claim = c_str(v.claim);
  out.request_time_ns = v.request_time_ns;
  out.waiting_for = c_str(v.waiting_for);
}

msg::Itinerary DdsType<msg::Itinerary>::from_c(const C& in) {
  msg::Itinerary v;
  v.robot_id = from_c_str(in.robot_id);
  v.tick = in.tick;
  v.sim_time_ns = in.sim_time_ns;
  v.radius = in.radius;
  v.x = in.x;
  v.y = in.y;
  v.path.reserve(in.path._length);
  for (uint32_t i = 0; i < in.path._length; ++i)
    v.path.push_back({in.path._buffer[i].x, in.path._buffer[i].y, in.path._buffer[i].t_ns});
  v.passage = from_c_str(in.passage);
  v.claim = from_c_str(in.claim);
  v.request_time_ns = in.request_time_ns;
  v.waiting_for = from_c_str(in.waiting_for);
  return v;
}

}  // namespace autonomy::dds
