#include "common/dds/message_types.hpp"

namespace autonomy::dds {

void DdsType<msg::DoorState>::to_c(const msg::DoorState& v, C& out, Arena&) {
  out.door_id = c_str(v.door_id);
  out.tick = v.tick;
  out.angle = v.angle;
  out.target_angle = v.target_angle;
  out.closed = v.closed;
  out.blocked = v.blocked;
}

msg::DoorState DdsType<msg::DoorState>::from_c(const C& in) {
  return {from_c_str(in.door_id), in.tick, in.angle, in.target_angle, in.closed, in.blocked};
}

}  // namespace autonomy::dds
