#include "common/dds/message_types.hpp"

namespace autonomy::dds {

void DdsType<msg::CourierCommand>::to_c(const msg::CourierCommand& v, C& out, Arena&) {
  out.command_id = c_str(v.command_id);
  out.requester = c_str(v.requester);
  out.kind = static_cast<autonomy_CourierCommandKind>(v.kind);
  out.text = c_str(v.text);
  out.job_id = c_str(v.job_id);
  out.object_id = c_str(v.object_id);
  out.object_kind = c_str(v.object_kind);
  out.object_colour = c_str(v.object_colour);
  out.from = c_str(v.from);
  out.to = c_str(v.to);
  out.deadline = c_str(v.deadline);
}

msg::CourierCommand DdsType<msg::CourierCommand>::from_c(const C& in) {
  msg::CourierCommand v;
  v.command_id = from_c_str(in.command_id);
  v.requester = from_c_str(in.requester);
  v.kind = static_cast<msg::CourierCommandKind>(in.kind);
  v.text = from_c_str(in.text);
  v.job_id = from_c_str(in.job_id);
  v.object_id = from_c_str(in.object_id);
  v.object_kind = from_c_str(in.object_kind);
  v.object_colour = from_c_str(in.object_colour);
  v.from = from_c_str(in.from);
  v.to = from_c_str(in.to);
  v.deadline = from_c_str(in.deadline);
  return v;
}

void DdsType<msg::CourierReply>::to_c(const msg::CourierReply& v, C& out, Arena& arena) {
  out.command_id = c_str(v.command_id);
  out.accepted = v.accepted;
  out.job_id = c_str(v.job_id);
  out.action = c_str(v.action);
  out.object = c_str(v.object);
  out.from = c_str(v.from);
  out.to = c_str(v.to);
  out.deadline = c_str(v.deadline);
  out.assumptions = to_c_strings(v.assumptions, arena);
  out.reason = c_str(v.reason);
  out.detail = c_str(v.detail);
  out.word = c_str(v.word);
  out.column = v.column;
  out.suggestions = to_c_strings(v.suggestions, arena);
  out.tick = v.tick;
}

msg::CourierReply DdsType<msg::CourierReply>::from_c(const C& in) {
  msg::CourierReply v;
  v.command_id = from_c_str(in.command_id);
  v.accepted = in.accepted;
  v.job_id = from_c_str(in.job_id);
  v.action = from_c_str(in.action);
  v.object = from_c_str(in.object);
  v.from = from_c_str(in.from);
  v.to = from_c_str(in.to);
  v.deadline = from_c_str(in.deadline);
  v.assumptions = from_c_strings(in.assumptions);
  v.reason = from_c_str(in.reason);
  v.detail = from_c_str(in.detail);
  v.word = from_c_str(in.word);
  v.column = in.column;
  v.suggestions = from_c_strings(in.suggestions);
  v.tick = in.tick;
  return v;
}

void DdsType<msg::CourierJobStatus>::to_c(const msg::CourierJobStatus& v, C& out, Arena&) {
  out.job_id = c_str(v.job_id);
  out.command_id = c_str(v.command_id);
  out.state = static_cast<autonomy_JobState>(v.state);
  out.phase = c_str(v.phase);
  out.robot_id = c_str(v.robot_id);
  out.object_id = c_str(v.object_id);
  out.object_kind = c_str(v.object_kind);
  out.object_colour = c_str(v.object_colour);
  out.from = c_str(v.from);
  out.to = c_str(v.to);
  out.deadline = c_str(v.deadline);
  out.estimated_completion = c_str(v.estimated_completion);
  out.reason = c_str(v.reason);
  out.allocation = c_str(v.allocation);
  out.tick = v.tick;
}

msg::CourierJobStatus DdsType<msg::CourierJobStatus>::from_c(const C& in) {
  msg::CourierJobStatus v;
  v.job_id = from_c_str(in.job_id);
  v.command_id = from_c_str(in.command_id);
  v.state = static_cast<msg::JobState>(in.state);
  v.phase = from_c_str(in.phase);
  v.robot_id = from_c_str(in.robot_id);
  v.object_id = from_c_str(in.object_id);
  v.object_kind = from_c_str(in.object_kind);
  v.object_colour = from_c_str(in.object_colour);
  v.from = from_c_str(in.from);
  v.to = from_c_str(in.to);
  v.deadline = from_c_str(in.deadline);
  v.estimated_completion = from_c_str(in.estimated_completion);
  v.reason = from_c_str(in.reason);
  v.allocation = from_c_str(in.allocation);
  v.tick = in.tick;
  return v;
}

void DdsType<msg::CourierSchedule>::to_c(const msg::CourierSchedule& v, C& out, Arena& arena) {
  out.robot_id = c_str(v.robot_id);
  out.engine = c_str(v.engine);
  out.proved_optimal = v.proved_optimal;
  const uint32_t n = static_cast<uint32_t>(v.stops.size());
  auto* stops = arena.allocate<autonomy_CourierStop>(n);
  for (uint32_t i = 0; i < n; ++i) {
    const msg::CourierStop& s = v.stops[i];
    stops[i] = {c_str(s.job_id), c_str(s.action), c_str(s.place), c_str(s.room), s.arrival_s, s.finish_s};
  }
  out.stops = {n, n, stops, false};
  out.assumptions = to_c_strings(v.assumptions, arena);
  out.late_jobs = v.late_jobs;
  out.total_lateness_s = v.total_lateness_s;
  out.tick = v.tick;
}

msg::CourierSchedule DdsType<msg::CourierSchedule>::from_c(const C& in) {
  msg::CourierSchedule v;
  v.robot_id = from_c_str(in.robot_id);
  v.engine = from_c_str(in.engine);
  v.proved_optimal = in.proved_optimal;
  for (uint32_t i = 0; i < in.stops._length; ++i) {
    const auto& s = in.stops._buffer[i];
    v.stops.push_back({from_c_str(s.job_id), from_c_str(s.action), from_c_str(s.place), from_c_str(s.room),
                       s.arrival_s, s.finish_s});
  }
  v.assumptions = from_c_strings(in.assumptions);
  v.late_jobs = in.late_jobs;
  v.total_lateness_s = in.total_lateness_s;
  v.tick = in.tick;
  return v;
}

void DdsType<msg::CourierReport>::to_c(const msg::CourierReport& v, C& out, Arena&) {
  out.command_id = c_str(v.command_id);
  out.job_id = c_str(v.job_id);
  out.success = v.success;
  out.text = c_str(v.text);
  out.tick = v.tick;
}

msg::CourierReport DdsType<msg::CourierReport>::from_c(const C& in) {
  return {from_c_str(in.command_id), from_c_str(in.job_id), in.success, from_c_str(in.text), in.tick};
}

}  // namespace autonomy::dds
