#include "common/dds/message_types.hpp"

namespace autonomy::dds {

void DdsType<msg::RangeScan>::to_c(const msg::RangeScan& v, C& out, Arena&) {
  out.robot_id = c_str(v.robot_id);
  out.tick = v.tick;
  out.angle_min = v.angle_min;
  out.angle_increment = v.angle_increment;
  out.max_range = v.max_range;
  const uint32_t n = static_cast<uint32_t>(v.ranges.size());
  // dds_write copies the sample; the buffer only has to live until then.
  out.ranges = {n, n, n ? const_cast<float*>(v.ranges.data()) : nullptr, false};
}

msg::RangeScan DdsType<msg::RangeScan>::from_c(const C& in) {
  msg::RangeScan v;
  v.robot_id = from_c_str(in.robot_id);
  v.tick = in.tick;
  v.angle_min = in.angle_min;
  v.angle_increment = in.angle_increment;
  v.max_range = in.max_range;
  if (in.ranges._length > 0) v.ranges.assign(in.ranges._buffer, in.ranges._buffer + in.ranges._length);
  return v;
}

void DdsType<msg::PoseEstimate>::to_c(const msg::PoseEstimate& v, C& out, Arena&) {
  out.robot_id = c_str(v.robot_id);
  out.tick = v.tick;
  out.x = v.x;
  out.y = v.y;
  out.theta = v.theta;
}

msg::PoseEstimate DdsType<msg::PoseEstimate>::from_c(const C& in) {
  return {from_c_str(in.robot_id), in.tick, in.x, in.y, in.theta};
}

void DdsType<msg::DoorObservation>::to_c(const msg::DoorObservation& v, C& out, Arena& arena) {
  out.robot_id = c_str(v.robot_id);
  out.tick = v.tick;
  const uint32_t n = static_cast<uint32_t>(v.doors.size());
  auto* doors = arena.allocate<autonomy_DoorSighting>(n);
  for (uint32_t i = 0; i < n; ++i) {
    const auto& d = v.doors[i];
    doors[i].door_id = c_str(d.door_id);
    doors[i].angle_estimate = d.angle_estimate;
    doors[i].distance = d.distance;
    doors[i].bearing = d.bearing;
  }
  out.doors = {n, n, doors, false};
}

msg::DoorObservation DdsType<msg::DoorObservation>::from_c(const C& in) {
  msg::DoorObservation v;
  v.robot_id = from_c_str(in.robot_id);
  v.tick = in.tick;
  v.doors.reserve(in.doors._length);
  for (uint32_t i = 0; i < in.doors._length; ++i) {
    const auto& d = in.doors._buffer[i];
    v.doors.push_back({from_c_str(d.door_id), d.angle_estimate, d.distance, d.bearing});
  }
  return v;
}

}  // namespace autonomy::dds
