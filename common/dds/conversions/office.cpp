#include "common/dds/message_types.hpp"

namespace autonomy::dds {

void DdsType<msg::HandoverRequest>::to_c(const msg::HandoverRequest& v, C& out, Arena&) {
  out.request_id = c_str(v.request_id);
  out.requester = c_str(v.requester);
  out.robot_id = c_str(v.robot_id);
  out.kind = static_cast<autonomy_HandoverKind>(v.kind);
  out.place = c_str(v.place);
  out.object_id = c_str(v.object_id);
}

msg::HandoverRequest DdsType<msg::HandoverRequest>::from_c(const C& in) {
  return {from_c_str(in.request_id), from_c_str(in.requester), from_c_str(in.robot_id),
          static_cast<msg::HandoverKind>(in.kind),  from_c_str(in.place),     from_c_str(in.object_id)};
}

void DdsType<msg::HandoverStatus>::to_c(const msg::HandoverStatus& v, C& out, Arena&) {
  out.request_id = c_str(v.request_id);
  out.robot_id = c_str(v.robot_id);
  out.kind = static_cast<autonomy_HandoverKind>(v.kind);
  out.place = c_str(v.place);
  out.object_id = c_str(v.object_id);
  out.state = static_cast<autonomy_HandoverState>(v.state);
  out.reason = c_str(v.reason);
  out.detail = c_str(v.detail);
  out.helper = c_str(v.helper);
  out.tick = v.tick;
  out.sim_time_ns = v.sim_time_ns;
  out.completes_at_ns = v.completes_at_ns;
}

msg::HandoverStatus DdsType<msg::HandoverStatus>::from_c(const C& in) {
  msg::HandoverStatus v;
  v.request_id = from_c_str(in.request_id);
  v.robot_id = from_c_str(in.robot_id);
  v.kind = static_cast<msg::HandoverKind>(in.kind);
  v.place = from_c_str(in.place);
  v.object_id = from_c_str(in.object_id);
  v.state = static_cast<msg::HandoverState>(in.state);
  v.reason = from_c_str(in.reason);
  v.detail = from_c_str(in.detail);
  v.helper = from_c_str(in.helper);
  v.tick = in.tick;
  v.sim_time_ns = in.sim_time_ns;
  v.completes_at_ns = in.completes_at_ns;
  return v;
}

void DdsType<msg::ObjectState>::to_c(const msg::ObjectState& v, C& out, Arena&) {
  out.object_id = c_str(v.object_id);
  out.kind = c_str(v.kind);
  out.colour = c_str(v.colour);
  out.place = c_str(v.place);
  out.carrier = c_str(v.carrier);
  out.tick = v.tick;
}

msg::ObjectState DdsType<msg::ObjectState>::from_c(const C& in) {
  return {from_c_str(in.object_id), from_c_str(in.kind),    from_c_str(in.colour),
          from_c_str(in.place),     from_c_str(in.carrier), in.tick};
}

}  // namespace autonomy::dds
