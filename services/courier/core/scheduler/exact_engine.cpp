// The exact engine: branch and bound over partial routes of one courier, breadth first by the
// number of stops done, with
//   - an incumbent from the large engine's search (greedy dispatch, descent, a few ruin and
//     recreate rounds), so pruning starts at once;
//   - a lower bound per partial route (lower_bound below: earliest completions, handover and
//     travel time still needed, on-time slot matching); travel is bounded by the farthest place
//     still to visit, only when the three terms before it tie with the incumbent;
//   - dominance: two partial routes that picked up and delivered the same jobs and stand at the
//     same location have the same choices left, and every future cost term is non-decreasing in
//     the start time (waiting for presence is allowed, deadlines are soft). So one that is there
//     no earlier and no better lexicographically than another cannot lead to anything better,
//     and is dropped. Breadth first, every label of a state is known before any is expanded, so
//     only non-dominated ones are (depth first expanded about as many later-dominated labels as
//     surviving ones, measured). The textbook dynamic program (reference_dp.hpp) keeps the same
//     labels but without bound or incumbent.
// Several couriers: every assignment of the waiting jobs to couriers, each courier's job set
// solved once (memoised); refused (large engine's answer, not proved) beyond 2^14 assignments.
#include "services/courier/core/scheduler/route_search.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace autonomy::courier::scheduling::detail {

namespace {

constexpr int kMaxJobsPerCourier = 30;
// Partial routes kept at most (about 160 bytes each): beyond, the search gives up, not proved.
constexpr std::size_t kMaxLabels = 1u << 19;
constexpr std::uint64_t kMaxAssignments = 1u << 14;
constexpr int kIncumbentRounds = 5;  // ruin-and-recreate rounds without improvement

// All-pairs shortest travel (the matrix may not obey the triangle inequality; bounds must).
std::vector<double> shortest_travel(const SchedulingProblem& p) {
  const std::size_t n = p.locations.size();
  std::vector<double> d = p.travel.values();
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t i = 0; i < n; ++i) {
      const double ik = d[i * n + k];
      if (!(ik < kNoRoute)) continue;
      for (std::size_t j = 0; j < n; ++j) d[i * n + j] = std::min(d[i * n + j], ik + d[k * n + j]);
    }
  return d;
}

// One courier, a given set of jobs, from the state after its forced prefix.
class CourierSearch {
 public:
  CourierSearch(RouteSearch& rs, const std::vector<double>& shortest, int courier,
                const std::vector<int>& jobs, const RouteState& start, const SearchBudget& budget)
      : rs_(rs),
        sim_(rs.sim()),
        shortest_(shortest),
        courier_(courier),
        jobs_(jobs),
        start_(start),
        budget_(budget),
        n_(rs.problem().locations.size()),
        capacity_(rs.problem().couriers[static_cast<std::size_t>(courier)].capacity) {
    for (std::size_t i = 0; i < jobs_.size(); ++i)
      if (start_.carries(jobs_[i])) initially_picked_ |= 1u << i;
    all_ = jobs_.size() == 32 ? ~0u : (1u << jobs_.size()) - 1u;
    // Places this search can be at: the start and the jobs' stops, with local ids for masks.
    local_.assign(n_, -1);
    auto add = [&](int loc) {
      if (local_[static_cast<std::size_t>(loc)] < 0) {
        local_[static_cast<std::size_t>(loc)] = static_cast<int>(places_.size());
        places_.push_back(loc);
      }
    };
    add(start_.loc);
    for (int j : jobs_) {
      const JobData& d = sim_.job(j);
      if (!start_.carries(j)) add(d.pick_loc);
      add(d.del_loc);
    }
    // Per place, the other places by travel time to it (nearest first).
    nearest_.resize(places_.size());
    for (std::size_t a = 0; a < places_.size(); ++a) {
      for (std::size_t b = 0; b < places_.size(); ++b)
        if (a != b) nearest_[a].push_back({sp(places_[b], places_[a]), static_cast<int>(b)});
      std::sort(nearest_[a].begin(), nearest_[a].end());
    }
    masks_ok_ = places_.size() <= 64;
    for (std::size_t i = 0; i < jobs_.size(); ++i) by_deadline_.push_back(static_cast<int>(i));
    std::sort(by_deadline_.begin(), by_deadline_.end(), [&](int x, int y) {
      return sim_.job(jobs_[static_cast<std::size_t>(x)]).deadline <
             sim_.job(jobs_[static_cast<std::size_t>(y)]).deadline;
    });
  }

