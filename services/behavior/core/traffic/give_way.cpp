#include "services/behavior/core/traffic/give_way.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <stdexcept>
#include <tuple>

namespace autonomy::behavior::traffic {

namespace {

// The points of a path from `from` up to `look_m` along it, `from` included.
std::vector<geometry::Vec2> give_way_stretch(const geometry::Vec2& from, const std::vector<geometry::Vec2>& path,
                                             double look_m) {
  std::vector<geometry::Vec2> out{from};
  double along = 0.0;
  for (const geometry::Vec2& p : path) {
    along += (p - out.back()).norm();
    if (along > look_m) break;
    out.push_back(p);
  }
  return out;
}

double give_way_gap(const std::vector<geometry::Vec2>& a, const std::vector<geometry::Vec2>& b) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& p : a)
    for (const auto& q : b) best = std::min(best, (p - q).norm());
  return best;
}

}  // namespace

bool meets_first(const geometry::Vec2& position, const Claim& claim, const std::vector<Passage>& passages) {
  if (claim.state == ClaimState::Holding) return true;
  return std::any_of(passages.begin(), passages.end(), [&](const Passage& q) { return q.contains(position); });
}

bool standing(const OtherRobot& o) {
  return !o.has_path || o.path.empty() || (o.claim.state == ClaimState::Waiting && o.path.size() <= 1);
}

std::optional<std::string> give_way_to(const std::string& my_id, const geometry::Vec2& me, bool me_first,
                                       const std::vector<geometry::Vec2>& path_ahead,
                                       const std::vector<OtherRobot>& others, const std::vector<Passage>& passages,
                                       double expiry_s, const GiveWaySettings& s) {
  if (!(s.look_m > 0.0) || !(s.clearance_m > 0.0) || !std::isfinite(s.same_way_cos) || !(s.side_search_m > 0.0) ||
      !(s.side_clear_m > 0.0) || !std::isfinite(s.look_m + s.clearance_m + s.side_search_m + s.side_clear_m))
    throw std::invalid_argument("give-way settings: distances must be positive and finite");
  if (path_ahead.empty()) return std::nullopt;
  const std::vector<geometry::Vec2> mine = give_way_stretch(me, path_ahead, s.look_m);
  const geometry::Vec2 my_way = mine.back() - me;
  using Rank = std::tuple<int, std::string>;
  const Rank my_rank{me_first ? 0 : 1, my_id};
  std::optional<std::string> out;
  double nearest = std::numeric_limits<double>::infinity();
  for (const OtherRobot& o : others) {
    if (o.id == my_id || !o.has_itinerary || o.itinerary_age_s > expiry_s || standing(o)) continue;
    const Rank their_rank{meets_first(o.position, o.claim, passages) ? 0 : 1, o.id};
    if (!(their_rank < my_rank)) continue;
    const std::vector<geometry::Vec2> theirs = give_way_stretch(o.position, o.path, s.look_m);
    const geometry::Vec2 their_way = theirs.back() - o.position;
    // Following the same way is the brake's business, not a meeting.
    if (my_way.norm() > 1e-6 && their_way.norm() > 1e-6 &&
        my_way.dot(their_way) > s.same_way_cos * my_way.norm() * their_way.norm())
      continue;
    if (give_way_gap(mine, theirs) >= s.clearance_m) continue;
    const double d = (o.position - me).norm();
    if (d < nearest) {
      nearest = d;
      out = o.id;
    }
  }
  return out;
}

std::optional<geometry::Vec2> side_point(const OccupancyGrid& grid, const geometry::Vec2& me,
                                         const std::vector<geometry::Vec2>& their_path,
                                         const std::vector<Passage>& passages,
                                         const std::vector<geometry::Vec2>& robots, const GiveWaySettings& s) {
  const GridGeometry& g = grid.geometry();
  const auto start = g.cell_at(me);
  if (!start) return std::nullopt;
  const double res = g.resolution_m();
  const auto in_passage = [&](const geometry::Vec2& p) {
    return std::any_of(passages.begin(), passages.end(), [&](const Passage& q) { return q.distance(p) <= res; });
  };
  // Breadth first over free cells (4-neighbours, one cell is `res` of walking), never into a
  // passage box: standing aside must not take the robot through a doorway it has not reserved.
  std::vector<int> steps(g.cell_count(), -1);
  std::deque<GridCell> open{*start};
  steps[g.index(*start)] = 0;
  const int max_steps = static_cast<int>(std::floor(s.side_search_m / res));
  std::optional<geometry::Vec2> best[2];  // [0]: apart from every robot; [1]: any
  double best_score[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  while (!open.empty()) {
    const GridCell c = open.front();
    open.pop_front();
    const int n = steps[g.index(c)];
    const geometry::Vec2 p = g.centre(c);
    if (!grid.blocked(c) && !in_passage(p)) {
      double clear = s.side_clear_m;
      for (const auto& q : their_path) clear = std::min(clear, (q - p).norm());
      // Each 0.1 m further from their path is worth 0.3 m of walking.
      const double score = n * res - 3.0 * clear;
      const bool apart = std::none_of(robots.begin(), robots.end(),
                                      [&](const geometry::Vec2& q) { return (q - p).norm() < s.side_apart_m; });
      for (int k = apart ? 0 : 1; k < 2; ++k) {
        if (score < best_score[k]) {
          best_score[k] = score;
          best[k] = p;
        }
      }
    }
    if (n >= max_steps) continue;
    for (const GridCell d : {GridCell{1, 0}, GridCell{-1, 0}, GridCell{0, 1}, GridCell{0, -1}}) {
      const GridCell m{c.col + d.col, c.row + d.row};
      if (!g.contains(m) || grid.blocked(m) || steps[g.index(m)] >= 0 || in_passage(g.centre(m))) continue;
      steps[g.index(m)] = n + 1;
      open.push_back(m);
    }
  }
  return best[0] ? best[0] : best[1];
}

}  // namespace autonomy::behavior::traffic
