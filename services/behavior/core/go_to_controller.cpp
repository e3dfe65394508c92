#include "services/behavior/core/go_to_controller.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace autonomy::behavior {

namespace {

bool positive_finite_limit(double v) { return std::isfinite(v) && v > 0.0; }

// True when every cell the segment a -> b touches is reachable, walking the cells in order
// (Amanatides & Woo, "A fast voxel traversal algorithm", 1987). Exact rather than sampled: a robot
// that moves along the segment stays in cells the field can route from, so it never clips a
// blocked corner and then has to escape back. Passing exactly through a grid corner needs both
// side cells, as diagonal moves in the field do. The caller has checked a's own cell.
bool visible(const CostToGoField& field, const geometry::Vec2& a, const geometry::Vec2& b) {
  const auto& g = field.geometry();
  const auto start = g.cell_at(a);
  if (!start) return false;
  const double res = g.resolution_m();
  const geometry::Vec2 d = b - a;
  const int step_c = d.x() > 0.0 ? 1 : (d.x() < 0.0 ? -1 : 0);
  const int step_r = d.y() > 0.0 ? 1 : (d.y() < 0.0 ? -1 : 0);
  constexpr double kNever = std::numeric_limits<double>::infinity();
  // t in [0, 1] along the segment at which the next column / row boundary is crossed.
  const auto first_crossing = [res](double from, double delta, int cell, int step) {
    if (step == 0) return kNever;
    const double boundary = (step > 0 ? cell + 1 : cell) * res;
    return (boundary - from) / delta;
  };
  double t_col = first_crossing(a.x(), d.x(), start->col, step_c);
  double t_row = first_crossing(a.y(), d.y(), start->row, step_r);
  const double dt_col = step_c != 0 ? res / std::abs(d.x()) : kNever;
  const double dt_row = step_r != 0 ? res / std::abs(d.y()) : kNever;
  constexpr double kSameCrossing = 1e-9;

  GridCell cell = *start;
  while (std::min(t_col, t_row) <= 1.0) {
    if (std::abs(t_col - t_row) <= kSameCrossing) {
      if (!field.reachable({cell.col + step_c, cell.row}) ||
          !field.reachable({cell.col, cell.row + step_r})) {
        return false;
      }
      cell = {cell.col + step_c, cell.row + step_r};
      t_col += dt_col;
      t_row += dt_row;
    } else if (t_col < t_row) {
      cell.col += step_c;
      t_col += dt_col;
    } else {
      cell.row += step_r;
      t_row += dt_row;
    }
    if (!field.reachable(cell)) return false;
  }
  return true;
}

}  // namespace

GoToController::GoToController(Kinematics kinematics, MotionLimits limits, GoToConfig config)
    : kinematics_(kinematics), limits_(limits), config_(config) {
  if (!positive_finite_limit(limits.max_speed_mps) || !positive_finite_limit(limits.max_omega_rps)) {
    throw std::invalid_argument("max speed and max omega must be positive and finite");
  }
  if (!positive_finite_limit(config.lookahead_m) || !positive_finite_limit(config.slowdown_radius_m) ||
      !positive_finite_limit(config.heading_gain) || !positive_finite_limit(config.turn_in_place_rad)) {
    throw std::invalid_argument("go-to controller parameters must be positive and finite");
  }
}

GoToDecision GoToController::command(const geometry::Pose2& pose, const CostToGoField& field,
                                     double tolerance_m) const {
  GoToDecision d;
  const geometry::Vec2 p = pose.position();
  if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.theta)) return d;
  const double to_goal = (field.goal() - p).norm();
  if (to_goal <= tolerance_m) {
    d.outcome = GoToOutcome::Arrived;
    d.target = field.goal();
    return d;
  }
  if (!field.has_route_anywhere()) return d;

  const double speed_cap = limits_.max_speed_mps * std::min(1.0, to_goal / config_.slowdown_radius_m);
  if (std::isfinite(field.cost_at(p))) {
    d.outcome = GoToOutcome::Following;
    d.target = choose_target(p, field);
  } else {
    const auto refuge = field.nearest_reachable(p, config_.lookahead_m);
    if (!refuge) return d;
    d.outcome = GoToOutcome::Escaping;
    d.target = field.geometry().centre(*refuge);
  }
  d.command = drive_towards(pose, d.target, speed_cap);
  return d;
}

