#include "services/courier/core/scheduler/job_selection.hpp"

#include "services/courier/core/scheduler/route_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_map>

namespace autonomy::courier::scheduling::detail {

namespace {

// Work (simulated stops) one feasibility question may take, and all questions of one selection
// together: at least these; on large problems 10 n^2 for n jobs (a greedy descent takes about
// 4 n^2) per question and twice that in all. A question cut off counts as "cannot be done" (not
// proved).
constexpr std::uint64_t kQuestionWork = 200000;
constexpr std::uint64_t kSelectionWork = 2000000;
std::uint64_t question_work(std::size_t jobs) {
  return std::max<std::uint64_t>(kQuestionWork, 10 * static_cast<std::uint64_t>(jobs * jobs));
}
// For naming the kept job a left-out one clashes with (only the detail text depends on it).
constexpr std::uint64_t kPairWork = 5000;
constexpr std::uint64_t kNamingWork = 200000;

using Routes = std::vector<std::vector<StopRef>>;

std::string clock_text(double s) {
  const long t = std::lround(s);
  char buf[64];
  if (t % 60 == 0)
    std::snprintf(buf, sizeof buf, "%02ld:%02ld", t / 3600, t / 60 % 60);
  else
    std::snprintf(buf, sizeof buf, "%02ld:%02ld:%02ld", t / 3600, t / 60 % 60, t % 60);
  return buf;
}

std::string quoted(const SchedulingProblem& p, int job) {
  return "'" + p.jobs[static_cast<std::size_t>(job)].id + "'";
}

bool reachable(const SchedulingProblem& p, int from, int to) {
  return p.travel.at(static_cast<std::size_t>(from), static_cast<std::size_t>(to)) < kNoRoute;
}

// The person is present again (at or after now) long enough for one handover.
bool present_again(const SchedulingProblem& p, const Place& place) {
  return earliest_handover_start(p, place.person, p.now_s, handover_duration(p, place)) < kNoRoute;
}

// Rule 1: unreachable, or nobody present again. Marks `left`.
void unreachable_or_absent(const SchedulingProblem& p, std::vector<UnschedulableJob>& out,
                           std::vector<char>& left) {
  for (std::size_t j = 0; j < p.jobs.size(); ++j) {
    const Job& job = p.jobs[j];
    const int ji = static_cast<int>(j);
    const std::string& del_name = p.locations[static_cast<std::size_t>(job.delivery.location)].name;
    auto leave = [&](UnschedulableReason why, std::string detail) {
      out.push_back({ji, why, std::move(detail)});
      left[j] = 1;
    };
    if (job.status == JobStatus::kAboard) {
      const Courier& c = p.couriers[static_cast<std::size_t>(job.aboard_courier)];
      if (!reachable(p, c.location, job.delivery.location)) {
        leave(UnschedulableReason::kUnreachable,
              "delivery " + del_name + " cannot be reached from courier '" + c.id + "' at " +
                  p.locations[static_cast<std::size_t>(c.location)].name);
        continue;
      }
    } else {
      const std::string& pick_name =
          p.locations[static_cast<std::size_t>(job.pickup.location)].name;
      bool any = false, pickup_reached = false;
      for (const Courier& c : p.couriers) {
        const bool to_pickup = reachable(p, c.location, job.pickup.location);
        pickup_reached = pickup_reached || to_pickup;
        any = any || (to_pickup && reachable(p, job.pickup.location, job.delivery.location));
      }
      if (!any) {
        leave(UnschedulableReason::kUnreachable,
              pickup_reached ? "delivery " + del_name + " cannot be reached from pickup " + pick_name
                             : "pickup " + pick_name + " cannot be reached by any courier");
        continue;
      }
      if (!present_again(p, job.pickup)) {
        leave(UnschedulableReason::kNobodyPresent,
              describe_place(p, job.pickup) + " is not present again for the pickup");
        continue;
      }
    }
    if (!present_again(p, job.delivery))
      leave(UnschedulableReason::kNobodyPresent,
            describe_place(p, job.delivery) + " is not present again for the delivery");
  }
}

// "Anna leaves at 10:15, the earliest arrival is 10:20" for a handover at `place` that cannot
// start at or after `arrival` (the person's last window ends too early).
std::string missed(const SchedulingProblem& p, const Place& place, const char* stop,
                   double arrival) {
  const Person& person = p.people[static_cast<std::size_t>(place.person)];
  const double leaves = person.presence.back().end_s;
  const double duration = handover_duration(p, place);
  std::string text = std::string(stop) + " at " +
                     p.locations[static_cast<std::size_t>(place.location)].name + ": " +
                     person.name + " leaves at " + clock_text(leaves) +
                     ", the earliest arrival is " + clock_text(arrival);
  if (arrival < leaves) {
    char buf[48];
    std::snprintf(buf, sizeof buf, ", too late for the %.0f s handover", duration);
    text += buf;
  }
  return text;
}

// Complete depth-first search for an order doing a given set of jobs, all couriers at once: the
// courier whose clock is earliest either does a next stop (earliest finish first, so the first
// descent is greedy parallel dispatch) or stops for good. Every set of routes is reached this way
// (replay it, always moving the courier that is earliest), so exhausting the tree proves that no
// order exists. Pruned where a job left cannot be finished even on its own, and where a state
// already failed (same job states, places and active couriers, every clock no later: waiting is
// allowed and presence windows only get fewer with time).
class Feasibility {
 public:
  enum class Answer : std::uint8_t { kFeasible, kInfeasible, kUnknown };

