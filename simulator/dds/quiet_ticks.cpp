// SimulatorNode's quiet ticks (idl/clock.idl): when every lockstep participant declared that it
// needs no tick before a later one, and nothing a participant reads changes, the world steps
// without publishing. A day in the office has its couriers parked most of the time: its ticks
// cost a world step instead of a round of DDS samples through every process.
#include "simulator/dds/simulator_node.hpp"

#include "simulator/dds/spacecraft_area.hpp"

namespace autonomy::sim {

namespace {

bool same_pose(const geometry::Pose2& a, const geometry::Pose2& b) {
  return a.x == b.x && a.y == b.y && a.theta == b.theta;
}

}  // namespace

bool SimulatorNode::may_stay_quiet(const std::vector<RobotStatus>& robots) {
  if (!options_.quiet_ticks || !lockstep() || spacecraft_ || wake_ || radio_dirty_) return false;
  if (!barrier_.quiet(tick_) || !unsynchronised_commands_.empty() || !spawn_requests_.empty()) return false;
  if (relay_.pending() > 0) return false;  // team messages on their way must be delivered on time
  for (const RobotStatus& r : robots) {
    const auto published = published_poses_.find(r.id);
    if (published == published_poses_.end() || !same_pose(published->second, r.pose)) return false;
    if (r.vx != 0.0 || r.vy != 0.0 || r.omega != 0.0) return false;
  }
  if (!doors_as_published()) return false;
  // Last, as it has an effect: a handover that ends now is published with this tick, which then
  // is published as a whole.
  return !update_office(robots);
}

void SimulatorNode::keep_quiet(const std::vector<RobotStatus>& robots) {
  quiet_ = true;
  ++quiet_ticks_;
  for (const RobotStatus& r : robots) record_robot(r);
  record_metrics(robots);
  const double now_s = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  barrier_.begin_tick(tick_, now_s);  // acks of earlier ticks are stale from now on
}

void SimulatorNode::continue_quietly() {
  quiet_continue_.reset();
  advance_while_complete();
}

}  // namespace autonomy::sim