  // Returns true when the search finished (the best found is optimal), false when the budget
  // stopped it. `incumbent` (may be empty) is a complete route for these jobs with its cost.
  bool run(const Objective& incumbent_cost, const std::vector<StopRef>* incumbent) {
    best_ = incumbent_cost;
    if (incumbent) best_route_ = *incumbent, found_ = true;
    search();
    return !stopped_;
  }
  bool found() const { return found_; }
  const Objective& best() const { return best_; }
  const std::vector<StopRef>& best_route() const { return best_route_; }
  std::uint64_t nodes() const { return nodes_; }
  bool out_of_memory() const { return out_of_memory_; }

 private:
  double sp(int a, int b) const {
    return shortest_[static_cast<std::size_t>(a) * n_ + static_cast<std::size_t>(b)];
  }

  // False when some job left cannot be finished at all from s. The bound combines, for the jobs
  // left (r of them):
  //   e_j  earliest completion of job j if it were done next, alone;
  //   w_j  the time job j's remaining stops take at least: their handovers, plus the travel into
  //        each place still to visit, charged to the first job with a stop there (none for the
  //        place the courier stands at): from the nearest place the courier can come from (where
  //        it is, or another place still to visit). Distinct places need distinct legs, so the
  //        sum of w over any k jobs bounds the time those k take;
  //   c_k  a lower bound on the k-th smallest completion: max(e_(k), t + the k smallest w_j
  //        (those k jobs' stops are all done by then), c_(k-1) + the shortest delivery handover);
  //   late jobs >= max(#{e_j > d_j}, jobs that cannot get an on-time slot among the c_k, matched
  //        greedily by deadline: slots are prefixes, so greedy is exact);
  //   lateness >= max(sum max(0, e_j - d_j), sum max(0, c_k - d_(k)) with deadlines sorted: the
  //        sorted matching minimises a sum of a convex function of c - d);
  //   completion >= sum (c_k - now).
  bool lower_bound(const RouteState& s, std::uint32_t picked, std::uint32_t delivered,
                   Objective& lb) {
    const SchedulingProblem& p = rs_.problem();
    lb = s.cost;
    double* e = earliest_;
    double* work = handover_;
    double* due = due_;
    // Travel into each place still to visit, charged to one stop there (the first, in job
    // order); the courier comes from its current place or another place still to visit. Nothing
    // for stops where the courier stands now.
    std::uint64_t active = 0;
    const int here = local_[static_cast<std::size_t>(s.loc)];
    if (masks_ok_) {
      active |= 1ull << here;
      for (std::size_t i = 0; i < jobs_.size(); ++i) {
        if (delivered >> i & 1u) continue;
        const JobData& d = sim_.job(jobs_[i]);
        if (!(picked >> i & 1u)) active |= 1ull << local_[static_cast<std::size_t>(d.pick_loc)];
        active |= 1ull << local_[static_cast<std::size_t>(d.del_loc)];
      }
    }
    std::uint64_t charged = masks_ok_ ? 1ull << here : ~0ull;
    auto inbound = [&](int loc) {
      if (!masks_ok_) return 0.0;
      const int a = local_[static_cast<std::size_t>(loc)];
      if (charged >> a & 1ull) return 0.0;
      charged |= 1ull << a;
      for (const auto& [t, src] : nearest_[static_cast<std::size_t>(a)])
        if (active >> src & 1ull) return t < kNoRoute ? t : 0.0;
      return 0.0;
    };
    int r = 0;
    int late_alone = 0;
    double lateness_alone = 0.0;
    for (std::size_t i = 0; i < jobs_.size(); ++i) {
      if (delivered >> i & 1u) continue;
      const JobData& d = sim_.job(jobs_[i]);
      double t = s.t;
      int loc = s.loc;
      double handovers = d.del_dur;
      if (!(picked >> i & 1u)) {
        t = start_within(d.pick_windows, t + sp(loc, d.pick_loc), d.pick_dur) + d.pick_dur;
        loc = d.pick_loc;
        handovers += d.pick_dur + inbound(d.pick_loc);
      }
      handovers += inbound(d.del_loc);
      t = start_within(d.del_windows, t + sp(loc, d.del_loc), d.del_dur) + d.del_dur;
      if (!(t < kNoRoute)) return false;
      if (t > d.deadline + 1e-9) {
        ++late_alone;
        lateness_alone += t - d.deadline;
      }
      e[r] = t;
      work[r] = handovers;
      ++r;
    }
    int q = 0;
    for (int i : by_deadline_)
      if (!(delivered >> i & 1u)) due[q++] = sim_.job(jobs_[static_cast<std::size_t>(i)]).deadline;
    std::sort(e, e + r);
    std::sort(work, work + r);
    double previous = -kNoRoute;
    double busy = s.t;
    const double gap = sim_.min_delivery_duration();
    double completion = 0.0, lateness_sorted = 0.0;
    for (int k = 0; k < r; ++k) {
      busy += work[k];
      const double c = std::max({e[k], busy, previous + gap});
      slot_[k] = c;
      completion += c - p.now_s;
      if (c > due[k] + 1e-9) lateness_sorted += c - due[k];
      previous = c;
    }
    // Greedy on-time matching: deadlines ascending, each takes the earliest free slot if on time.
    int next_slot = 0, on_time = 0;
    for (int k = 0; k < r; ++k)
      if (next_slot < r && slot_[next_slot] <= due[k] + 1e-9) ++next_slot, ++on_time;
    lb.late_jobs += std::max(late_alone, r - on_time);
    lb.lateness_s += std::max(lateness_alone, lateness_sorted);
    lb.completion_s += completion;
    return true;
  }

