#include "common/dds/message_types.hpp"

namespace autonomy::dds {

void DdsType<msg::SpacecraftCommand>::to_c(const msg::SpacecraftCommand& v, C& out, Arena& arena) {
  out.command_id = c_str(v.command_id);
  out.source = c_str(v.source);
  out.tick = v.tick;
  out.device = c_str(v.device);
  out.command = c_str(v.command);
  out.arguments = to_c_strings(v.arguments, arena);
}

msg::SpacecraftCommand DdsType<msg::SpacecraftCommand>::from_c(const C& in) {
  return {from_c_str(in.command_id), from_c_str(in.source),  in.tick,
          from_c_str(in.device),     from_c_str(in.command), from_c_strings(in.arguments)};
}

void DdsType<msg::SpacecraftCommandStatus>::to_c(const msg::SpacecraftCommandStatus& v, C& out,
                                                 Arena&) {
  out.command_id = c_str(v.command_id);
  out.source = c_str(v.source);
  out.device = c_str(v.device);
  out.command = c_str(v.command);
  out.accepted = v.accepted;
  out.reason = c_str(v.reason);
  out.tick = v.tick;
  out.sim_time_ns = v.sim_time_ns;
  out.busy = v.busy;
}

msg::SpacecraftCommandStatus DdsType<msg::SpacecraftCommandStatus>::from_c(const C& in) {
  return {from_c_str(in.command_id),
          from_c_str(in.source),
          from_c_str(in.device),
          from_c_str(in.command),
          in.accepted,
          from_c_str(in.reason),
          in.tick,
          in.sim_time_ns,
          in.busy};
}

void DdsType<msg::SpacecraftTelemetry>::to_c(const msg::SpacecraftTelemetry& v, C& out,
                                             Arena& arena) {
  out.spacecraft = c_str(v.spacecraft);
  out.tick = v.tick;
  out.sim_time_ns = v.sim_time_ns;
  const uint32_t nd = static_cast<uint32_t>(v.devices.size());
  auto* devices = arena.allocate<autonomy_DeviceReport>(nd);
  for (uint32_t i = 0; i < nd; ++i) {
    const msg::DeviceReport& d = v.devices[i];
    devices[i] = {c_str(d.device), c_str(d.mode), c_str(d.confirmed_command),
                  c_str(d.confirmed_command_id), d.confirmed_tick};
  }
  out.devices = {nd, nd, devices, false};
  const uint32_t nr = static_cast<uint32_t>(v.readings.size());
  auto* readings = arena.allocate<autonomy_SensorReading>(nr);
  for (uint32_t i = 0; i < nr; ++i)
    readings[i] = {c_str(v.readings[i].sensor), v.readings[i].value};
  out.readings = {nr, nr, readings, false};
  const msg::AttitudeTelemetry& a = v.attitude;
  out.attitude = {a.qw,
                  a.qx,
                  a.qy,
                  a.qz,
                  c_str(a.pointing_target),
                  c_str(a.turn_target),
                  c_str(a.control_mode),
                  a.rate_deg_s,
                  a.remaining_deg};
  out.propulsion = {v.propulsion.thrust_level, v.propulsion.power_w, v.propulsion.thrust_time_s};
  out.camera = {v.camera.power_w, v.camera.images_taken, v.camera.images_on_target,
                c_str(v.camera.last_image_target)};
  out.power = {v.power.solar_array_w, v.power.load_w, v.power.battery_soc, v.power.battery_wh};
  out.telecom = {c_str(v.telecom.ground_station), v.telecom.downlink_rate_kbps,
                 v.telecom.downlinked_mb};
  out.storage = {v.storage.used_mb, v.storage.capacity_mb};
  out.commands_accepted = v.commands_accepted;
  out.commands_rejected = v.commands_rejected;
  const msg::FaultProtectionTelemetry& fp = v.fault_protection;
  out.fault_protection = {fp.safe_mode,   c_str(fp.reason),          fp.safed_at_ns,
                          fp.safings,     fp.commander_silent_s,     fp.commander_timeout_s};
  out.commands_busy = v.commands_busy;
}

msg::SpacecraftTelemetry DdsType<msg::SpacecraftTelemetry>::from_c(const C& in) {
  msg::SpacecraftTelemetry v;
  v.spacecraft = from_c_str(in.spacecraft);
  v.tick = in.tick;
  v.sim_time_ns = in.sim_time_ns;
  v.devices.reserve(in.devices._length);
  for (uint32_t i = 0; i < in.devices._length; ++i) {
    const auto& d = in.devices._buffer[i];
    v.devices.push_back({from_c_str(d.device), from_c_str(d.mode), from_c_str(d.confirmed_command),
                         from_c_str(d.confirmed_command_id), d.confirmed_tick});
  }
  v.readings.reserve(in.readings._length);
  for (uint32_t i = 0; i < in.readings._length; ++i)
    v.readings.push_back({from_c_str(in.readings._buffer[i].sensor), in.readings._buffer[i].value});
  const auto& a = in.attitude;
  v.attitude = {a.qw,
                a.qx,
                a.qy,
                a.qz,
                from_c_str(a.pointing_target),
                from_c_str(a.turn_target),
                from_c_str(a.control_mode),
                a.rate_deg_s,
                a.remaining_deg};
  v.propulsion = {in.propulsion.thrust_level, in.propulsion.power_w, in.propulsion.thrust_time_s};
  v.camera = {in.camera.power_w, in.camera.images_taken, in.camera.images_on_target,
              from_c_str(in.camera.last_image_target)};
  v.power = {in.power.solar_array_w, in.power.load_w, in.power.battery_soc, in.power.battery_wh};
  v.telecom = {from_c_str(in.telecom.ground_station), in.telecom.downlink_rate_kbps,
               in.telecom.downlinked_mb};
  v.storage = {in.storage.used_mb, in.storage.capacity_mb};
  v.commands_accepted = in.commands_accepted;
  v.commands_rejected = in.commands_rejected;
  const auto& fp = in.fault_protection;
  v.fault_protection = {fp.safe_mode, from_c_str(fp.reason), fp.safed_at_ns,
                        fp.safings,   fp.commander_silent_s,  fp.commander_timeout_s};
  v.commands_busy = in.commands_busy;
  return v;
}

void DdsType<msg::SpacecraftFaultInjection>::to_c(const msg::SpacecraftFaultInjection& v, C& out,
                                                  Arena&) {
  out.fault_id = c_str(v.fault_id);
  out.source = c_str(v.source);
  out.kind = c_str(v.kind);
  out.subject = c_str(v.subject);
  out.value = v.value;
  out.reset_cures = v.reset_cures;
  out.clear = v.clear;
}

msg::SpacecraftFaultInjection DdsType<msg::SpacecraftFaultInjection>::from_c(const C& in) {
  return {from_c_str(in.fault_id),
          from_c_str(in.source),
          from_c_str(in.kind),
          from_c_str(in.subject),
          in.value,
          in.reset_cures,
          in.clear};
}

void DdsType<msg::SpacecraftFaultState>::to_c(const msg::SpacecraftFaultState& v, C& out, Arena&) {
  out.fault_id = c_str(v.fault_id);
  out.kind = c_str(v.kind);
  out.subject = c_str(v.subject);
  out.value = v.value;
  out.active = v.active;
  out.trigger = c_str(v.trigger);
  out.ended_by = c_str(v.ended_by);
  out.since_ns = v.since_ns;
}

msg::SpacecraftFaultState DdsType<msg::SpacecraftFaultState>::from_c(const C& in) {
  return {from_c_str(in.fault_id),
          from_c_str(in.kind),
          from_c_str(in.subject),
          in.value,
          in.active,
          from_c_str(in.trigger),
          from_c_str(in.ended_by),
          in.since_ns};
}

void DdsType<msg::SpacecraftEvent>::to_c(const msg::SpacecraftEvent& v, C& out, Arena&) {
  out.spacecraft = c_str(v.spacecraft);
  out.tick = v.tick;
  out.sim_time_ns = v.sim_time_ns;
  out.kind = c_str(v.kind);
  out.detail = c_str(v.detail);
}

msg::SpacecraftEvent DdsType<msg::SpacecraftEvent>::from_c(const C& in) {
  return {from_c_str(in.spacecraft), in.tick, in.sim_time_ns, from_c_str(in.kind),
          from_c_str(in.detail)};
}

}  // namespace autonomy::dds
