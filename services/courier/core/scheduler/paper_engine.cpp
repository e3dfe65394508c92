// FAXBOT's SCHEDULE-DELIVERIES (Beetz and Bennewitz), the baseline the other engines are measured
// against. Per courier:
//   1. Every navigation task (a job's pickup and delivery location) is put north or south of the
//      hallway (y above or below hallway_y_m, default the median of the locations' y).
//   2. North is sorted by x descending, south by x ascending; north splits into the part east of
//      the robot and the part west of it; the schedule is West, South, East: one loop around the
//      hallway starting towards the west. Stops at one location stay together.
//   3. While the schedule has a conflict, one conflict is removed, the first one in stop order:
//        - a delivery before its pickup: the delivery moves into the next loop after the
//          pickup, at its place in loop order there;
//        - a pickup while a look-alike object is aboard: the pickup moves to right after that
//          object's delivery (the paper's two red letters: one job completely, then the other);
//        - a pickup beyond capacity: it moves to right after the next delivery;
//        - a missed deadline: the late job's delivery moves to right after its pickup, and if it is
//          still late both move to the front; a move that does not reduce lateness is undone and
//          the job is left late.
// Conflicts still left after 8 rounds per stop (moves that undo each other) fall back to every
// job completely, one after the other, in pickup order: never a look-alike or capacity conflict.
// Several couriers (the paper has one robot): jobs aboard stay with their courier; the others go,
// in job order, to the courier with the fewest jobs so far, ties to the one nearest the pickup.
// Locations without a position keep their index order (x = index, all south).
#include "services/courier/core/scheduler/route_search.hpp"

#include <algorithm>
#include <cmath>

namespace autonomy::courier::scheduling::detail {

namespace {

struct Placed {
  StopRef stop;
  int lap = 0;
  double rank = 0.0;  // position along the loop
};

class PaperEngine final : public SchedulerEngine {
 public:
  const char* name() const override { return "paper"; }

  JobSchedule solve(const SchedulingProblem& problem, const SearchBudget& budget) override {
    if (std::string e = problem_error(problem); !e.empty())
      return failed_schedule(problem, ScheduleStatus::kInvalidProblem, e, name(), 0);
    RouteSearch search(problem, budget);
    const std::size_t couriers = problem.couriers.size();
    std::vector<std::vector<int>> assigned(couriers);
    for (int j : search.free_jobs()) {
      const JobData& d = search.sim().job(j);
      if (search.delivery_only(j)) {
        assigned[static_cast<std::size_t>(search.owner(j))].push_back(j);
        continue;
      }
      std::size_t best = 0;
      for (std::size_t c = 1; c < couriers; ++c) {
        const auto key = [&](std::size_t k) {
          return std::make_pair(assigned[k].size(),
                                search.sim().travel(problem.couriers[k].location, d.pick_loc));
        };
        if (key(c) < key(best)) best = c;
      }
      assigned[best].push_back(j);
    }
    Routes routes(couriers);
    for (std::size_t c = 0; c < couriers; ++c)
      routes[c] = schedule_courier(search, static_cast<int>(c), assigned[c]);
    std::vector<Objective> costs;
    Objective total;
    if (search.total_cost(routes, costs, total))
      return finish_schedule(search, routes, name(), false);
    // A conflict SCHEDULE-DELIVERIES cannot remove (e.g. presence windows it does not reorder
    // for): the order the job selection found, when there is one; infeasible only when proved.
    const JobSelection& sel = search.selection();
    if (!sel.feasible)
      return failed_schedule(
          search, sel.proved ? ScheduleStatus::kInfeasible : ScheduleStatus::kNoSolution,
          sel.reason.empty() ? "no order of the stops satisfies every constraint" : sel.reason,
          name());
    JobSchedule s = finish_schedule(search, sel.witness, name(), false);
    if (s.ok())
      s.reason = "SCHEDULE-DELIVERIES left a conflict it cannot remove: the job selection's order";
    return s;
  }

 private:
  // The loop position of every location: West (north, descending x), South (ascending x),
  // East (north, descending x), as ranks 0, 1, 2, ...
  static std::vector<double> loop_ranks(const SchedulingProblem& p, int robot_location) {
    const std::size_t n = p.locations.size();
    std::vector<double> x(n), y(n);
    bool positions = true;
    for (std::size_t i = 0; i < n; ++i) {
      positions = positions && p.locations[i].x_m.has_value();
      x[i] = p.locations[i].x_m.value_or(static_cast<double>(i));
      y[i] = p.locations[i].y_m.value_or(0.0);
    }
    double hallway = 0.0;
    if (p.hallway_y_m) {
      hallway = *p.hallway_y_m;
    } else if (positions) {
      std::vector<double> sorted = y;
      std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(n / 2),
                       sorted.end());
      hallway = sorted[n / 2];
    }
    const double robot_x = x[static_cast<std::size_t>(robot_location)];
    std::vector<std::size_t> west, south, east;
    for (std::size_t i = 0; i < n; ++i) {
      const bool north = positions && y[i] > hallway;
      if (!north)
        south.push_back(i);
      else if (x[i] > robot_x)
        east.push_back(i);
      else
        west.push_back(i);
    }
    auto by_x = [&](bool descending) {
      return [&x, descending](std::size_t a, std::size_t b) {
        return descending ? x[a] > x[b] : x[a] < x[b];
      };
    };
    std::stable_sort(west.begin(), west.end(), by_x(true));
    std::stable_sort(south.begin(), south.end(), by_x(false));
    std::stable_sort(east.begin(), east.end(), by_x(true));
    std::vector<double> rank(n);
    double r = 0.0;
    for (const auto* part : {&west, &south, &east})
      for (std::size_t i : *part) rank[i] = r++;
    return rank;
  }

