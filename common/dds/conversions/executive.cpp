#include "common/dds/message_types.hpp"

namespace autonomy::dds {

void DdsType<msg::ExecutiveEvent>::to_c(const msg::ExecutiveEvent& v, C& out, Arena&) {
  out.executive = c_str(v.executive);
  out.number = v.number;
  out.tick = v.tick;
  out.sim_time_ns = v.sim_time_ns;
  out.kind = c_str(v.kind);
  out.text = c_str(v.text);
  out.plan_id = c_str(v.plan_id);
}

msg::ExecutiveEvent DdsType<msg::ExecutiveEvent>::from_c(const C& in) {
  return {from_c_str(in.executive), in.number,           in.tick,
          in.sim_time_ns,           from_c_str(in.kind),   from_c_str(in.text),
          from_c_str(in.plan_id)};
}

void DdsType<msg::ExecutiveStatus>::to_c(const msg::ExecutiveStatus& v, C& out, Arena& arena) {
  out.executive = c_str(v.executive);
  out.state = c_str(v.state);
  out.plan_id = c_str(v.plan_id);
  out.tick = v.tick;
  out.plan_origin_s = v.plan_origin_s;
  out.horizon_end_s = v.horizon_end_s;
  out.executing = to_c_strings(v.executing, arena);
  out.goals_achieved = to_c_strings(v.goals_achieved, arena);
  out.goals_lost = to_c_strings(v.goals_lost, arena);
  out.disabled_devices = to_c_strings(v.disabled_devices, arena);
  out.ignored_sensors = to_c_strings(v.ignored_sensors, arena);
  out.replans = v.replans;
  out.horizons = v.horizons;
  out.decision_us_mean = v.decision_us_mean;
  out.decision_us_max = v.decision_us_max;
  out.watchdog_alarm = v.watchdog_alarm;
}

msg::ExecutiveStatus DdsType<msg::ExecutiveStatus>::from_c(const C& in) {
  msg::ExecutiveStatus v;
  v.executive = from_c_str(in.executive);
  v.state = from_c_str(in.state);
  v.plan_id = from_c_str(in.plan_id);
  v.tick = in.tick;
  v.plan_origin_s = in.plan_origin_s;
  v.horizon_end_s = in.horizon_end_s;
  v.executing = from_c_strings(in.executing);
  v.goals_achieved = from_c_strings(in.goals_achieved);
  v.goals_lost = from_c_strings(in.goals_lost);
  v.disabled_devices = from_c_strings(in.disabled_devices);
  v.ignored_sensors = from_c_strings(in.ignored_sensors);
  v.replans = in.replans;
  v.horizons = in.horizons;
  v.decision_us_mean = in.decision_us_mean;
  v.decision_us_max = in.decision_us_max;
  v.watchdog_alarm = in.watchdog_alarm;
  return v;
}

}  // namespace autonomy::dds
