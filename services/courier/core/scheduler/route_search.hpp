#pragma once
// Internal to the scheduler library: route building blocks shared by the engines. Routes are stop
// lists per courier (forced prefixes included, never moved); costs come from RouteSimulator. Every
// simulated stop counts as one unit of work against the SearchBudget.
#include "services/courier/core/scheduler/job_selection.hpp"
#include "services/courier/core/scheduler/route_simulation.hpp"
#include "services/courier/core/scheduler/scheduler_engine.hpp"

#include <cstdint>
#include <random>
#include <vector>

namespace autonomy::courier::scheduling::detail {

using Routes = std::vector<std::vector<StopRef>>;

class RouteSearch {
 public:
  RouteSearch(const SchedulingProblem& problem, const SearchBudget& budget);

  const RouteSimulator& sim() const { return sim_; }
  const SchedulingProblem& problem() const { return *p_; }
  std::uint64_t work() const { return work_; }
  // The budget ran out (polled every 1024 units of work).
  bool stopped() const { return stopped_; }
  int fixed_length(int courier) const { return fixed_[static_cast<std::size_t>(courier)]; }
  // Objects aboard `courier` that no schedule can deliver: they stay aboard to the end.
  int stuck_aboard(int courier) const { return stuck_[static_cast<std::size_t>(courier)]; }
  // Jobs to schedule (not unschedulable, not in a forced prefix), in job order.
  const std::vector<int>& free_jobs() const { return free_jobs_; }
  const std::vector<char>& left_out() const { return left_out_; }
  // The jobs left out (find_unschedulable's answer) and an order doing all the others.
  const JobSelection& selection() const { return selection_; }

  // Rules (capacity, look-alike, aboard) + timing of one stop.
  bool step(int courier, RouteState& s, StopRef stop);
  // Cost of a complete route (false if a rule breaks, a travel is +inf, or objects are still
  // aboard at the end). Gives up (false) as soon as the partial cost is not better than *bound.
  bool route_cost(int courier, const std::vector<StopRef>& route, Objective& out,
                  const Objective* bound = nullptr);
  // States before each stop: st[0] = start, st[k] = after k stops; returns how many stops could
  // be simulated (st has that + 1 entries).
  std::size_t states_of(int courier, const std::vector<StopRef>& route,
                        std::vector<RouteState>& st);

  // The cheapest insertion of `job` (its pickup when waiting, and its delivery) into `route`,
  // after the forced prefix. window bounds the stops between pickup and delivery (-1 = any).
  // Returns false when no insertion is feasible or better than *bound.
  struct Insertion {
    int pickup_before = -1;  // index in the route before insertion; -1 when aboard
    int delivery_before = -1;
    Objective cost;  // of the whole route after insertion
  };
  bool best_insertion(int courier, const std::vector<StopRef>& route, int job, int window,
                      Insertion& best, const Objective* bound = nullptr);
  static void apply(std::vector<StopRef>& route, int job, const Insertion& ins);

  // Greedy parallel dispatch: the courier free first takes the stop it can finish first.
  bool greedy(Routes& out);
  // Removes every stop of `job` from its route.
  static void remove_job(std::vector<StopRef>& route, int job);
  // Which courier may do `job` (its own when aboard or picked up in a forced prefix; any
  // otherwise).
  bool allowed(int courier, int job) const;
  // The courier a job is bound to (aboard, or picked up in a forced prefix), or -1.
  int owner(int job) const { return owner_[static_cast<std::size_t>(job)]; }
  // Only its delivery is left to schedule.
  bool delivery_only(int job) const { return owner(job) >= 0; }

  // Local search to a local optimum (or the budget): single stop moves within a route, then job
  // relocation to the best position on any courier. `costs` are kept per courier.
  void descend(Routes& routes, std::vector<Objective>& costs, int window);
  // Ruin (remove a few related jobs) and recreate (cheapest insertion, most constrained first)
  // until the budget or `stale_limit` rounds without improvement. Returns the best routes.
  void ruin_and_recreate(Routes& routes, std::vector<Objective>& costs, int window,
                         int stale_limit);

  // Sum over couriers; false if a route is infeasible.
  bool total_cost(const Routes& routes, std::vector<Objective>& costs, Objective& total);

 private:
  void poll();

  const SchedulingProblem* p_;
  const SearchBudget* budget_;
  RouteSimulator sim_;
  JobSelection selection_;
  std::vector<int> fixed_;
  std::vector<int> stuck_;  // per courier: unschedulable objects aboard (they stay aboard)
  std::vector<int> free_jobs_;
  std::vector<int> owner_;
  std::vector<char> left_out_;
  std::uint64_t work_ = 0;
  std::uint64_t next_poll_ = 1024;
  bool stopped_ = false;
  std::mt19937_64 rng_;
  std::vector<RouteState> scratch_;
};

// The JobSchedule of routes an engine found (evaluate_order, then the engine's name and effort).
// Given the search, its selection is not computed again.
JobSchedule finish_schedule(const SchedulingProblem& problem, const Routes& routes,
                            const char* engine, bool proved_optimal, std::uint64_t work);
JobSchedule finish_schedule(const RouteSearch& search, const Routes& routes, const char* engine,
                            bool proved_optimal);
// A JobSchedule for a problem that cannot be scheduled at all.
JobSchedule failed_schedule(const SchedulingProblem& problem, ScheduleStatus status,
                            std::string reason, const char* engine, std::uint64_t work);
JobSchedule failed_schedule(const RouteSearch& search, ScheduleStatus status, std::string reason,
                            const char* engine);

std::unique_ptr<SchedulerEngine> make_exact_engine();
std::unique_ptr<SchedulerEngine> make_large_engine();
std::unique_ptr<SchedulerEngine> make_paper_engine();

// The large engine's search, for engines that want a good first incumbent. Starts from greedy
// dispatch, the repaired previous order or, when both fail, the selection's order; false only when
// the selection found no order (the forced prefixes cannot be done).
bool large_search(RouteSearch& search, Routes& routes, int stale_limit);

}  // namespace autonomy::courier::scheduling::detail