  Feasibility(const SchedulingProblem& p, const RouteSimulator& sim, std::vector<RouteState> starts)
      : p_(p), sim_(sim), starts_(std::move(starts)) {}

  std::uint64_t work() const { return work_; }

  // Can every job with include[j] be done (after the forced prefixes; objects aboard that are not
  // included stay aboard)? On kFeasible, `routes` holds the stops after the prefixes.
  Answer decide(const std::vector<char>& include, std::uint64_t max_work, Routes& routes) {
    const std::size_t couriers = starts_.size();
    include_ = include;
    limit_ = work_ + max_work;
    cut_off_ = false;
    failed_.clear();
    state_ = starts_;
    active_.assign(couriers, 1);
    routes_.assign(couriers, {});
    code_.assign(p_.jobs.size(), kOut);
    finisher_.assign(p_.jobs.size(), 0);
    remaining_ = 0;
    for (std::size_t j = 0; j < p_.jobs.size(); ++j) {
      if (!include_[j]) continue;
      code_[j] = kWaiting;
      for (std::size_t c = 0; c < couriers; ++c)
        if (state_[c].carries(static_cast<int>(j))) code_[j] = static_cast<std::uint8_t>(c);
      ++remaining_;
    }
    if (search()) {
      routes = routes_;
      return Answer::kFeasible;
    }
    return cut_off_ ? Answer::kUnknown : Answer::kInfeasible;
  }

  // Puts job `j` (its pickup unless aboard, and its delivery) into `routes`, a feasible order for
  // the other jobs of `include`, at the first positions that keep it feasible; true when there are
  // some.
  bool insert(const std::vector<char>& include, Routes& routes, int j, std::uint64_t max_work) {
    include_ = include;
    const std::uint64_t limit = work_ + max_work;
    for (std::size_t c = 0; c < routes.size(); ++c) {
      const bool aboard = starts_[c].carries(j);
      if (!aboard && p_.jobs[static_cast<std::size_t>(j)].status == JobStatus::kAboard) continue;
      const auto& r = routes[c];
      const std::size_t n = r.size();
      // Pickup before r[i] (none when aboard), delivery before r[k], i <= k.
      for (std::size_t i = 0; i <= (aboard ? 0 : n); ++i)
        for (std::size_t k = i; k <= n; ++k) {
          if (work_ >= limit) return false;
          std::vector<StopRef> trial;
          for (std::size_t m = 0; m <= n; ++m) {
            if (m == i && !aboard) trial.push_back({j, StopKind::kPickup});
            if (m == k) trial.push_back({j, StopKind::kDelivery});
            if (m < n) trial.push_back(r[m]);
          }
          if (route_works(static_cast<int>(c), trial)) {
            routes[c] = std::move(trial);
            return true;
          }
        }
    }
    return false;
  }

 private:
  static constexpr std::uint8_t kWaiting = 250;
  static constexpr std::uint8_t kDone = 251;
  static constexpr std::uint8_t kOut = 252;

  // One stop with every rule (look-alike, capacity, order, timing).
  bool step(int c, RouteState& s, StopRef stop) {
    ++work_;
    if (sim_.refusal(s, stop)) return false;
    if (stop.kind == StopKind::kPickup &&
        s.load >= p_.couriers[static_cast<std::size_t>(c)].capacity)
      return false;
    return sim_.advance(s, stop);
  }