geometry::Vec2 GoToController::choose_target(const geometry::Vec2& p,
                                             const CostToGoField& field) const {
  const double lookahead = config_.lookahead_m;
  if ((field.goal() - p).norm() <= lookahead && visible(field, p, field.goal())) return field.goal();

  // Candidates ranked by estimated remaining path; line of sight is tested in rank order, so most
  // calls test only a handful of segments.
  const auto& g = field.geometry();
  const double res = g.resolution_m();
  const int c0 = std::max(0, static_cast<int>(std::floor((p.x() - lookahead) / res)));
  const int r0 = std::max(0, static_cast<int>(std::floor((p.y() - lookahead) / res)));
  const int c1 = std::min(g.cols() - 1, static_cast<int>(std::floor((p.x() + lookahead) / res)));
  const int r1 = std::min(g.rows() - 1, static_cast<int>(std::floor((p.y() + lookahead) / res)));
  // (score, index): index breaks ties, so the order is total and the first visible candidate is
  // the same whatever the heap does. A heap, not a sort: most calls look at a handful of the
  // hundreds of candidates. The buffer is kept between calls (one command per tick).
  std::vector<std::tuple<double, std::size_t>>& ranked = ranked_;
  ranked.clear();
  for (int row = r0; row <= r1; ++row) {
    for (int col = c0; col <= c1; ++col) {
      const GridCell c{col, row};
      const float cost = field.cost(c);
      if (!std::isfinite(cost)) continue;
      const double dist = (g.centre(c) - p).norm();
      if (dist > lookahead) continue;
      ranked.emplace_back(static_cast<double>(cost) + dist, g.index(c));
    }
  }
  const auto later = std::greater<std::tuple<double, std::size_t>>();
  std::make_heap(ranked.begin(), ranked.end(), later);
  for (auto end = ranked.end(); end != ranked.begin(); --end) {
    std::pop_heap(ranked.begin(), end, later);  // the best candidate left moves to end - 1
    const auto centre = g.centre(g.cell(std::get<1>(*(end - 1))));
    if (visible(field, p, centre)) return centre;
  }
  // Unreachable in practice: the robot's own cell is reachable and its centre is always visible.
  return p;
}

VelocityCommand GoToController::drive_towards(const geometry::Pose2& pose,
                                              const geometry::Vec2& target, double speed_cap) const {
  VelocityCommand cmd;
  const geometry::Vec2 delta = target - pose.position();
  const double dist = delta.norm();
  if (dist < 1e-9) return cmd;
  const double speed = std::clamp(speed_cap, 0.0, limits_.max_speed_mps);

  if (kinematics_ == Kinematics::Holonomic) {
    const geometry::Vec2 v = delta * (speed / dist);
    // Rounding can put |v| a few ulps above the limit; the limit is a contract, not a goal.
    const double norm = v.norm();
    const double shrink = norm > limits_.max_speed_mps ? limits_.max_speed_mps / norm : 1.0;
    cmd.vx = v.x() * shrink;
    cmd.vy = v.y() * shrink;
    return cmd;
  }

  const double error = geometry::wrap_angle(std::atan2(delta.y(), delta.x()) - pose.theta);
  cmd.omega = std::clamp(config_.heading_gain * error, -limits_.max_omega_rps, limits_.max_omega_rps);
  const double alignment = 1.0 - std::abs(error) / config_.turn_in_place_rad;
  cmd.vx = alignment > 0.0 ? speed * alignment : 0.0;
  return cmd;
}

}  // namespace autonomy::behavior
