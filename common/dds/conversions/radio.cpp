#include "common/dds/message_types.hpp"

namespace autonomy::dds {

void DdsType<msg::RadioLink>::to_c(const msg::RadioLink& v, C& out, Arena&) {
  out.robot_a = c_str(v.robot_a);
  out.robot_b = c_str(v.robot_b);
  out.tick = v.tick;
  out.signal_dbm = v.signal_dbm;
  out.margin_db = v.margin_db;
  out.connected = v.connected;
}

msg::RadioLink DdsType<msg::RadioLink>::from_c(const C& in) {
  return {from_c_str(in.robot_a), from_c_str(in.robot_b), in.tick, in.signal_dbm, in.margin_db, in.connected};
}

void DdsType<msg::TeamConnectivity>::to_c(const msg::TeamConnectivity& v, C& out, Arena& arena) {
  out.tick = v.tick;
  const uint32_t n = static_cast<uint32_t>(v.components.size());
  auto* components = arena.allocate<autonomy_TeamComponent>(n);
  for (uint32_t i = 0; i < n; ++i) components[i].robots = to_c_strings(v.components[i].robots, arena);
  out.components = {n, n, components, false};
  out.fully_connected = v.fully_connected;
}

msg::TeamConnectivity DdsType<msg::TeamConnectivity>::from_c(const C& in) {
  msg::TeamConnectivity v;
  v.tick = in.tick;
  v.components.reserve(in.components._length);
  for (uint32_t i = 0; i < in.components._length; ++i)
    v.components.push_back({from_c_strings(in.components._buffer[i].robots)});
  v.fully_connected = in.fully_connected;
  return v;
}

void DdsType<msg::TeamMessage>::to_c(const msg::TeamMessage& v, C& out, Arena&) {
  out.from = c_str(v.from);
  out.to = c_str(v.to);
  out.message_id = c_str(v.message_id);
  out.payload = c_str(v.payload);
}

msg::TeamMessage DdsType<msg::TeamMessage>::from_c(const C& in) {
  return {from_c_str(in.from), from_c_str(in.to), from_c_str(in.message_id), from_c_str(in.payload)};
}

void DdsType<msg::TeamDelivery>::to_c(const msg::TeamDelivery& v, C& out, Arena&) {
  out.recipient = c_str(v.recipient);
  out.from = c_str(v.from);
  out.to = c_str(v.to);
  out.message_id = c_str(v.message_id);
  out.payload = c_str(v.payload);
  out.sent_time_ns = v.sent_time_ns;
  out.delivered_time_ns = v.delivered_time_ns;
  out.hops = v.hops;
}

msg::TeamDelivery DdsType<msg::TeamDelivery>::from_c(const C& in) {
  return {from_c_str(in.recipient), from_c_str(in.from),       from_c_str(in.to),      from_c_str(in.message_id),
          from_c_str(in.payload),   in.sent_time_ns, in.delivered_time_ns, in.hops};
}

}  // namespace autonomy::dds
