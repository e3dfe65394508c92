#include "simulator/core/door.hpp"

#include "simulator/core/number_format.hpp"
#include "simulator/core/shapes.hpp"

#include <algorithm>
#include <limits>

namespace autonomy::sim {

namespace {

double sign(DoorSwing s) { return s == DoorSwing::CounterClockwise ? 1.0 : -1.0; }

geometry::Vec2 unit(double angle) { return {std::cos(angle), std::sin(angle)}; }

}  // namespace

geometry::Vec2 DoorSpec::hinge() const { return position - 0.5 * width * unit(heading); }

DoorLeaf DoorSpec::leaf(double opening_angle) const {
  const geometry::Vec2 h = hinge();
  return {h, h + width * unit(heading + sign(swing) * opening_angle)};
}

std::optional<std::string> door_problem(const DoorSpec& d) {
  if (!std::isfinite(d.position.x()) || !std::isfinite(d.position.y()) || !std::isfinite(d.heading)) {
    return std::string("position and heading must be finite");
  }
  if (!(std::isfinite(d.width) && d.width > 0.0)) {
    return "width must be positive (got " + format_number(d.width) + ")";
  }
  if (!(d.max_angle > 0.0 && d.max_angle <= M_PI)) {
    return "max_angle must be in (0, pi] (got " + format_number(d.max_angle) + ")";
  }
  if (!(d.angle >= 0.0 && d.angle <= d.max_angle)) {
    return "angle " + format_number(d.angle) + " is outside [0, max_angle " + format_number(d.max_angle) + "]";
  }
  return std::nullopt;
}

bool disc_overlaps_leaf(const DoorLeaf& leaf, const geometry::Vec2& center, double radius) {
  return segment_distance(center, leaf.hinge, leaf.tip) < radius + kDoorLeafHalfThicknessM;
}

bool disc_in_sweep(const DoorSpec& door, double from, double to, const geometry::Vec2& center,
                   double radius) {
  const double reach = radius + kDoorLeafHalfThicknessM;
  const geometry::Vec2 h = door.hinge();
  const geometry::Vec2 rel = center - h;
  if (rel.norm() >= door.width + reach) return false;
  if (disc_overlaps_leaf(door.leaf(from), center, radius) || disc_overlaps_leaf(door.leaf(to), center, radius)) {
    return true;
  }
  // Inside the sector between the two leaf positions: its direction from the hinge, measured
  // like an opening angle, lies between them.
  const double phi = sign(door.swing) * geometry::wrap_angle(std::atan2(rel.y(), rel.x()) - door.heading);
  return phi >= std::min(from, to) && phi <= std::max(from, to);
}

DoorSchedule::DoorSchedule(DoorScheduleSpec spec, double initial_angle, Rng rng)
    : spec_(std::move(spec)), open_(initial_angle > 0.0), rng_(rng) {
  if (spec_.kind == DoorScheduleSpec::Kind::Random) draw_next(0.0);
}

void DoorSchedule::draw_next(double from_s) {
  const double rate = open_ ? spec_.random.close_rate_hz : spec_.random.open_rate_hz;
  next_change_s_ = rate > 0.0 ? from_s + rng_.exponential(rate) : std::numeric_limits<double>::infinity();
}

std::optional<double> DoorSchedule::advance(double to_s) {
  std::optional<double> angle;
  switch (spec_.kind) {
    case DoorScheduleSpec::Kind::Fixed: break;
    case DoorScheduleSpec::Kind::Script:
      while (next_event_ < spec_.script.size() && spec_.script[next_event_].time_s <= to_s) {
        angle = spec_.script[next_event_++].angle;
      }
      break;
    case DoorScheduleSpec::Kind::Random:
      while (next_change_s_ <= to_s) {
        open_ = !open_;
        angle = open_ ? spec_.random.open_angle : 0.0;
        draw_next(next_change_s_);
      }
      break;
  }
  now_s_ = std::max(now_s_, to_s);
  return angle;
}

}  // namespace autonomy::sim
