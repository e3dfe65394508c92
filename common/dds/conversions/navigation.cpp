#include "common/dds/message_types.hpp"

namespace autonomy::dds {

void DdsType<msg::NavGoal>::to_c(const msg::NavGoal& v, C& out, Arena&) {
  out.robot_id = c_str(v.robot_id);
  out.goal_id = c_str(v.goal_id);
  out.x = v.x;
  out.y = v.y;
  out.tolerance = v.tolerance;
}

msg::NavGoal DdsType<msg::NavGoal>::from_c(const C& in) {
  return {from_c_str(in.robot_id), from_c_str(in.goal_id), in.x, in.y, in.tolerance};
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

}  // namespace autonomy::dds
