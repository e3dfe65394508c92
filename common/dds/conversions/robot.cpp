#include "common/dds/message_types.hpp"

namespace autonomy::dds {

void DdsType<msg::RobotState>::to_c(const msg::RobotState& v, C& out, Arena&) {
  out.robot_id = c_str(v.robot_id);
  out.tick = v.tick;
  out.sim_time_ns = v.sim_time_ns;
  out.x = v.x;
  out.y = v.y;
  out.theta = v.theta;
  out.vx = v.vx;
  out.vy = v.vy;
  out.omega = v.omega;
  out.kinematics = static_cast<autonomy_Kinematics>(v.kinematics);
  out.radius = v.radius;
  out.max_speed = v.max_speed;
  out.max_omega = v.max_omega;
  out.in_collision = v.in_collision;
}

msg::RobotState DdsType<msg::RobotState>::from_c(const C& in) {
  msg::RobotState v;
  v.robot_id = from_c_str(in.robot_id);
  v.tick = in.tick;
  v.sim_time_ns = in.sim_time_ns;
  v.x = in.x;
  v.y = in.y;
  v.theta = in.theta;
  v.vx = in.vx;
  v.vy = in.vy;
  v.omega = in.omega;
  v.kinematics = static_cast<msg::Kinematics>(in.kinematics);
  v.radius = in.radius;
  v.max_speed = in.max_speed;
  v.max_omega = in.max_omega;
  v.in_collision = in.in_collision;
  return v;
}

void DdsType<msg::VelocityCommand>::to_c(const msg::VelocityCommand& v, C& out, Arena&) {
  out.robot_id = c_str(v.robot_id);
  out.source = c_str(v.source);
  out.tick = v.tick;
  out.vx = v.vx;
  out.vy = v.vy;
  out.omega = v.omega;
}

msg::VelocityCommand DdsType<msg::VelocityCommand>::from_c(const C& in) {
  return {from_c_str(in.robot_id), from_c_str(in.source), in.tick, in.vx, in.vy, in.omega};
}

void DdsType<msg::CommandRejection>::to_c(const msg::CommandRejection& v, C& out, Arena&) {
  out.robot_id = c_str(v.robot_id);
  out.source = c_str(v.source);
  out.tick = v.tick;
  out.reason = c_str(v.reason);
}

msg::CommandRejection DdsType<msg::CommandRejection>::from_c(const C& in) {
  return {from_c_str(in.robot_id), from_c_str(in.source), in.tick, from_c_str(in.reason)};
}

}  // namespace autonomy::dds
