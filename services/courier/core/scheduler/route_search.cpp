#include "services/courier/core/scheduler/route_search.hpp"

#include "services/courier/core/scheduler/schedule_evaluation.hpp"

#include <algorithm>
#include <numeric>

namespace autonomy::courier::scheduling::detail {

namespace {

Objective minus(Objective a, const Objective& b) {
  a.late_jobs -= b.late_jobs;
  a.lateness_s -= b.lateness_s;
  a.completion_s -= b.completion_s;
  a.travel_s -= b.travel_s;
  a.interruptions -= b.interruptions;
  return a;
}

// Routes longer than this get granular insertion: pickups only after the nearest stops.
constexpr std::size_t kGranularAbove = 40;
constexpr std::size_t kGranularPositions = 10;

}  // namespace

RouteSearch::RouteSearch(const SchedulingProblem& problem, const SearchBudget& budget)
    : p_(&problem),
      budget_(&budget),
      sim_(problem),
      selection_(select_jobs(problem)),
      rng_(budget.seed) {
  left_out_.assign(problem.jobs.size(), 0);
  for (const auto& u : selection_.unschedulable) left_out_[static_cast<std::size_t>(u.job)] = 1;
  // A job whose delivery is in a forced prefix is done by the prefix; one whose pickup only is
  // there is bound to that courier, like a job aboard.
  std::vector<char> in_prefix(problem.jobs.size(), 0);
  owner_.assign(problem.jobs.size(), -1);
  for (std::size_t j = 0; j < problem.jobs.size(); ++j)
    if (problem.jobs[j].status == JobStatus::kAboard) owner_[j] = problem.jobs[j].aboard_courier;
  for (std::size_t c = 0; c < problem.couriers.size(); ++c) {
    const auto& prefix = problem.couriers[c].forced_prefix;
    fixed_.push_back(static_cast<int>(prefix.size()));
    for (StopRef s : prefix) {
      const auto j = static_cast<std::size_t>(s.job);
      if (s.kind == StopKind::kDelivery)
        in_prefix[j] = 1;
      else
        owner_[j] = static_cast<int>(c);
    }
  }
  for (std::size_t j = 0; j < problem.jobs.size(); ++j)
    if (!left_out_[j] && !in_prefix[j]) free_jobs_.push_back(static_cast<int>(j));
  stuck_.assign(problem.couriers.size(), 0);
  for (std::size_t j = 0; j < problem.jobs.size(); ++j)
    if (left_out_[j] && problem.jobs[j].status == JobStatus::kAboard)
      ++stuck_[static_cast<std::size_t>(problem.jobs[j].aboard_courier)];
}

void RouteSearch::poll() {
  next_poll_ = work_ + 1024;
  if (!stopped_ && budget_->exhausted(work_)) stopped_ = true;
}

bool RouteSearch::allowed(int courier, int job) const {
  return owner(job) < 0 || owner(job) == courier;
}

bool RouteSearch::step(int courier, RouteState& s, StopRef stop) {
  if (++work_ >= next_poll_) poll();
  if (sim_.refusal(s, stop)) return false;
  if (stop.kind == StopKind::kPickup &&
      s.load >= p_->couriers[static_cast<std::size_t>(courier)].capacity)
    return false;
  return sim_.advance(s, stop);
}

bool RouteSearch::route_cost(int courier, const std::vector<StopRef>& route, Objective& out,
                             const Objective* bound) {
  RouteState s = sim_.start(courier);
  for (StopRef stop : route) {
    if (!step(courier, s, stop)) return false;
    if (bound && compare(s.cost, *bound) >= 0) return false;
  }
  if (s.load != stuck_[static_cast<std::size_t>(courier)]) return false;
  out = s.cost;
  return true;
}

std::size_t RouteSearch::states_of(int courier, const std::vector<StopRef>& route,
                                   std::vector<RouteState>& st) {
  st.clear();
  st.push_back(sim_.start(courier));
  for (std::size_t k = 0; k < route.size(); ++k) {
    RouteState s = st.back();
    if (!step(courier, s, route[k])) return k;
    st.push_back(s);
  }
  return route.size();
}

bool RouteSearch::best_insertion(int courier, const std::vector<StopRef>& route, int job,
                                 int window, Insertion& best, const Objective* bound) {
  if (!allowed(courier, job)) return false;
  std::vector<RouteState>& st = scratch_;
  const std::size_t valid = states_of(courier, route, st);
  const std::size_t n = route.size();
  Objective limit = bound ? *bound : worst_objective();
  bool found = false;
  const auto first = static_cast<std::size_t>(fixed_[static_cast<std::size_t>(courier)]);
  if (first > valid) return false;
  // Simulates route[from..] after s; records the insertion if it beats the limit.
  auto finish = [&](RouteState s, std::size_t from, int pick, int del) {
    for (std::size_t k = from; k < n; ++k) {
      if (!step(courier, s, route[k])) return;
      if (compare(s.cost, limit) >= 0) return;
    }
    if (compare(s.cost, limit) >= 0) return;
    limit = s.cost;
    best = {pick, del, s.cost};
    found = true;
  };
  const JobData& d = sim_.job(job);
  const StopRef delivery{job, StopKind::kDelivery};
  if (delivery_only(job)) {
    for (std::size_t i = first; i <= valid && !stopped_; ++i) {
      RouteState s = st[i];
      if (!step(courier, s, delivery)) continue;
      finish(s, i, -1, static_cast<int>(i));
    }
    return found;
  }
  const StopRef pickup{job, StopKind::kPickup};
  std::vector<std::size_t> positions;
  if (n <= kGranularAbove) {
    for (std::size_t i = first; i <= valid; ++i) positions.push_back(i);
  } else {
    // After the stops nearest to the pickup (and at the very start and end of the route).
    std::vector<std::pair<double, std::size_t>> near;
    for (std::size_t i = first; i <= valid; ++i)
      near.push_back({sim_.travel(st[i].loc, d.pick_loc), i});
    const std::size_t keep = std::min(kGranularPositions, near.size());
    std::partial_sort(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(keep), near.end());
    for (std::size_t k = 0; k < keep; ++k) positions.push_back(near[k].second);
    positions.push_back(first);
    positions.push_back(valid);
    std::sort(positions.begin(), positions.end());
    positions.erase(std::unique(positions.begin(), positions.end()), positions.end());
  }
  for (std::size_t i : positions) {
    if (stopped_) break;
    RouteState pre = st[i];
    if (!step(courier, pre, pickup)) continue;
    if (compare(pre.cost, limit) >= 0) continue;
    for (std::size_t j = i; j <= n; ++j) {
      if (window >= 0 && j - i > static_cast<std::size_t>(window)) break;
      RouteState s = pre;
      if (step(courier, s, delivery)) finish(s, j, static_cast<int>(i), static_cast<int>(j));
      if (j == n) break;
      if (!step(courier, pre, route[j])) break;
      if (compare(pre.cost, limit) >= 0) break;
    }
  }
  return found;
}

void RouteSearch::apply(std::vector<StopRef>& route, int job, const Insertion& ins) {
  route.insert(route.begin() + ins.delivery_before, StopRef{job, StopKind::kDelivery});
  if (ins.pickup_before >= 0)
    route.insert(route.begin() + ins.pickup_before, StopRef{job, StopKind::kPickup});
}

void RouteSearch::remove_job(std::vector<StopRef>& route, int job) {
  route.erase(
      std::remove_if(route.begin(), route.end(), [job](const StopRef& s) { return s.job == job; }),
      route.end());
}

bool RouteSearch::total_cost(const Routes& routes, std::vector<Objective>& costs,
                             Objective& total) {
  costs.assign(routes.size(), Objective{});
  total = Objective{};
  for (std::size_t c = 0; c < routes.size(); ++c) {
    if (!route_cost(static_cast<int>(c), routes[c], costs[c])) return false;
    total += costs[c];
  }
  return true;
}

bool RouteSearch::greedy(Routes& out) {
  const int couriers = sim_.courier_count();
  out.assign(static_cast<std::size_t>(couriers), {});
  std::vector<RouteState> state;
  for (int c = 0; c < couriers; ++c) {
    RouteState s = sim_.start(c);
    for (StopRef stop : p_->couriers[static_cast<std::size_t>(c)].forced_prefix) {
      if (!step(c, s, stop)) return false;
      out[static_cast<std::size_t>(c)].push_back(stop);
    }
    state.push_back(s);
  }
  std::vector<char> pending(p_->jobs.size(), 0);
  std::size_t left = 0;
  for (int j : free_jobs_)
    if (!delivery_only(j)) pending[static_cast<std::size_t>(j)] = 1, ++left;
  std::vector<int> by_time(static_cast<std::size_t>(couriers));
  for (;;) {
    std::iota(by_time.begin(), by_time.end(), 0);
    std::sort(by_time.begin(), by_time.end(), [&](int a, int b) {
      return state[static_cast<std::size_t>(a)].t < state[static_cast<std::size_t>(b)].t;
    });
    bool moved = false;
    bool anything_left = left > 0;
    for (int c : by_time) {
      RouteState& s = state[static_cast<std::size_t>(c)];
      if (s.load > stuck_[static_cast<std::size_t>(c)]) anything_left = true;
      double best_finish = kNoRoute;
      StopRef best_stop{};
      RouteState best_state;
      auto consider = [&](StopRef stop) {
        RouteState t = s;
        if (!step(c, t, stop)) return;
        // Deliveries first on ties: they free capacity and finish jobs.
        const double score = t.t - (stop.kind == StopKind::kDelivery ? 1e-6 : 0.0);
        if (score < best_finish) best_finish = score, best_stop = stop, best_state = t;
      };
      for (int i = 0; i < s.load; ++i) {
        const int j = s.aboard[static_cast<std::size_t>(i)];
        if (!left_out_[static_cast<std::size_t>(j)]) consider({j, StopKind::kDelivery});
      }
      for (int j : free_jobs_)
        if (pending[static_cast<std::size_t>(j)]) consider({j, StopKind::kPickup});
      if (best_finish < kNoRoute) {
        s = best_state;
        out[static_cast<std::size_t>(c)].push_back(best_stop);
        if (best_stop.kind == StopKind::kPickup)
          pending[static_cast<std::size_t>(best_stop.job)] = 0, --left;
        moved = true;
        break;
      }
    }
    if (!moved) return !anything_left;
    if (stopped_) return false;
  }
}

void RouteSearch::descend(Routes& routes, std::vector<Objective>& costs, int window) {
  std::vector<RouteState> st;
  bool improved = true;
  while (improved && !stopped_) {
    improved = false;
    // Single stop moves inside a route.
    for (std::size_t c = 0; c < routes.size() && !stopped_; ++c) {
      const int ci = static_cast<int>(c);
      auto& r = routes[c];
      const auto first = static_cast<std::size_t>(fixed_[c]);
      for (std::size_t a = first; a < r.size() && !stopped_; ++a) {
        states_of(ci, r, st);
        const StopRef moving = r[a];
        // New sequence: r without a, with `moving` inserted at b.
        auto at = [&](std::size_t k, std::size_t b) -> StopRef {
          const std::size_t without = k < b ? k : k - 1;  // index in r-without-a
          if (k == b) return moving;
          return without < a ? r[without] : r[without + 1];
        };
        std::size_t best_b = a;
        Objective limit = costs[c];
        for (std::size_t b = first; b < r.size(); ++b) {
          if (b == a) continue;
          const std::size_t m = std::min(a, b);
          if (m >= st.size()) break;
          RouteState s = st[m];
          bool ok = true;
          for (std::size_t k = m; k < r.size() && ok; ++k) {
            ok = step(ci, s, at(k, b)) && compare(s.cost, limit) < 0;
          }
          if (ok && s.load == stuck_[c]) limit = s.cost, best_b = b;
        }
        if (best_b != a) {
          r.erase(r.begin() + static_cast<std::ptrdiff_t>(a));
          r.insert(r.begin() + static_cast<std::ptrdiff_t>(best_b), moving);
          costs[c] = limit;
          improved = true;
        }
      }
    }
    // Job relocation to the best place on any courier.
    std::vector<int> order = free_jobs_;
    std::shuffle(order.begin(), order.end(), rng_);
    for (int job : order) {
      if (stopped_) break;
      std::size_t from = 0;
      while (from < routes.size() && std::none_of(routes[from].begin(), routes[from].end(),
                                                  [job](const StopRef& s) { return s.job == job; }))
        ++from;
      if (from == routes.size()) continue;
      std::vector<StopRef> without = routes[from];
      remove_job(without, job);
      Objective without_cost;
      if (!route_cost(static_cast<int>(from), without, without_cost)) continue;
      const Objective saved = minus(costs[from], without_cost);
      int best_c = -1;
      Insertion best_ins;
      Objective best_gain{};  // new - old of the receiving route, must beat `saved`
      for (std::size_t c = 0; c < routes.size(); ++c) {
        const int ci = static_cast<int>(c);
        if (!allowed(ci, job)) continue;
        const auto& base = c == from ? without : routes[c];
        const Objective& base_cost = c == from ? without_cost : costs[c];
        const Objective bound = best_c < 0 ? base_cost + saved : base_cost + best_gain;
        Insertion ins;
        if (!best_insertion(ci, base, job, window, ins, &bound)) continue;
        best_c = ci;
        best_ins = ins;
        best_gain = minus(ins.cost, base_cost);
      }
      if (best_c < 0) continue;
      if (static_cast<std::size_t>(best_c) != from) {
        routes[from] = std::move(without);
        costs[from] = without_cost;
      } else {
        routes[from] = without;
      }
      apply(routes[static_cast<std::size_t>(best_c)], job, best_ins);
      costs[static_cast<std::size_t>(best_c)] = best_ins.cost;
      improved = true;
    }
  }
}

void RouteSearch::ruin_and_recreate(Routes& routes, std::vector<Objective>& costs, int window,
                                    int stale_limit) {
  const std::size_t n = free_jobs_.size();
  if (n == 0) return;
  Routes best = routes, current = routes;
  std::vector<Objective> best_costs = costs, current_costs = costs;
  Objective best_total{}, current_total{};
  for (const Objective& o : costs) best_total += o;
  current_total = best_total;
  const std::size_t max_remove =
      std::max<std::size_t>(1, std::min<std::size_t>(n, std::min<std::size_t>(10, n / 4 + 2)));
  std::vector<int> removed;
  std::vector<Objective> partial(routes.size());
  std::vector<RouteState> st;
  int stale = 0;
  while (!stopped_ && stale < stale_limit) {
    Routes cand = current;
    // Ruin: a seed job and the jobs whose places are nearest to it, or a random set.
    std::uniform_int_distribution<std::size_t> pick_count(1, max_remove);
    const std::size_t k = pick_count(rng_);
    removed.clear();
    std::vector<int> pool = free_jobs_;
    std::shuffle(pool.begin(), pool.end(), rng_);
    if (rng_() % 2 == 0) {
      const JobData& seed = sim_.job(pool[0]);
      auto distance = [&](int j) {
        const JobData& d = sim_.job(j);
        const int a = d.aboard ? d.del_loc : d.pick_loc;
        const int sa = seed.aboard ? seed.del_loc : seed.pick_loc;
        return std::min(sim_.travel(sa, a), sim_.travel(a, sa)) +
               std::min(sim_.travel(seed.del_loc, d.del_loc), sim_.travel(d.del_loc, seed.del_loc));
      };
      std::stable_sort(pool.begin(), pool.end(),
                       [&](int a, int b) { return distance(a) < distance(b); });
    }
    removed.assign(pool.begin(), pool.begin() + static_cast<std::ptrdiff_t>(k));
    for (int j : removed)
      for (auto& r : cand) remove_job(r, j);
    // Recreate: most urgent first, cheapest insertion over all couriers.
    std::sort(removed.begin(), removed.end(),
              [&](int a, int b) { return sim_.job(a).deadline < sim_.job(b).deadline; });
    if (rng_() % 3 == 0) std::shuffle(removed.begin(), removed.end(), rng_);
    bool ok = true;
    for (std::size_t c = 0; c < cand.size() && ok; ++c) {
      const std::size_t valid = states_of(static_cast<int>(c), cand[c], st);
      ok = valid == cand[c].size();
      partial[c] = st.back().cost;
    }
    for (int job : removed) {
      if (!ok || stopped_) break;
      int best_c = -1;
      Insertion best_ins;
      Objective best_delta{};
      for (std::size_t c = 0; c < cand.size(); ++c) {
        const int ci = static_cast<int>(c);
        if (!allowed(ci, job)) continue;
        const Objective bound = partial[c] + best_delta;
        Insertion ins;
        if (!best_insertion(ci, cand[c], job, window, ins, best_c < 0 ? nullptr : &bound)) continue;
        best_c = ci;
        best_ins = ins;
        best_delta = minus(ins.cost, partial[c]);
      }
      if (best_c < 0) {
        ok = false;
        break;
      }
      apply(cand[static_cast<std::size_t>(best_c)], job, best_ins);
      partial[static_cast<std::size_t>(best_c)] = best_ins.cost;
    }
    if (!ok || stopped_) {
      ++stale;
      continue;
    }
    std::vector<Objective> cand_costs;
    Objective total;
    if (!total_cost(cand, cand_costs, total)) {
      ++stale;
      continue;
    }
    if (compare(total, current_total) <= 0) {
      current = std::move(cand);
      current_costs = std::move(cand_costs);
      current_total = total;
    }
    if (better(current_total, best_total)) {
      descend(current, current_costs, window);
      current_total = Objective{};
      for (const Objective& o : current_costs) current_total += o;
      best = current;
      best_costs = current_costs;
      best_total = current_total;
      stale = 0;
    } else if (++stale % 50 == 0) {
      current = best;
      current_costs = best_costs;
      current_total = best_total;
    }
  }
  routes = std::move(best);
  costs = std::move(best_costs);
}

JobSchedule finish_schedule(const SchedulingProblem& problem, const Routes& routes,
                            const char* engine, bool proved_optimal, std::uint64_t work) {
  JobSchedule s = evaluate_order(problem, routes);
  s.engine = engine;
  s.work = work;
  s.proved_optimal = proved_optimal && s.ok();
  return s;
}

JobSchedule finish_schedule(const RouteSearch& search, const Routes& routes, const char* engine,
                            bool proved_optimal) {
  JobSchedule s = evaluate_order(search.problem(), routes, search.selection().unschedulable);
  s.engine = engine;
  s.work = search.work();
  s.proved_optimal = proved_optimal && s.ok();
  return s;
}

JobSchedule failed_schedule(const RouteSearch& search, ScheduleStatus status, std::string reason,
                            const char* engine) {
  JobSchedule s;
  s.status = status;
  s.reason = std::move(reason);
  s.engine = engine;
  s.work = search.work();
  s.unschedulable = search.selection().unschedulable;
  return s;
}

JobSchedule failed_schedule(const SchedulingProblem& problem, ScheduleStatus status,
                            std::string reason, const char* engine, std::uint64_t work) {
  JobSchedule s;
  s.status = status;
  s.reason = std::move(reason);
  s.engine = engine;
  s.work = work;
  if (status != ScheduleStatus::kInvalidProblem) s.unschedulable = find_unschedulable(problem);
  return s;
}

}  // namespace autonomy::courier::scheduling::detail