  double travel_bound(const RouteState& s, std::uint32_t picked, std::uint32_t delivered) const {
    double far = 0.0;
    for (std::size_t i = 0; i < jobs_.size(); ++i) {
      if (delivered >> i & 1u) continue;
      const JobData& d = sim_.job(jobs_[i]);
      far = std::max(far, sp(s.loc, d.del_loc));
      if (!(picked >> i & 1u)) far = std::max(far, sp(s.loc, d.pick_loc));
    }
    return far;
  }

  // One partial route: its state, which jobs it picked up and delivered, how it got here.
  struct Entry {
    RouteState state;
    std::uint32_t picked = 0;
    std::uint32_t delivered = 0;
    int parent = -1;
    StopRef stop;
    int next = -1;  // the next label of the same state
    bool alive = true;
  };

  // Open addressing from a state (picked, delivered, location) to its chain of labels.
  struct StateTable {
    struct Slot {
      std::uint64_t masks = 0;
      int loc = -1;
      int head = -1;
    };
    std::vector<Slot> slots = std::vector<Slot>(1u << 10);
    std::size_t used = 0;

    static std::size_t hash(std::uint64_t masks, int loc) {
      std::uint64_t x = masks ^ (static_cast<std::uint64_t>(loc) * 0x9E3779B97F4A7C15ull);
      x ^= x >> 31;
      x *= 0xBF58476D1CE4E5B9ull;
      x ^= x >> 29;
      return static_cast<std::size_t>(x);
    }
    Slot& find(std::uint64_t masks, int loc) {
      const std::size_t mask = slots.size() - 1;
      for (std::size_t i = hash(masks, loc) & mask;; i = (i + 1) & mask) {
        Slot& s = slots[i];
        if (s.loc < 0 || (s.masks == masks && s.loc == loc)) return s;
      }
    }
    Slot& claim(std::uint64_t masks, int loc) {
      if (2 * (used + 1) > slots.size()) {
        std::vector<Slot> old = std::move(slots);
        slots.assign(old.size() * 2, Slot{});
        for (const Slot& s : old)
          if (s.loc >= 0) find(s.masks, s.loc) = s;
      }
      Slot& s = find(masks, loc);
      if (s.loc < 0) s.masks = masks, s.loc = loc, ++used;
      return s;
    }
  };