  bool route_works(int c, const std::vector<StopRef>& route) {
    RouteState s = starts_[static_cast<std::size_t>(c)];
    for (StopRef stop : route)
      if (!step(c, s, stop)) return false;
    for (int i = 0; i < s.load; ++i)
      if (include_[static_cast<std::size_t>(s.aboard[static_cast<std::size_t>(i)])]) return false;
    return true;
  }

  // Every job left can still be finished on its own by a courier that is still active. The
  // courier that could last time is asked first (a hint only: every answer is checked).
  bool all_finishable() {
    const std::size_t couriers = state_.size();
    auto can = [&](std::size_t c, int j) {
      return active_[c] && sim_.earliest_completion(state_[c], j) < kNoRoute;
    };
    for (std::size_t j = 0; j < code_.size(); ++j) {
      const std::uint8_t code = code_[j];
      if (code == kOut || code == kDone) continue;
      const int ji = static_cast<int>(j);
      if (code != kWaiting) {
        if (!can(code, ji)) return false;
        continue;
      }
      std::size_t& hint = finisher_[j];
      if (can(hint, ji)) continue;
      bool any = false;
      for (std::size_t k = 1; k < couriers && !any; ++k)
        if (can((hint + k) % couriers, ji)) hint = (hint + k) % couriers, any = true;
      if (!any) return false;
    }
    return true;
  }

  std::string key() const {
    std::string k(code_.begin(), code_.end());
    for (std::size_t c = 0; c < state_.size(); ++c) {
      k.push_back(static_cast<char>(active_[c]));
      const int loc = active_[c] ? state_[c].loc : -1;
      k.append(reinterpret_cast<const char*>(&loc), sizeof loc);
    }
    return k;
  }

  // A failed state with the same key and every active clock no later than now.
  bool dominated(const std::string& k) const {
    const auto it = failed_.find(k);
    if (it == failed_.end()) return false;
    for (const std::vector<double>& times : it->second) {
      bool no_later = true;
      for (std::size_t c = 0; c < state_.size() && no_later; ++c)
        no_later = !active_[c] || times[c] <= state_[c].t;
      if (no_later) return true;
    }
    return false;
  }

  bool search() {
    if (work_ >= limit_) cut_off_ = true;
    if (cut_off_) return false;
    if (remaining_ == 0) return true;
    if (!all_finishable()) return false;
    const std::string k = key();
    if (dominated(k)) return false;
    int c = -1;
    for (std::size_t i = 0; i < state_.size(); ++i)
      if (active_[i] && (c < 0 || state_[i].t < state_[static_cast<std::size_t>(c)].t))
        c = static_cast<int>(i);
    if (c < 0) return false;
    const auto cu = static_cast<std::size_t>(c);
    // Next stops, earliest finish first (deliveries first on ties).
    struct Next {
      double finish;
      StopRef stop;
      RouteState state;
    };
    std::vector<Next> next;
    bool carries_included = false;
    for (std::size_t j = 0; j < code_.size(); ++j) {
      const std::uint8_t code = code_[j];
      StopRef stop{static_cast<int>(j), StopKind::kPickup};
      if (code == c)
        stop.kind = StopKind::kDelivery, carries_included = true;
      else if (code != kWaiting)
        continue;
      RouteState s = state_[cu];
      if (!step(c, s, stop)) continue;
      next.push_back({s.t - (stop.kind == StopKind::kDelivery ? 1e-6 : 0.0), stop, s});
    }
    std::stable_sort(next.begin(), next.end(),
                     [](const Next& a, const Next& b) { return a.finish < b.finish; });
    const RouteState before = state_[cu];
    for (const Next& n : next) {
      const auto j = static_cast<std::size_t>(n.stop.job);
      const std::uint8_t code = code_[j];
      state_[cu] = n.state;
      routes_[cu].push_back(n.stop);
      code_[j] = n.stop.kind == StopKind::kPickup ? static_cast<std::uint8_t>(c) : kDone;
      if (code_[j] == kDone) --remaining_;
      if (search()) return true;
      if (code_[j] == kDone) ++remaining_;
      code_[j] = code;
      routes_[cu].pop_back();
      state_[cu] = before;
      if (cut_off_) return false;
    }
    if (!carries_included) {
      active_[cu] = 0;
      if (search()) return true;
      active_[cu] = 1;
      if (cut_off_) return false;
    }
    auto& seen = failed_[k];
    if (seen.size() < 8) {
      std::vector<double> times(state_.size());
      for (std::size_t i = 0; i < state_.size(); ++i) times[i] = state_[i].t;
      seen.push_back(std::move(times));
    }
    return false;
  }