  static std::vector<StopRef> stops_of(const std::vector<Placed>& placed) {
    std::vector<StopRef> out;
    for (const Placed& p : placed) out.push_back(p.stop);
    return out;
  }

  static int index_of(const std::vector<Placed>& placed, StopRef s) {
    for (std::size_t i = 0; i < placed.size(); ++i)
      if (placed[i].stop == s) return static_cast<int>(i);
    return -1;
  }

  static void sort_by_loop(std::vector<Placed>& placed, std::size_t from) {
    std::stable_sort(placed.begin() + static_cast<std::ptrdiff_t>(from), placed.end(),
                     [](const Placed& a, const Placed& b) {
                       return a.lap != b.lap ? a.lap < b.lap : a.rank < b.rank;
                     });
  }

  std::vector<StopRef> schedule_courier(RouteSearch& search, int courier,
                                        const std::vector<int>& jobs) {
    const SchedulingProblem& p = search.problem();
    const RouteSimulator& sim = search.sim();
    const auto rank = loop_ranks(p, p.couriers[static_cast<std::size_t>(courier)].location);
    const auto& prefix = p.couriers[static_cast<std::size_t>(courier)].forced_prefix;
    std::vector<Placed> placed;
    for (StopRef s : prefix) placed.push_back({s, -1, 0.0});
    const std::size_t fixed = placed.size();
    for (int j : jobs) {
      const JobData& d = sim.job(j);
      if (!search.delivery_only(j))
        placed.push_back({{j, StopKind::kPickup}, 0, rank[static_cast<std::size_t>(d.pick_loc)]});
      // Same location: pickups first (a tiny rank offset).
      placed.push_back(
          {{j, StopKind::kDelivery}, 0, rank[static_cast<std::size_t>(d.del_loc)] + 0.5});
    }
    sort_by_loop(placed, fixed);
    std::vector<int> deadline_moves(p.jobs.size(), 0);
    const std::size_t limit = 8 * placed.size() + 8;
    for (std::size_t round = 0; round < limit && !search.stopped(); ++round) {
      if (!remove_a_conflict(search, courier, placed, fixed, deadline_moves)) break;
    }
    Objective cost;
    if (search.route_cost(courier, stops_of(placed), cost)) return stops_of(placed);
    // Conflicts left (moves that undo each other): every job completely, one after the other, in
    // the order of the pickups, objects already aboard first. Always free of look-alike and
    // capacity conflicts.
    std::vector<StopRef> sequential(prefix.begin(), prefix.end());
    for (std::size_t k = fixed; k < placed.size(); ++k)
      if (placed[k].stop.kind == StopKind::kDelivery && search.delivery_only(placed[k].stop.job))
        sequential.push_back(placed[k].stop);
    for (std::size_t k = fixed; k < placed.size(); ++k)
      if (placed[k].stop.kind == StopKind::kPickup) {
        sequential.push_back(placed[k].stop);
        sequential.push_back({placed[k].stop.job, StopKind::kDelivery});
      }
    return sequential;
  }