  // Breadth first by the number of stops done, so that every label of a state is known before
  // any of them is expanded: only non-dominated labels are expanded (a depth-first search expands
  // many that a later label dominates). Each expanded label is bounded against the incumbent.
  void search() {
    std::vector<Entry> arena;
    arena.reserve(1u << 12);
    Entry root;
    root.state = start_;
    root.picked = initially_picked_;
    arena.push_back(root);
    std::vector<int> layer{0};
    int best_parent = -2;  // -2: the incumbent given to run()
    StopRef best_last;
    while (!layer.empty() && !stopped_) {
      StateTable table;
      std::vector<int> next;
      for (int index : layer) {
        if (stopped_) break;
        if (!arena[static_cast<std::size_t>(index)].alive) continue;
        if ((++nodes_ & 1023u) == 0 && budget_.exhausted(nodes_ + rs_.work())) {
          stopped_ = true;
          break;
        }
        const Entry e = arena[static_cast<std::size_t>(index)];
        const RouteState& s = e.state;
        if (!bounded_below_best(s, e.picked, e.delivered)) continue;
        for (std::size_t i = 0; i < jobs_.size(); ++i) {
          if (e.delivered >> i & 1u) continue;
          const int j = jobs_[i];
          const std::uint32_t bit = 1u << i;
          const bool deliver = e.picked & bit;
          if (!deliver && (s.load >= capacity_ || !sim_.may_pick_up(s, j))) continue;
          Entry child;
          child.state = s;
          child.stop = {j, deliver ? StopKind::kDelivery : StopKind::kPickup};
          if (!sim_.advance(child.state, child.stop)) continue;
          child.picked = e.picked | (deliver ? 0u : bit);
          child.delivered = e.delivered | (deliver ? bit : 0u);
          child.parent = index;
          if (child.delivered == all_) {
            if (!found_ || better(child.state.cost, best_)) {
              best_ = child.state.cost;
              best_parent = index;
              best_last = child.stop;
              found_ = true;
            }
            continue;
          }
          if (found_ && compare(child.state.cost, best_) >= 0) continue;
          auto& slot = table.claim(child.picked | static_cast<std::uint64_t>(child.delivered) << 32,
                                   child.state.loc);
          bool dominated = false;
          for (int k = slot.head; k >= 0 && !dominated;
               k = arena[static_cast<std::size_t>(k)].next) {
            Entry& other = arena[static_cast<std::size_t>(k)];
            if (!other.alive) continue;
            if (other.state.t <= child.state.t + 1e-9 &&
                compare(other.state.cost, child.state.cost) <= 0)
              dominated = true;
            else if (child.state.t <= other.state.t + 1e-9 &&
                     compare(child.state.cost, other.state.cost) <= 0)
              other.alive = false;
          }
          if (dominated) continue;
          child.next = slot.head;
          if (arena.size() >= kMaxLabels) {
            stopped_ = out_of_memory_ = true;
            break;
          }
          arena.push_back(child);
          slot.head = static_cast<int>(arena.size() - 1);
          next.push_back(slot.head);
        }
      }
      layer.swap(next);
    }
    if (best_parent == -2) return;  // nothing better than the incumbent
    best_route_.clear();
    best_route_.push_back(best_last);
    for (int k = best_parent; k > 0; k = arena[static_cast<std::size_t>(k)].parent)
      best_route_.push_back(arena[static_cast<std::size_t>(k)].stop);
    std::reverse(best_route_.begin(), best_route_.end());
  }

  // False when the bound says no completion of this partial route beats the incumbent.
  bool bounded_below_best(const RouteState& s, std::uint32_t picked, std::uint32_t delivered) {
    Objective lb;
    if (!lower_bound(s, picked, delivered, lb)) return false;
    if (!found_) return true;
    if (compare(lb, best_) >= 0) return false;
    if (lb.late_jobs == best_.late_jobs && std::abs(lb.lateness_s - best_.lateness_s) < 1e-6 &&
        std::abs(lb.completion_s - best_.completion_s) < 1e-6) {
      lb.travel_s += travel_bound(s, picked, delivered);
      if (compare(lb, best_) >= 0) return false;
    }
    return true;
  }