  const SchedulingProblem& p_;
  const RouteSimulator& sim_;
  const std::vector<RouteState> starts_;
  std::vector<char> include_;
  std::vector<RouteState> state_;
  std::vector<char> active_;
  Routes routes_;
  std::vector<std::uint8_t> code_;  // per job: courier index when aboard, or kWaiting/kDone/kOut
  std::vector<std::size_t> finisher_;  // per job: a courier that could finish it alone lately
  std::size_t remaining_ = 0;
  std::unordered_map<std::string, std::vector<std::vector<double>>> failed_;
  std::uint64_t work_ = 0;
  std::uint64_t limit_ = 0;
  bool cut_off_ = false;
};

}  // namespace

JobSelection select_jobs(const SchedulingProblem& p) {
  JobSelection out;
  const std::size_t n = p.jobs.size();
  const std::size_t couriers = p.couriers.size();
  std::vector<char> left(n, 0);
  unreachable_or_absent(p, out.unschedulable, left);
  auto finish = [&]() -> JobSelection& {
    std::stable_sort(out.unschedulable.begin(), out.unschedulable.end(),
                     [](const UnschedulableJob& a, const UnschedulableJob& b) { return a.job < b.job; });
    return out;
  };

  // The forced prefixes, from each courier's start; what they pick up must be delivered.
  const RouteSimulator sim(p);
  std::vector<RouteState> starts;
  std::vector<char> in_prefix(n, 0), delivered_in_prefix(n, 0);
  for (std::size_t c = 0; c < couriers; ++c) {
    RouteState s = sim.start(static_cast<int>(c));
    for (StopRef stop : p.couriers[c].forced_prefix) {
      const auto j = static_cast<std::size_t>(stop.job);
      in_prefix[j] = 1;
      if (stop.kind == StopKind::kDelivery) delivered_in_prefix[j] = 1;
      const bool done = !left[j] && !sim.refusal(s, stop) &&
                        !(stop.kind == StopKind::kPickup && s.load >= p.couriers[c].capacity) &&
                        sim.advance(s, stop);
      if (!done) {
        out.reason = "courier '" + p.couriers[c].id + "': its forced prefix cannot be done (" +
                     to_string(stop.kind) + " of job " + quoted(p, stop.job) + ")";
        return finish();
      }
    }
    starts.push_back(s);
  }

  // Rule 2: missed even alone. The earliest arrival over the couriers that may do the job decides
  // (a later arrival never finds an earlier handover).
  for (std::size_t j = 0; j < n; ++j) {
    if (left[j] || in_prefix[j]) continue;
    const Job& job = p.jobs[j];
    const JobData& d = sim.job(static_cast<int>(j));
    double pick_arrival = kNoRoute, del_arrival = kNoRoute;
    for (std::size_t c = 0; c < couriers; ++c) {
      const RouteState& s = starts[c];
      if (job.status == JobStatus::kAboard) {
        if (static_cast<std::size_t>(job.aboard_courier) == c)
          del_arrival = s.t + sim.travel(s.loc, d.del_loc);
      } else {
        pick_arrival = std::min(pick_arrival, s.t + sim.travel(s.loc, d.pick_loc));
      }
    }
    if (job.status != JobStatus::kAboard) {
      const double start = start_within(d.pick_windows, pick_arrival, d.pick_dur);
      if (!(start < kNoRoute)) {
        out.unschedulable.push_back({static_cast<int>(j), UnschedulableReason::kNobodyPresent,
                                     missed(p, job.pickup, "pickup", pick_arrival)});
        left[j] = 1;
        continue;
      }
      del_arrival = start + d.pick_dur + sim.travel(d.pick_loc, d.del_loc);
    }
    if (!(start_within(d.del_windows, del_arrival, d.del_dur) < kNoRoute)) {
      out.unschedulable.push_back({static_cast<int>(j), UnschedulableReason::kNobodyPresent,
                                   missed(p, job.delivery, "delivery", del_arrival)});
      left[j] = 1;
    }
  }

  // Rule 3: together, or admitted one by one.
  Feasibility feasibility(p, sim, starts);
  const std::uint64_t question = question_work(n);
  const std::uint64_t selection = std::max(kSelectionWork, 2 * question);
  auto limit = [&] {
    const std::uint64_t used = feasibility.work();
    return used >= selection ? 0 : std::min(question, selection - used);
  };
  std::vector<char> kept(n, 0);
  for (std::size_t j = 0; j < n; ++j) kept[j] = !left[j] && !delivered_in_prefix[j];
  Routes tail;
  if (feasibility.decide(kept, limit(), tail) != Feasibility::Answer::kFeasible) {
    std::vector<int> order;  // objects aboard first, then job order
    for (int pass = 0; pass < 2; ++pass)
      for (std::size_t j = 0; j < n; ++j)
        if (kept[j] && !in_prefix[j] && (p.jobs[j].status == JobStatus::kAboard) == (pass == 0))
          order.push_back(static_cast<int>(j));
    for (int j : order) kept[static_cast<std::size_t>(j)] = 0;
    const auto base = feasibility.decide(kept, limit(), tail);
    if (base != Feasibility::Answer::kFeasible) {
      out.proved = base == Feasibility::Answer::kInfeasible;
      out.reason = out.proved ? "the objects the forced prefixes pick up cannot all be delivered"
                              : "no order found for the forced prefixes' objects within the "
                                "search limit";
      return finish();
    }
    std::vector<int> admitted;
    std::uint64_t naming_work = 0;
    for (int j : order) {
      const auto ju = static_cast<std::size_t>(j);
      kept[ju] = 1;
      Routes trial = tail;
      Feasibility::Answer answer = Feasibility::Answer::kFeasible;
      // A place in the order so far proves it at once; otherwise the complete search decides.
      if (!feasibility.insert(kept, trial, j, limit()))
        answer = feasibility.decide(kept, limit(), trial);
      if (answer == Feasibility::Answer::kFeasible) {
        tail = std::move(trial);
        admitted.push_back(j);
        continue;
      }
      kept[ju] = 0;
      const bool proved = answer == Feasibility::Answer::kInfeasible;
      out.proved = out.proved && proved;
      // Name the first kept job it cannot be done with on its own, if there is one.
      std::string with;
      std::vector<char> pair(n, 0);
      for (std::size_t m = 0; m < n; ++m) pair[m] = kept[m] && in_prefix[m];
      pair[ju] = 1;
      for (int other : admitted) {
        if (naming_work >= kNamingWork) break;
        pair[static_cast<std::size_t>(other)] = 1;
        Routes ignored;
        const std::uint64_t w0 = feasibility.work();
        const auto a = feasibility.decide(pair, kPairWork, ignored);
        naming_work += feasibility.work() - w0;
        pair[static_cast<std::size_t>(other)] = 0;
        if (a == Feasibility::Answer::kInfeasible) {
          with = "job " + quoted(p, other);
          break;
        }
      }
      if (with.empty() && admitted.empty()) {
        bool stays_aboard = false, prefix_pickups = false;
        for (std::size_t m = 0; m < n; ++m) {
          stays_aboard = stays_aboard || (!kept[m] && p.jobs[m].status == JobStatus::kAboard);
          prefix_pickups = prefix_pickups || (kept[m] && in_prefix[m]);
        }
        with = stays_aboard ? "the objects left out that stay aboard" : "";
        if (prefix_pickups || with.empty())
          with += std::string(with.empty() ? "" : " and ") + "what the forced prefixes pick up";
      } else if (with.empty()) {
        with = "the jobs kept before it (";
        for (std::size_t k = 0; k < admitted.size() && k < 5; ++k)
          with += (k ? ", " : "") + quoted(p, admitted[k]);
        if (admitted.size() > 5) with += " and " + std::to_string(admitted.size() - 5) + " more";
        with += ")";
      }
      out.unschedulable.push_back(
          {j, UnschedulableReason::kClash,
           "cannot be done together with " + with +
               (proved ? "" : " (no order found within the search limit: not proved)")});
    }
  }
  out.feasible = true;
  out.witness.resize(couriers);
  for (std::size_t c = 0; c < couriers; ++c) {
    out.witness[c] = p.couriers[c].forced_prefix;
    out.witness[c].insert(out.witness[c].end(), tail[c].begin(), tail[c].end());
  }
  out.work = feasibility.work();
  return finish();
}

}  // namespace autonomy::courier::scheduling::detail