  // Removes the first conflict; false when there is none left (or none it can remove).
  bool remove_a_conflict(RouteSearch& search, int courier, std::vector<Placed>& placed,
                         std::size_t fixed, std::vector<int>& deadline_moves) {
    const RouteSimulator& sim = search.sim();
    const int capacity = search.problem().couriers[static_cast<std::size_t>(courier)].capacity;
    RouteState s = sim.start(courier);
    for (std::size_t k = 0; k < placed.size(); ++k) {
      const StopRef stop = placed[k].stop;
      if (stop.kind == StopKind::kDelivery && !s.carries(stop.job)) {
        if (k < fixed) return false;
        const int pick = index_of(placed, {stop.job, StopKind::kPickup});
        if (pick < 0) return false;  // an object neither aboard nor picked up: not ours to fix
        // Into the next loop after the pickup: past the pickup's own loop, in loop order there.
        Placed moving = placed[k];
        moving.lap = placed[static_cast<std::size_t>(pick)].lap + 1;
        placed.erase(placed.begin() + static_cast<std::ptrdiff_t>(k));
        std::size_t at = static_cast<std::size_t>(pick);  // the pickup moved up by one
        while (at < placed.size() &&
               (placed[at].lap < moving.lap ||
                (placed[at].lap == moving.lap && placed[at].rank <= moving.rank)))
          ++at;
        placed.insert(placed.begin() + static_cast<std::ptrdiff_t>(at), moving);
        return true;
      }
      if (stop.kind == StopKind::kPickup && k >= fixed) {
        int blocker = -1;
        for (int i = 0; i < s.load; ++i) {
          const int other = s.aboard[static_cast<std::size_t>(i)];
          if (sim.job(other).cls == sim.job(stop.job).cls) blocker = other;
        }
        if (blocker >= 0 || s.load >= capacity) {
          // After the blocker's delivery, or after the next delivery of anything aboard.
          int after = -1;
          for (std::size_t m = k + 1; m < placed.size() && after < 0; ++m) {
            const StopRef o = placed[m].stop;
            if (o.kind == StopKind::kDelivery &&
                (blocker < 0 ? s.carries(o.job) : o.job == blocker))
              after = static_cast<int>(m);
          }
          if (after < 0) return false;
          Placed moving = placed[k];
          moving.lap = placed[static_cast<std::size_t>(after)].lap;
          moving.rank = placed[static_cast<std::size_t>(after)].rank;
          placed.insert(placed.begin() + after + 1, moving);
          placed.erase(placed.begin() + static_cast<std::ptrdiff_t>(k));
          return true;
        }
      }
      if (!search.step(courier, s, stop)) return false;  // no route: nothing the sort can fix
    }
    return remove_missed_deadline(search, courier, placed, fixed, deadline_moves);
  }

  bool remove_missed_deadline(RouteSearch& search, int courier, std::vector<Placed>& placed,
                              std::size_t fixed, std::vector<int>& deadline_moves) {
    const RouteSimulator& sim = search.sim();
    Objective before;
    if (!search.route_cost(courier, stops_of(placed), before) || before.late_jobs == 0)
      return false;
    // The first late job whose moves are not used up.
    RouteState s = sim.start(courier);
    int late = -1;
    for (const Placed& pl : placed) {
      const int had = s.cost.late_jobs;
      if (!search.step(courier, s, pl.stop)) return false;
      if (s.cost.late_jobs > had && deadline_moves[static_cast<std::size_t>(pl.stop.job)] < 2 &&
          static_cast<std::size_t>(index_of(placed, pl.stop)) >= fixed) {
        late = pl.stop.job;
        break;
      }
    }
    if (late < 0) return false;
    const auto backup = placed;
    int& moves = deadline_moves[static_cast<std::size_t>(late)];
    const int d = index_of(placed, {late, StopKind::kDelivery});
    const int pickup_at = index_of(placed, {late, StopKind::kPickup});
    if (d < 0 || static_cast<std::size_t>(d) < fixed) {
      // A stop of the forced prefix never moves (and the prefix would lose its length).
      moves = 2;
      return true;
    }
    // A pickup in the prefix stays there: the delivery's only move is to just after the prefix.
    const bool pickup_forced = pickup_at >= 0 && static_cast<std::size_t>(pickup_at) < fixed;
    Placed delivery = placed[static_cast<std::size_t>(d)];
    placed.erase(placed.begin() + d);
    const int pk = index_of(placed, {late, StopKind::kPickup});
    // Moved stops take keys that keep them where they are when the loop is sorted again.
    if (pickup_forced) {
      delivery.lap = -1;
      delivery.rank = -1e9 + static_cast<double>(fixed_front_++);
      placed.insert(placed.begin() + static_cast<std::ptrdiff_t>(fixed), delivery);
      moves = 1;  // one move only (counted below)
    } else if (moves == 0 && pk >= 0) {
      delivery.lap = placed[static_cast<std::size_t>(pk)].lap;
      delivery.rank = placed[static_cast<std::size_t>(pk)].rank + 0.25;
      placed.insert(placed.begin() + pk + 1, delivery);
    } else {
      // Both to the front, right after the forced prefix.
      std::vector<Placed> front;
      if (pk >= 0) {
        front.push_back(placed[static_cast<std::size_t>(pk)]);
        placed.erase(placed.begin() + pk);
      }
      front.push_back(delivery);
      for (Placed& f : front) f.lap = -1, f.rank = -1e9 + static_cast<double>(fixed_front_++);
      placed.insert(placed.begin() + static_cast<std::ptrdiff_t>(fixed), front.begin(),
                    front.end());
    }
    ++moves;
    Objective after;
    const bool ok = search.route_cost(courier, stops_of(placed), after);
    if (!ok ||
        !(after.late_jobs < before.late_jobs ||
          (after.late_jobs == before.late_jobs && after.lateness_s < before.lateness_s - 1e-6))) {
      placed = backup;
    }
    return true;  // either improved or this job's move is used up: look again
  }

  int fixed_front_ = 0;  // order of the stops moved to the front
};

}  // namespace

std::unique_ptr<SchedulerEngine> make_paper_engine() {
  return std::make_unique<PaperEngine>();
}

}  // namespace autonomy::courier::scheduling::detail