  RouteSearch& rs_;
  const RouteSimulator& sim_;
  const std::vector<double>& shortest_;
  int courier_;
  std::vector<int> jobs_;
  RouteState start_;
  const SearchBudget& budget_;
  std::size_t n_;
  int capacity_;
  std::uint32_t initially_picked_ = 0;
  std::uint32_t all_ = 0;
  double earliest_[kMaxJobsPerCourier + 2] = {};
  double handover_[kMaxJobsPerCourier + 2] = {};
  std::vector<int> local_;   // location -> place id, -1 if not a place of this search
  std::vector<int> places_;  // place id -> location
  std::vector<std::vector<std::pair<double, int>>> nearest_;
  bool masks_ok_ = true;  // at most 64 places (else no travel is charged)
  std::vector<int> by_deadline_;
  double due_[kMaxJobsPerCourier + 2] = {};
  double slot_[kMaxJobsPerCourier + 2] = {};
  std::vector<StopRef> best_route_;
  Objective best_;
  bool found_ = false;
  bool stopped_ = false;
  bool out_of_memory_ = false;
  std::uint64_t nodes_ = 0;
};

class ExactEngine final : public SchedulerEngine {
 public:
  const char* name() const override { return "exact"; }

  JobSchedule solve(const SchedulingProblem& problem, const SearchBudget& budget) override {
    if (std::string e = problem_error(problem); !e.empty())
      return failed_schedule(problem, ScheduleStatus::kInvalidProblem, e, name(), 0);
    RouteSearch rs(problem, budget);
    const std::size_t couriers = problem.couriers.size();
    // Start states after the forced prefixes.
    std::vector<RouteState> starts;
    for (std::size_t c = 0; c < couriers; ++c) {
      RouteState s = rs.sim().start(static_cast<int>(c));
      for (StopRef stop : problem.couriers[c].forced_prefix)
        if (!rs.step(static_cast<int>(c), s, stop))
          return failed_schedule(problem, ScheduleStatus::kInfeasible,
                                 "courier '" + problem.couriers[c].id +
                                     "': its forced prefix cannot be done (" +
                                     std::string(to_string(stop.kind)) + " of job '" +
                                     problem.jobs[static_cast<std::size_t>(stop.job)].id + "')",
                                 name(), rs.work());
      starts.push_back(s);
    }
    // Incumbent: the large engine's search, briefly (an optimal incumbent lets the bound cut at
    // the first objective term; the search only has to prove it).
    Routes heuristic;
    std::vector<Objective> heuristic_costs;
    Objective heuristic_total;
    bool have_heuristic = large_search(rs, heuristic, kIncumbentRounds) &&
                          rs.total_cost(heuristic, heuristic_costs, heuristic_total);
    if (rs.stopped()) return give_up(problem, rs, have_heuristic ? &heuristic : nullptr, 0);
    const auto shortest = shortest_travel(problem);

    std::vector<std::vector<int>> bound(couriers);  // jobs only that courier can do
    std::vector<int> open;                          // jobs any courier can do
    for (int j : rs.free_jobs())
      (rs.owner(j) >= 0 ? bound[static_cast<std::size_t>(rs.owner(j))] : open).push_back(j);

    std::uint64_t assignments = 1;
    for (std::size_t k = 0; k < open.size() && assignments <= kMaxAssignments; ++k)
      assignments *= couriers;
    if (assignments > kMaxAssignments)
      return give_up(problem, rs, have_heuristic ? &heuristic : nullptr, 0,
                     "too many job assignments to enumerate");

    std::uint64_t nodes = 0;
    bool complete = true;
    const char* why = "the budget ran out";
    struct Solved {
      bool feasible = false;
      Objective cost;
      std::vector<StopRef> route;
    };
    std::map<std::pair<std::size_t, std::uint64_t>, Solved> memo;
    auto solve_courier = [&](std::size_t c, std::uint64_t subset) -> const Solved& {
      auto it = memo.find({c, subset});
      if (it != memo.end()) return it->second;
      std::vector<int> jobs = bound[c];
      for (std::size_t k = 0; k < open.size(); ++k)
        if (subset >> k & 1u) jobs.push_back(open[k]);
      Solved solved;
      if (jobs.size() > static_cast<std::size_t>(kMaxJobsPerCourier)) {
        complete = false;
        why = "more than 30 jobs for one courier";
        return memo[{c, subset}] = solved;
      }
      std::sort(jobs.begin(), jobs.end());
      CourierSearch search(rs, shortest, static_cast<int>(c), jobs, starts[c], budget);
      // The heuristic's route is an incumbent when it does exactly these jobs.
      std::vector<StopRef> tail;
      bool use_heuristic = false;
      if (have_heuristic) {
        const auto& r = heuristic[c];
        tail.assign(r.begin() + rs.fixed_length(static_cast<int>(c)), r.end());
        std::vector<int> done;
        for (StopRef s : tail)
          if (s.kind == StopKind::kDelivery) done.push_back(s.job);
        std::sort(done.begin(), done.end());
        use_heuristic = done == jobs;
      }
      const bool finished = search.run(use_heuristic ? heuristic_costs[c] : worst_objective(),
                                       use_heuristic ? &tail : nullptr);
      complete = complete && finished;
      if (search.out_of_memory()) why = "more than 2^19 partial routes to keep";
      nodes += search.nodes();
      solved.feasible = search.found();
      solved.cost = search.best();
      solved.route = search.best_route();
      return memo[{c, subset}] = solved;
    };

    Objective best = worst_objective();
    std::vector<std::uint64_t> best_subsets;
    bool found = false;
    std::vector<std::uint64_t> subsets(couriers);
    for (std::uint64_t a = 0; a < assignments && !rs.stopped(); ++a) {
      std::fill(subsets.begin(), subsets.end(), 0);
      std::uint64_t code = a;
      for (std::size_t k = 0; k < open.size(); ++k) {
        subsets[code % couriers] |= 1ull << k;
        code /= couriers;
      }
      Objective total;
      bool feasible = true;
      for (std::size_t c = 0; c < couriers && feasible; ++c) {
        const Solved& s = solve_courier(c, subsets[c]);
        feasible = s.feasible;
        total += s.cost;
      }
      if (!complete) break;
      if (feasible && (!found || better(total, best))) {
        best = total;
        best_subsets = subsets;
        found = true;
      }
    }
    if (!complete || rs.stopped()) {
      // One courier: the interrupted search's best is at least as good as the heuristic's.
      const auto it = memo.find({0, open.empty() ? 0 : (1ull << open.size()) - 1});
      if (couriers == 1 && it != memo.end() && it->second.feasible) {
        Routes partial(1, problem.couriers[0].forced_prefix);
        partial[0].insert(partial[0].end(), it->second.route.begin(), it->second.route.end());
        return give_up(problem, rs, &partial, nodes, why);
      }
      return give_up(problem, rs, have_heuristic ? &heuristic : nullptr, nodes, why);
    }
    if (!found)
      return failed_schedule(problem, ScheduleStatus::kInfeasible,
                             "no order of the stops satisfies every constraint", name(),
                             rs.work() + nodes);
    Routes routes(couriers);
    for (std::size_t c = 0; c < couriers; ++c) {
      routes[c] = problem.couriers[c].forced_prefix;
      const auto& r = memo[{c, best_subsets[c]}].route;
      routes[c].insert(routes[c].end(), r.begin(), r.end());
    }
    return finish_schedule(problem, routes, name(), true, rs.work() + nodes);
  }

 private:
  JobSchedule give_up(const SchedulingProblem& problem, RouteSearch& rs, const Routes* heuristic,
                      std::uint64_t nodes, const char* why = "the budget ran out") {
    if (!heuristic)
      return failed_schedule(problem, ScheduleStatus::kNoSolution, why, name(), rs.work() + nodes);
    JobSchedule s = finish_schedule(problem, *heuristic, name(), false, rs.work() + nodes);
    if (s.ok()) s.reason = std::string("not proved optimal: ") + why;
    return s;
  }
};

}  // namespace

std::unique_ptr<SchedulerEngine> make_exact_engine() {
  return std::make_unique<ExactEngine>();
}

}  // namespace autonomy::courier::scheduling::detail
