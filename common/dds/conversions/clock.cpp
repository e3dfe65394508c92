#include "common/dds/message_types.hpp"

namespace autonomy::dds {

void DdsType<msg::SimClock>::to_c(const msg::SimClock& v, C& out, Arena&) {
  out.tick = v.tick;
  out.sim_time_ns = v.sim_time_ns;
  out.step_ns = v.step_ns;
  out.mode = static_cast<autonomy_ClockMode>(v.mode);
  out.warp = v.warp;
  out.world_id = v.world_id;
}

msg::SimClock DdsType<msg::SimClock>::from_c(const C& in) {
  return {in.tick, in.sim_time_ns, in.step_ns, static_cast<msg::ClockMode>(in.mode), in.warp, in.world_id};
}

void DdsType<msg::LockstepRegistration>::to_c(const msg::LockstepRegistration& v, C& out, Arena&) {
  out.participant = c_str(v.participant);
  out.active = v.active;
}

msg::LockstepRegistration DdsType<msg::LockstepRegistration>::from_c(const C& in) {
  return {from_c_str(in.participant), in.active};
}

void DdsType<msg::TickAck>::to_c(const msg::TickAck& v, C& out, Arena&) {
  out.participant = c_str(v.participant);
  out.tick = v.tick;
  out.commands_sent = v.commands_sent;
  out.quiet_until_tick = v.quiet_until_tick;
}

msg::TickAck DdsType<msg::TickAck>::from_c(const C& in) {
  return {from_c_str(in.participant), in.tick, in.commands_sent, in.quiet_until_tick};
}

}  // namespace autonomy::dds
