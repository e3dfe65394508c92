#include "common/dds/message_types.hpp"

namespace autonomy::dds {

void DdsType<msg::Heartbeat>::to_c(const msg::Heartbeat& v, C& out, Arena& arena) {
  out.service = c_str(v.service);
  out.instance = c_str(v.instance);
  out.host = c_str(v.host);
  out.pid = v.pid;
  out.state = static_cast<autonomy_ServiceState>(v.state);
  out.uptime_s = v.uptime_s;
  out.period_ms = v.period_ms;
  out.capabilities = to_c_strings(v.capabilities, arena);
  out.world_id = v.world_id;
  out.clock_samples_ignored = v.clock_samples_ignored;
  out.detail = c_str(v.detail);
}

msg::Heartbeat DdsType<msg::Heartbeat>::from_c(const C& in) {
  msg::Heartbeat v;
  v.service = from_c_str(in.service);
  v.instance = from_c_str(in.instance);
  v.host = from_c_str(in.host);
  v.pid = in.pid;
  v.state = static_cast<msg::ServiceState>(in.state);
  v.uptime_s = in.uptime_s;
  v.period_ms = in.period_ms;
  v.capabilities = from_c_strings(in.capabilities);
  v.world_id = in.world_id;
  v.clock_samples_ignored = in.clock_samples_ignored;
  v.detail = from_c_str(in.detail);
  return v;
}

}  // namespace autonomy::dds
