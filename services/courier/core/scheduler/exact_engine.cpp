// The exact engine: branch and bound over partial routes of one courier, breadth first by the
// number of stops done, with
//   - an incumbent from the large engine's search (greedy dispatch, descent, a few ruin and
//     recreate rounds), so pruning starts at once;
//   - a lower bound per partial route (lower_bound below: earliest completions, handover and
//     travel time still needed, on-time slot matching); travel is bounded by the farthest place
//     still to visit, only when the three terms before it tie with the incumbent; the
//     completion term also by the delivery-sequence bound (delivery_sequence_bound.hpp: the
//     cheapest order of the deliveries left, tabulated once per search, plus the pickups'
//     handovers and detours);
//   - dominance: two partial routes that picked up and delivered the same jobs and stand at the
//     same location have the same choices left, and every future cost term is non-decreasing in
//     the start time (waiting for presence is allowed, deadlines are soft). So one that is there
//     no earlier and no better lexicographically than another cannot lead to anything better,
//     and is dropped. One that is there earlier but is worse is dropped too when the delay of the
//     other is priced (delay_penalty: no presence window can be missed by it, so every later
//     completion is at most the delay later) and it still does not make up the difference.
//     Conversely, when no stop left can wait for a window, a later label that is better is
//     dropped when the earlier one's head start, kept by each job left, makes up the difference
//     (gain_covers). In loose offices (few deadlines, everybody present) that leaves one label
//     per state: the search is a dynamic program over states with bound pruning. Breadth
//     first, every label of a state is known before any is expanded, so only non-dominated
//     ones are (depth first expanded about as many later-dominated labels as surviving ones,
//     measured). The textbook dynamic program (reference_dp.hpp) keeps the
//     same states but without bound, delay pricing or incumbent.
// Labels live only in the layer being expanded and the one being built (and their last stop in
// a trail for the route), with the aboard set as masks: the search is memory bound, and a label
// with the simulator's whole RouteState was twice as large.
// Several couriers: every assignment of the waiting jobs to couriers, each courier's job set
// solved once (memoised); refused (large engine's answer, not proved) beyond 2^14 assignments.
#include "services/courier/core/scheduler/delivery_sequence_bound.hpp"
#include "services/courier/core/scheduler/route_search.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

namespace autonomy::courier::scheduling::detail {

namespace {

constexpr int kMaxJobsPerCourier = 30;
// Partial routes kept at most: the trail steps of the labels alive after the last layer plus the
// labels of the layer being built (12 bytes each for the route, about 80 while in a layer):
// beyond, the search gives up, not proved.
constexpr std::size_t kMaxLabels = 1u << 20;
constexpr std::uint64_t kMaxAssignments = 1u << 14;
// Ruin-and-recreate rounds without improvement for the incumbent. The search is breadth first, so
// it finds complete routes only in its last layer and prunes with the incumbent until then: at 5
// rounds the incumbent was 1-2 % above the optimum on most loose 12-job offices (9 % on one),
// at 60 it is nearly always optimal and the search 20-30 % cheaper (bench 1b, CPU medians).
// That was before the beam search below: with one courier and the beam's job count the rounds
// are skipped (greedy dispatch and descent only), since the beam then finds the incumbent. They
// were 15 % of a loose 12-job solve's instructions (callgrind, seeds 1-10 and 1001-1020), and
// without them the solves took 12 % fewer instructions in all; at 12 jobs CPU medians 10-14 %
// lower on the loose class, 16-45 % on the default class (docs/courier-scheduling.md).
constexpr int kIncumbentRounds = 60;
// Then a beam search over the exact search's own states (the labels of the best bound per layer)
// from 8 jobs per courier: the large engine's routes were above the optimum on 8 of 20 loose
// 12-job offices (seeds 1001-1020), and on those the search expanded up to 1.7 times the labels
// it expands with the optimum as incumbent. 64 labels per layer improve the incumbent on 8 of
// 20 (and 6 of 10 on seeds 1-10); the search improves on the beam's on 1 of 20 (1 of 10). It
// costs 2-3 ms at 12 jobs, about 1,100 labels expanded (32: more left to improve; 128 and 256:
// none left on 1001-1020, more cost).
constexpr std::size_t kBeamWidth = 64;
constexpr std::size_t kBeamFromJobs = 8;
// The delivery-sequence bound from this many jobs per courier (below, searches are small; its
// table has 2^jobs x places entries, built once per search).
constexpr std::size_t kSequenceFromJobs = 6;

// C++17 has no <bit>: the compiler builtins (GCC and Clang) for the mask loops.
int lowest_bit(std::uint64_t x) {
  return __builtin_ctzll(x);
}
int bit_count(std::uint32_t x) {
  return __builtin_popcount(x);
}

// Sort of the bound's arrays (at most 30 values, about 10 on average) by counting each value's
// rank: no data-dependent branches, so it vectorises. std::sort was 18 % of a loose 12-job
// search (its dispatch on such short arrays), insertion sort 22-25 % (a mispredicted branch per
// move); counting takes about two thirds of insertion sort's time.
void sort_bound_values(double* v, int n) {
  double in[32];
  for (int i = 0; i < n; ++i) in[i] = v[i];
  for (int i = 0; i < n; ++i) {
    const double x = in[i];
    int rank = 0;
    for (int j = 0; j < i; ++j) rank += in[j] <= x;
    for (int j = i + 1; j < n; ++j) rank += in[j] < x;
    v[rank] = x;
  }
}

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
  // `sequence` (may be null): the delivery-sequence table of another search of the same jobs
  // from the same start (the beam's), shared instead of built again.
  CourierSearch(RouteSearch& rs, const std::vector<double>& shortest, const std::vector<int>& jobs,
                const RouteState& start, int capacity, const SearchBudget& budget,
                std::shared_ptr<const DeliverySequenceBound> sequence = nullptr)
      : rs_(rs),
        sim_(rs.sim()),
        shortest_(shortest),
        jobs_(jobs),
        start_(start),
        budget_(budget),
        n_(rs.problem().locations.size()),
        capacity_(capacity) {
    arena_->in_use = true;
    current_.clear();
    next_.clear();
    trail_.clear();
    states_.reset();
    for (std::size_t i = 0; i < jobs_.size(); ++i)
      if (start_.carries(jobs_[i])) initially_picked_ |= 1u << i;
    all_ = jobs_.size() == 32 ? ~0u : (1u << jobs_.size()) - 1u;
    // Objects aboard that are not jobs of this search (they stay aboard): they take capacity and
    // block look-alikes for the whole route.
    for (int k = 0; k < start_.load; ++k) {
      const int j = start_.aboard[static_cast<std::size_t>(k)];
      if (std::find(jobs_.begin(), jobs_.end(), j) == jobs_.end()) base_aboard_.push_back(j);
    }
    // Places this search can be at: the start and the jobs' stops, with local ids for masks.
    local_.assign(n_, -1);
    auto add = [&](int loc) {
      if (local_[static_cast<std::size_t>(loc)] < 0) {
        local_[static_cast<std::size_t>(loc)] = static_cast<int>(places_.size());
        places_.push_back(loc);
      }
      return local_[static_cast<std::size_t>(loc)];
    };
    add(start_.loc);
    for (std::size_t i = 0; i < jobs_.size(); ++i) {
      const JobData& d = sim_.job(jobs_[i]);
      LocalJob& lj = local_jobs_[i];
      lj.pick_place = (initially_picked_ >> i & 1u) ? -1 : add(d.pick_loc);
      lj.del_place = add(d.del_loc);
      for (std::size_t k = 0; k < jobs_.size(); ++k)
        if (sim_.job(jobs_[k]).cls == d.cls) lj.look_alikes |= 1u << k;
      for (int b : base_aboard_) lj.blocked_for_good |= sim_.job(b).cls == d.cls;
      if (d.pick_windows) pick_windowed_ |= 1u << i;
      if (d.del_windows) del_windowed_ |= 1u << i;
    }
    // Per place, the other places by travel time to it (nearest first), and the longest direct
    // leg into it (for the delay dominance's upper bound on finish times).
    longest_leg_in_.assign(places_.size(), 0.0);
    std::vector<std::pair<double, int>> by_leg;
    for (std::size_t a = 0; a < places_.size(); ++a) {
      by_leg.clear();
      for (std::size_t b = 0; b < places_.size(); ++b) {
        if (a == b) continue;
        by_leg.push_back({sp(places_[b], places_[a]), static_cast<int>(b)});
        const double leg = sim_.travel(places_[b], places_[a]);
        if (leg < kNoRoute) longest_leg_in_[a] = std::max(longest_leg_in_[a], leg);
      }
      std::sort(by_leg.begin(), by_leg.end());
      for (const auto& [leg, b] : by_leg) nearest_leg_.push_back(leg), nearest_from_.push_back(b);
    }
    masks_ok_ = places_.size() <= 64;
    sequence_ = std::move(sequence);
    build_sequence_bound();
    if (sequence_) prepare_sequence_completion();
    for (std::size_t i = 0; i < jobs_.size(); ++i) by_deadline_.push_back(static_cast<int>(i));
    std::sort(by_deadline_.begin(), by_deadline_.end(), [&](int x, int y) {
      return sim_.job(jobs_[static_cast<std::size_t>(x)]).deadline <
             sim_.job(jobs_[static_cast<std::size_t>(y)]).deadline;
    });
  }

  ~CourierSearch() {
    trim(current_);
    trim(next_);
    trim(trail_);
    trim(renumber_);
    if (states_.slots.size() * sizeof(StateTable::Slot) > kArenaKeepBytes)
      states_.slots = std::vector<StateTable::Slot>(1u << 10);
    arena_->in_use = false;
  }
  CourierSearch(const CourierSearch&) = delete;
  CourierSearch& operator=(const CourierSearch&) = delete;

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
  const std::shared_ptr<const DeliverySequenceBound>& sequence_bound() const { return sequence_; }
  bool out_of_memory() const { return out_of_memory_; }
  // Beam search instead, for an incumbent: each layer keeps only its `width` labels of the best
  // lower bound. Its result is a complete route (if found), never proved optimal.
  // The beam ranks by the bound without the delivery-sequence part: with it, its route was worse
  // on some offices (one loose 16-job office of 20 then stopped at the label cap).
  void set_beam(std::size_t width) { beam_ = width; }

 private:
  // A job of this search by its local index (bit i of the masks).
  struct LocalJob {
    int pick_place = -1;  // -1: aboard from the start
    int del_place = -1;
    std::uint32_t look_alikes = 0;  // jobs of the same class (itself included)
    bool blocked_for_good = false;  // a look-alike that is not a job here stays aboard
  };

  // One partial route of the layer being built or expanded (the aboard set is picked minus
  // delivered, plus base_aboard_).
  struct Label {
    Objective cost;
    double t = 0.0;
    std::uint32_t picked = 0;
    std::uint32_t delivered = 0;
    int loc = -1;
    int trail = -1;  // its last step in trail_ (-1: the start)
    int next = -1;   // the next label of the same state in this layer
    bool visited = false;
    bool alive = true;
  };
  // How a label got there: kept for every label ever made, to rebuild the best route.
  struct TrailStep {
    int parent = -1;
    StopRef stop;
  };

  // Open addressing from a state (picked, delivered, location) to its chain of labels in the
  // layer being built. Reset per layer by a new generation, without clearing.
  struct StateTable {
    struct Slot {
      std::uint64_t masks = 0;
      int loc = -1;
      int head = -1;
      std::uint32_t generation = 0;
    };
    std::vector<Slot> slots = std::vector<Slot>(1u << 10);
    std::size_t used = 0;
    std::uint32_t generation = 1;

    void reset() { ++generation, used = 0; }
    static std::size_t hash(std::uint64_t masks, int loc) {
      std::uint64_t x = masks ^ (static_cast<std::uint64_t>(loc) * 0x9E3779B97F4A7C15ull);
      x ^= x >> 31;
      x *= 0xBF58476D1CE4E5B9ull;
      x ^= x >> 29;
      return static_cast<std::size_t>(x);
    }
    Slot& find(std::uint64_t masks, int loc, std::size_t h) {
      const std::size_t mask = slots.size() - 1;
      for (std::size_t i = h & mask;; i = (i + 1) & mask) {
        Slot& s = slots[i];
        if (s.generation != generation || (s.masks == masks && s.loc == loc)) return s;
      }
    }
    // The slot a lookup of hash h starts at, asked for early: the lookups are cache misses, and
    // a parent's children are looked up together after all of them are made.
    void prefetch(std::size_t h) const { __builtin_prefetch(&slots[h & (slots.size() - 1)]); }
    Slot& claim(std::uint64_t masks, int loc, std::size_t h) {
      if (2 * (used + 1) > slots.size()) {
        std::vector<Slot> old = std::move(slots);
        slots.assign(old.size() * 2, Slot{});
        for (const Slot& s : old)
          if (s.generation == generation) find(s.masks, s.loc, hash(s.masks, s.loc)) = s;
      }
      Slot& s = find(masks, loc, h);
      if (s.generation != generation) s = {masks, loc, -1, generation}, ++used;
      return s;
    }
  };

  // The delivery-sequence table (delivery_sequence_bound.hpp), unless another search of the
  // same jobs from the same start gave it (the beam's) or the job count is out of its range.
  void build_sequence_bound() {
    if (sequence_ || !masks_ok_ || jobs_.size() < kSequenceFromJobs ||
        jobs_.size() > static_cast<std::size_t>(DeliverySequenceBound::kMaxJobs))
      return;
    std::vector<int> del_place;
    std::vector<double> del_dur, travel;
    for (std::size_t i = 0; i < jobs_.size(); ++i) {
      del_place.push_back(local_jobs_[i].del_place);
      del_dur.push_back(data(i).del_dur);
    }
    for (int a : places_)
      for (int b : places_) travel.push_back(sp(a, b));
    sequence_ = std::make_shared<const DeliverySequenceBound>(del_place, del_dur, travel,
                                                              static_cast<int>(places_.size()));
  }
  void prepare_sequence_completion() {
    for (std::size_t i = 0; i < jobs_.size(); ++i) {
      const LocalJob& lj = local_jobs_[i];
      if (lj.pick_place >= 0) picks_at_[lj.pick_place] |= 1u << i;
      pick_dur_[i] = data(i).pick_dur;
      del_place_bit_[i] = 1ull << lj.del_place;
    }
  }

  // The delivery-sequence bound on the completion still to come from s (r jobs left, from now):
  // the table's deliveries from where s stands, plus the pickups left, each its handover and its
  // share of its place's detour (shared by the pickups left there: one visit may do them all;
  // none where a delivery is left or where s stands, since a delivery's visit or the visit under
  // way may do it), the largest at weight 1, the next at 2, ... (each is done no later than its
  // own delivery, and the deliveries take distinct positions).
  double sequence_completion(const Label& s, int r) const {
    const std::uint32_t left = all_ & ~s.delivered;
    const std::uint32_t to_pick = left & ~s.picked;
    const int here = local_[static_cast<std::size_t>(s.loc)];
    std::uint64_t delivery_places = 0;
    for (std::uint32_t b = left; b; b &= b - 1) delivery_places |= del_place_bit_[__builtin_ctz(b)];
    // Sum of x_k times its weight (1 for the largest, ...): the sum of the x plus, over each
    // pair, the smaller one (no sort).
    double x[kMaxJobsPerCourier];
    int u = 0;
    for (std::uint32_t b = to_pick; b; b &= b - 1) {
      const int i = __builtin_ctz(b);
      const int place = local_jobs_[i].pick_place;
      x[u] = pick_dur_[i];
      if (place != here && !(delivery_places >> place & 1ull))
        x[u] += sequence_->detour(place) / __builtin_popcount(picks_at_[place] & to_pick);
      ++u;
    }
    double pickups = 0.0;
    for (int i = 0; i < u; ++i) {
      pickups += x[i];
      for (int j = i + 1; j < u; ++j) pickups += std::min(x[i], x[j]);
    }
    return r * (s.t - rs_.problem().now_s) + sequence_->cost(left, here) + pickups;
  }

  double sp(int a, int b) const {
    return shortest_[static_cast<std::size_t>(a) * n_ + static_cast<std::size_t>(b)];
  }
  const JobData& data(std::size_t i) const { return sim_.job(jobs_[i]); }

  // False when some job left cannot be finished at all. The bound combines, for the jobs left (r
  // of them):
  //   e_j  earliest completion of job j if it were done next, alone;
  //   w_j  the time job j's remaining stops take at least: their handovers, plus a share of the
  //        travel into their places. Every place still to visit needs one leg in at least, from
  //        the nearest place the courier can come from (where it is, or another place still to
  //        visit; nothing for the place it stands at). Any split of that leg among the jobs
  //        with a stop there is a valid w: any k jobs touch their places, so the sum of their w
  //        is at most the time those k take. The leg is split by water filling (raising the
  //        smallest w of those jobs first), which keeps the w even and so their sorted prefix
  //        sums large: it cut 10-20 % of the labels expanded at 12 loose jobs against the two
  //        fixed splits used before (all to one job, or equal shares), and made them redundant;
  //   c_k  a lower bound on the k-th smallest completion: max(e_(k), t + the sum of the k
  //        smallest w_j, c_(k-1) + the shortest delivery handover left);
  //   late jobs >= max(#{e_j > d_j}, jobs that cannot get an on-time slot among the c_k, matched
  //        greedily by deadline: slots are prefixes, so greedy is exact);
  //   lateness >= max(sum max(0, e_j - d_j), sum max(0, c_k - d_(k)) with deadlines sorted: the
  //        sorted matching minimises a sum of a convex function of c - d);
  //   completion >= sum (c_k - now).
  //
  // The work part (t + the sum of the k smallest w_j, each completion at least `gap` after the
  // one before) is computed first: on loose offices it decides nearly every cut (bench 1b, 12
  // jobs, seed 1: the sum of the e_j alone would cut 20 of the about 44,000 labels the bound
  // cuts), so when `cut_at` is given and that part already reaches it, the e_j and the deadline
  // terms are skipped (returns false: no completion beats `cut_at`). It is a componentwise lower
  // bound of the whole, so the same labels are cut. Also false when some job left cannot be
  // finished.
  bool lower_bound(const Label& s, Objective& lb, const Objective* cut_at = nullptr) {
    lb = s.cost;
    int r = 0;
    double shortest_delivery_left = kNoRoute;
    std::uint64_t active = 0;  // places with a stop left, as place masks of the jobs (by slot r)
    for (std::size_t i = 0; i < jobs_.size(); ++i) {
      if (s.delivered >> i & 1u) continue;
      const JobData& d = data(i);
      const LocalJob& lj = local_jobs_[i];
      const bool picked = s.picked >> i & 1u;
      shortest_delivery_left = std::min(shortest_delivery_left, d.del_dur);
      work_[r] = d.del_dur + (picked ? 0.0 : d.pick_dur);
      if (masks_ok_) {
        if (!picked) {
          active |= 1ull << lj.pick_place;
          touching_[lj.pick_place] |= 1u << r;
        }
        active |= 1ull << lj.del_place;
        touching_[lj.del_place] |= 1u << r;
      }
      ++r;
    }
    if (masks_ok_) charge_legs(local_[static_cast<std::size_t>(s.loc)], active);
    const double gap = shortest_delivery_left;
    const double now = rs_.problem().now_s;
    if (cut_at) {
      // Every w_j is at least its delivery handover, so at least `gap`: the chain never binds
      // here and the work part is t - now plus the k-th prefix sum of the sorted w, summed over
      // k. That sum is sum_j w_j plus, over pairs, the smaller w of the pair, which needs no
      // sort (the sort is done only for the labels this part does not cut).
      Objective partial = s.cost;
      double pairs = 0.0;
      for (int i = 0; i < r; ++i) {
        const double wi = work_[i];
        pairs += wi;
        for (int j = i + 1; j < r; ++j) pairs += std::min(wi, work_[j]);
      }
      partial.completion_s += r * (s.t - now) + pairs;
      if (compare(partial, *cut_at) >= 0) return false;
      // Then the delivery-sequence bound (cut 19 % of the labels expanded on the 30 loose 12-job
      // offices), only for the labels the work part leaves (about a third).
      if (sequence_ && !beam_) {
        sequence_value_ = sequence_completion(s, r);
        partial.completion_s = s.cost.completion_s + sequence_value_;
        if (compare(partial, *cut_at) >= 0) return false;
      }
    }
    sort_bound_values(work_, r);
    int late_alone = 0;
    double lateness_alone = 0.0;
    for (int i = 0, k = 0; i < static_cast<int>(jobs_.size()); ++i) {
      if (s.delivered >> i & 1u) continue;
      const double t = earliest_alone(s, static_cast<std::size_t>(i), s.t);
      if (!(t < kNoRoute)) return false;
      const double deadline = data(static_cast<std::size_t>(i)).deadline;
      if (t > deadline + 1e-9) {
        ++late_alone;
        lateness_alone += t - deadline;
      }
      earliest_[k++] = t;
    }
    int q = 0;
    for (int i : by_deadline_)
      if (!(s.delivered >> i & 1u)) due_[q++] = data(static_cast<std::size_t>(i)).deadline;
    sort_bound_values(earliest_, r);
    double previous = -kNoRoute;
    double busy = s.t;
    double completion = 0.0, lateness_sorted = 0.0;
    for (int k = 0; k < r; ++k) {
      busy += work_[k];
      const double c = std::max({earliest_[k], busy, previous + gap});
      slot_[k] = c;
      completion += c - now;
      if (c > due_[k] + 1e-9) lateness_sorted += c - due_[k];
      previous = c;
    }
    // Greedy on-time matching: deadlines ascending, each takes the earliest free slot if on time.
    int next_slot = 0, on_time = 0;
    for (int k = 0; k < r; ++k)
      if (next_slot < r && slot_[next_slot] <= due_[k] + 1e-9) ++next_slot, ++on_time;
    lb.late_jobs += std::max(late_alone, r - on_time);
    lb.lateness_s += std::max(lateness_alone, lateness_sorted);
    if (sequence_ && !beam_)
      completion = std::max(completion, cut_at ? sequence_value_ : sequence_completion(s, r));
    lb.completion_s += completion;
    return true;
  }

  // Adds to work_ each active place's leg in (see lower_bound), split among the jobs touching it
  // by water filling; clears touching_.
  void charge_legs(int here, std::uint64_t active) {
    const std::uint64_t sources = active | 1ull << here;
    for (std::uint64_t rest = active; rest; rest &= rest - 1) {
      const int a = lowest_bit(rest);
      const std::uint32_t jobs = touching_[a];
      touching_[a] = 0;
      if (a == here) continue;
      double leg = 0.0;
      const std::size_t others = places_.size() - 1;
      const std::size_t row = static_cast<std::size_t>(a) * others;
      for (std::size_t k = row; k < row + others; ++k)
        if (sources >> nearest_from_[k] & 1ull) {
          leg = nearest_leg_[k] < kNoRoute ? nearest_leg_[k] : 0.0;
          break;
        }
      if (leg <= 0.0) continue;
      if ((jobs & (jobs - 1)) == 0) {  // one job there (the common case): all of it
        work_[__builtin_ctz(jobs)] += leg;
        continue;
      }
      // The jobs there by w ascending (a few), then the lowest k raised to a common level.
      int n = 0;
      for (std::uint32_t b = jobs; b; b &= b - 1) {
        const int v = __builtin_ctz(b);
        int y = n++;
        for (; y > 0 && work_[fill_[y - 1]] > work_[v]; --y) fill_[y] = fill_[y - 1];
        fill_[y] = v;
      }
      // The k lowest are raised while their common level (leg + their sum) / k would pass the
      // next one; compared by multiplying (a division per step was the bound's slowest line).
      double sum = leg;
      int k = 0;
      while (k < n) {
        sum += work_[fill_[k++]];
        if (k == n || sum <= k * work_[fill_[k]]) break;
      }
      const double level = sum / k;
      for (int x = 0; x < k; ++x) work_[fill_[x]] = level;
    }
  }

  double travel_bound(const Label& s) const {
    double far = 0.0;
    for (std::size_t i = 0; i < jobs_.size(); ++i) {
      if (s.delivered >> i & 1u) continue;
      const JobData& d = data(i);
      far = std::max(far, sp(s.loc, d.del_loc));
      if (!(s.picked >> i & 1u)) far = std::max(far, sp(s.loc, d.pick_loc));
    }
    return far;
  }

  // False when the bound says no completion of this partial route beats the incumbent.
  bool bounded_below_best(const Label& s) {
    Objective lb;
    if (!lower_bound(s, lb, found_ ? &best_ : nullptr)) return false;
    if (!found_) return true;
    if (compare(lb, best_) >= 0) return false;
    if (lb.late_jobs == best_.late_jobs && std::abs(lb.lateness_s - best_.lateness_s) < 1e-6 &&
        std::abs(lb.completion_s - best_.completion_s) < 1e-6) {
      lb.travel_s += travel_bound(s);
      if (compare(lb, best_) >= 0) return false;
    }
    return true;
  }

  // Two labels of one state (same jobs picked up and delivered, same place) face the same
  // choices. Started at `early`, the rest of any route is no worse than started at `late` >=
  // early, since every cost term is non-decreasing in the start time. The converse holds up to a
  // penalty when nothing left can jump: if every handover left falls in the same presence window
  // whether started at early or late, each later finish is at most late - early later, so the
  // late label ends at most (late - early) x (jobs left) worse in completion and, for the jobs
  // whose deadline could pass, one more late job and late - early more lateness each. Returns
  // false when a window could be missed (no penalty bounds it).
  bool delay_penalty(const Label& s, double early, double late, Objective& penalty) {
    // Latest any handover left can finish: from `late`, every leg at its longest, no waiting
    // after the latest window opening used.
    double span = 0.0;
    double waits_until = late;
    int windowed = 0;
    auto visit = [&](int place, double dur, const std::vector<TimeWindow>* windows) {
      span += longest_leg_in_[static_cast<std::size_t>(place)] + dur;
      if (!windows) return true;
      for (const TimeWindow& w : *windows)
        if (std::max(early, w.start_s) + dur <= w.end_s) {
          waits_until = std::max(waits_until, w.start_s);
          window_start_[windowed] = w.start_s;
          latest_start_[windowed++] = w.end_s - dur;
          return true;
        }
      return false;
    };
    int left = 0;
    for (std::size_t i = 0; i < jobs_.size(); ++i) {
      if (s.delivered >> i & 1u) continue;
      const JobData& d = data(i);
      const LocalJob& lj = local_jobs_[i];
      if (!(s.picked >> i & 1u) && !visit(lj.pick_place, d.pick_dur, d.pick_windows)) return false;
      if (!visit(lj.del_place, d.del_dur, d.del_windows)) return false;
      ++left;
    }
    const double latest_finish = waits_until + span;
    for (int k = 0; k < windowed; ++k)
      if (std::max(latest_finish, window_start_[k]) > latest_start_[k]) return false;
    const double delay = late - early;
    penalty = Objective{};
    penalty.completion_s = delay * left;
    for (std::size_t i = 0; i < jobs_.size(); ++i)
      if (!(s.delivered >> i & 1u) && data(i).deadline < latest_finish) {
        // A job that is late even done next alone from `early` is late either way: the delay
        // adds lateness, not a late job.
        if (earliest_alone(s, i, early) <= data(i).deadline + 1e-9) ++penalty.late_jobs;
        penalty.lateness_s += delay;
      }
    return true;
  }

  // Earliest finish of local job i's delivery from the label's state at time t, the job done
  // next and alone (shortest travel, presence windows).
  double earliest_alone(const Label& s, std::size_t i, double t) const {
    const JobData& d = data(i);
    int loc = s.loc;
    if (!(s.picked >> i & 1u)) {
      t = start_within(d.pick_windows, t + sp(loc, d.pick_loc), d.pick_dur) + d.pick_dur;
      loc = d.pick_loc;
    }
    return start_within(d.del_windows, t + sp(loc, d.del_loc), d.del_dur) + d.del_dur;
  }

  // True when no stop left in the label's state can wait for a presence window: every route
  // from the state then finishes each handover exactly `delay` later when started `delay` later.
  bool no_wait(const Label& s) const {
    return !(~s.picked & pick_windowed_) && !(~s.delivered & del_windowed_);
  }
  // `a` (earlier, same state, no waiting left) is no worse than `b`: started at b.t instead of
  // a.t, every route finishes each of the r jobs left b.t - a.t later (and may add late jobs and
  // lateness, never travel or visits), so b pays at least (b.t - a.t) r more completion.
  bool gain_covers(const Label& a, const Label& b) const {
    Objective shifted = b.cost;
    shifted.completion_s += (b.t - a.t) * jobs_left(a);
    return compare(a.cost, shifted) <= 0;
  }
  int jobs_left(const Label& s) const {
    return static_cast<int>(jobs_.size()) - bit_count(s.delivered);
  }

  // `a` is no worse than `b` (same state) for every way to finish the route.
  bool dominates(const Label& a, const Label& b) {
    const int by_cost = compare(a.cost, b.cost);
    if (a.t <= b.t + 1e-9) return by_cost <= 0 || (no_wait(a) && gain_covers(a, b));
    if (by_cost >= 0) return false;
    Objective penalty;
    return delay_penalty(a, b.t, a.t, penalty) && compare(a.cost + penalty, b.cost) <= 0;
  }

  // RouteSimulator::advance on a label, without building and copying a RouteState per child:
  // the aboard set is the masks, and the rules (capacity, look-alikes) are checked by the caller.
  bool advance_label(const Label& from, StopRef stop, Label& to) const {
    to.cost = from.cost;
    to.t = from.t;
    to.loc = from.loc;
    to.visited = from.visited;
    return sim_.timed_step(to.t, to.loc, to.visited, to.cost, stop);
  }

  static std::uint64_t key(const Label& l) {
    return l.picked | static_cast<std::uint64_t>(l.delivered) << 32;
  }

  // Adds a child to the layer being built unless a label of its state dominates it; drops the
  // labels of its state it dominates. The bound waits for the expansion: most children are
  // dominated by a sibling made later, and bounding them all cost more than it saved (measured).
  void add_label(const Label& child, const StopRef& stop, int parent_trail, std::size_t hash) {
    auto& slot = states_.claim(key(child), child.loc, hash);
    for (int k = slot.head; k >= 0; k = next_[static_cast<std::size_t>(k)].next) {
      Label& other = next_[static_cast<std::size_t>(k)];
      if (!other.alive) continue;
      if (dominates(other, child)) return;
      if (dominates(child, other)) other.alive = false;
    }
    if (trail_.size() >= kMaxLabels) {
      stopped_ = out_of_memory_ = true;
      return;
    }
    trail_.push_back({parent_trail, stop});
    Label kept = child;
    kept.trail = static_cast<int>(trail_.size() - 1);
    kept.next = slot.head;
    next_.push_back(kept);
    slot.head = static_cast<int>(next_.size() - 1);
  }

  // The beam's cut of the layer just built: only the beam_ labels of the best bound stay.
  void keep_beam() {
    beam_order_.clear();
    for (std::size_t k = 0; k < next_.size(); ++k) {
      Label& l = next_[k];
      if (!l.alive) continue;
      Objective lb;
      if (lower_bound(l, lb))
        beam_order_.push_back({lb, static_cast<int>(k)});
      else
        l.alive = false;
    }
    if (beam_order_.size() <= beam_) return;
    std::nth_element(beam_order_.begin(), beam_order_.begin() + static_cast<std::ptrdiff_t>(beam_),
                     beam_order_.end(),
                     [](const auto& x, const auto& y) { return better(x.first, y.first); });
    for (std::size_t k = beam_; k < beam_order_.size(); ++k)
      next_[static_cast<std::size_t>(beam_order_[k].second)].alive = false;
  }

  // After each layer, drops the steps no label of the layer just built (nor the best complete
  // route) leads back to: those of labels dominated or cut by the bound. Parents come before
  // their children in trail_, so one pass renumbers them, in time linear in the trail (about as
  // much as building the layer). Without it the trail of every label ever made filled the 2^20
  // cap on 15 of 30 loose 14-job offices (bench 1b) while most of it was dead.
  void compact_trail(int& best_trail) {
    constexpr int kUnmarked = -1, kMarked = -2;
    renumber_.assign(trail_.size(), kUnmarked);
    auto mark = [&](int k) {
      for (; k >= 0 && renumber_[static_cast<std::size_t>(k)] == kUnmarked;
           k = trail_[static_cast<std::size_t>(k)].parent)
        renumber_[static_cast<std::size_t>(k)] = kMarked;
    };
    for (const Label& label : next_)
      if (label.alive) mark(label.trail);
    mark(best_trail);
    int kept = 0;
    for (std::size_t k = 0; k < trail_.size(); ++k) {
      if (renumber_[k] != kMarked) continue;
      TrailStep step = trail_[k];
      if (step.parent >= 0) step.parent = renumber_[static_cast<std::size_t>(step.parent)];
      renumber_[k] = kept;
      trail_[static_cast<std::size_t>(kept++)] = step;
    }
    trail_.resize(static_cast<std::size_t>(kept));
    for (Label& label : next_)
      if (label.alive && label.trail >= 0)
        label.trail = renumber_[static_cast<std::size_t>(label.trail)];
    if (best_trail >= 0) best_trail = renumber_[static_cast<std::size_t>(best_trail)];
  }

  // Breadth first by the number of stops done, so that every label of a state is known before
  // any of them is expanded: only non-dominated labels are expanded (a depth-first search expands
  // many that a later label dominates), each bounded against the incumbent first.
  void search() {
    Label root;
    root.cost = start_.cost;
    root.t = start_.t;
    root.loc = start_.loc;
    root.visited = start_.visited;
    root.picked = initially_picked_;
    if (jobs_.empty()) {
      // Nothing to do is a complete route: a courier left idle (e.g. one available only after
      // the others have done everything) is a valid assignment, not an infeasible one.
      if (!found_ || better(root.cost, best_)) best_ = root.cost, best_route_.clear();
      found_ = true;
      return;
    }
    current_.assign(1, root);
    int best_trail = -2;  // -2: the incumbent given to run()
    StopRef best_last;
    const int base_load = static_cast<int>(base_aboard_.size());
    while (!current_.empty() && !stopped_) {
      states_.reset();
      next_.clear();
      for (std::size_t index = 0; index < current_.size() && !stopped_; ++index) {
        const Label e = current_[index];
        if (!e.alive) continue;
        if (!bounded_below_best(e)) continue;
        if ((++nodes_ & 1023u) == 0 && budget_.exhausted(nodes_ + rs_.work())) {
          stopped_ = true;
          break;
        }
        const std::uint32_t aboard = e.picked & ~e.delivered;
        const bool full = base_load + bit_count(aboard) >= capacity_;
        int made = 0;  // children_ stored after all are made (their lookups overlap)
        for (std::size_t i = 0; i < jobs_.size() && !stopped_; ++i) {
          const std::uint32_t bit = 1u << i;
          if (e.delivered & bit) continue;
          const bool deliver = e.picked & bit;
          const LocalJob& lj = local_jobs_[i];
          if (!deliver && (full || lj.blocked_for_good || (lj.look_alikes & aboard))) continue;
          const StopRef stop{jobs_[i], deliver ? StopKind::kDelivery : StopKind::kPickup};
          Label child;
          if (!advance_label(e, stop, child)) continue;
          child.picked = e.picked | (deliver ? 0u : bit);
          child.delivered = e.delivered | (deliver ? bit : 0u);
          if (child.delivered == all_) {
            if (!found_ || better(child.cost, best_)) {
              best_ = child.cost;
              best_trail = e.trail;
              best_last = stop;
              found_ = true;
            }
            continue;
          }
          if (found_ && compare(child.cost, best_) >= 0) continue;
          Child& c = children_[made++];
          c.label = child;
          c.stop = stop;
          c.hash = StateTable::hash(key(child), child.loc);
          states_.prefetch(c.hash);
        }
        for (int k = 0; k < made && !stopped_; ++k)
          add_label(children_[k].label, children_[k].stop, e.trail, children_[k].hash);
      }
      if (beam_ && !stopped_) keep_beam();
      if (!stopped_) compact_trail(best_trail);
      current_.swap(next_);
    }
    if (best_trail == -2) return;  // nothing better than the incumbent
    best_route_.clear();
    best_route_.push_back(best_last);
    for (int k = best_trail; k >= 0; k = trail_[static_cast<std::size_t>(k)].parent)
      best_route_.push_back(trail_[static_cast<std::size_t>(k)].stop);
    std::reverse(best_route_.begin(), best_route_.end());
  }

  RouteSearch& rs_;
  const RouteSimulator& sim_;
  const std::vector<double>& shortest_;
  std::vector<int> jobs_;
  RouteState start_;
  const SearchBudget& budget_;
  std::size_t n_;
  int capacity_;
  std::uint32_t initially_picked_ = 0;
  std::uint32_t all_ = 0;
  std::vector<int> base_aboard_;
  LocalJob local_jobs_[kMaxJobsPerCourier] = {};
  std::vector<int> local_;   // location -> place id, -1 if not a place of this search
  std::vector<int> places_;  // place id -> location
  // Per place a, row a (places - 1 entries): the other places by shortest travel into a, nearest
  // first, as two flat arrays (a vector per place cost a pointer chase per leg charged).
  std::vector<double> nearest_leg_;
  std::vector<int> nearest_from_;
  std::vector<double> longest_leg_in_;
  bool masks_ok_ = true;  // at most 64 places (else no travel is charged)
  std::vector<int> by_deadline_;
  std::shared_ptr<const DeliverySequenceBound> sequence_;  // null: not built (job count)
  // For sequence_completion: per place the jobs picked up there, per job its pickup handover
  // and its delivery place as a place mask.
  std::uint32_t picks_at_[64] = {};
  double pick_dur_[kMaxJobsPerCourier] = {};
  std::uint64_t del_place_bit_[kMaxJobsPerCourier] = {};
  double sequence_value_ = 0.0;  // sequence_completion of the label lower_bound works on
  std::uint32_t pick_windowed_ = 0;  // local jobs whose pickup / delivery has presence windows
  std::uint32_t del_windowed_ = 0;
  // Scratch of lower_bound and delay_penalty (no allocation per label).
  double earliest_[kMaxJobsPerCourier] = {};
  double work_[kMaxJobsPerCourier] = {};
  int fill_[kMaxJobsPerCourier] = {};
  std::uint32_t touching_[64] = {};
  double due_[kMaxJobsPerCourier] = {};
  double slot_[kMaxJobsPerCourier] = {};
  double window_start_[2 * kMaxJobsPerCourier] = {};
  double latest_start_[2 * kMaxJobsPerCourier] = {};
  // The layers, the state table of the layer being built and every label's last step, in memory
  // kept by the thread from one search to the next: fresh vectors grew by doubling and every
  // solve touched their pages anew (page faults were 14 % of a loose 12-job search's time).
  struct Arena {
    std::vector<Label> current, next;
    StateTable states;
    std::vector<TrailStep> trail;
    std::vector<int> renumber;
    bool in_use = false;
  };
  // The thread's arena, or a private one while it is taken (searches do not nest today).
  static Arena* take_arena(std::unique_ptr<Arena>& own) {
    static thread_local Arena shared;
    if (!shared.in_use) return &shared;
    own = std::make_unique<Arena>();
    return own.get();
  }
  // Memory of a search too large to keep for the next one (a 16-job search can fill 2^20 labels).
  static constexpr std::size_t kArenaKeepBytes = std::size_t{32} << 20;
  template <typename T>
  static void trim(std::vector<T>& v) {
    v.clear();
    if (v.capacity() * sizeof(T) > kArenaKeepBytes) std::vector<T>().swap(v);
  }
  std::unique_ptr<Arena> own_arena_;
  Arena* arena_ = take_arena(own_arena_);
  std::vector<Label>& current_ = arena_->current;
  std::vector<Label>& next_ = arena_->next;
  StateTable& states_ = arena_->states;
  std::vector<TrailStep>& trail_ = arena_->trail;
  std::vector<int>& renumber_ = arena_->renumber;  // scratch of compact_trail
  std::vector<StopRef> best_route_;
  Objective best_;
  bool found_ = false;
  bool stopped_ = false;
  bool out_of_memory_ = false;
  std::uint64_t nodes_ = 0;
  // The children of the label being expanded, before they are stored.
  struct Child {
    Label label;
    StopRef stop;
    std::size_t hash = 0;
  };
  Child children_[kMaxJobsPerCourier];
  std::size_t beam_ = 0;                               // 0: exact
  std::vector<std::pair<Objective, int>> beam_order_;  // scratch of keep_beam
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
    const bool beam_finds_incumbent = couriers == 1 && rs.free_jobs().size() >= kBeamFromJobs;
    bool have_heuristic =
        large_search(rs, heuristic, beam_finds_incumbent ? 0 : kIncumbentRounds) &&
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
      Objective incumbent = use_heuristic ? heuristic_costs[c] : worst_objective();
      std::shared_ptr<const DeliverySequenceBound> sequence;
      if (jobs.size() >= kBeamFromJobs) {
        CourierSearch beam(rs, shortest, jobs, starts[c], problem.couriers[c].capacity, budget);
        sequence = beam.sequence_bound();
        beam.set_beam(kBeamWidth);
        beam.run(incumbent, use_heuristic ? &tail : nullptr);
        nodes += beam.nodes();
        if (beam.found() && (!use_heuristic || better(beam.best(), incumbent))) {
          tail = beam.best_route();
          incumbent = beam.best();
          use_heuristic = true;
        }
      }
      CourierSearch search(rs, shortest, jobs, starts[c], problem.couriers[c].capacity, budget,
                           sequence);
      const bool finished = search.run(incumbent, use_heuristic ? &tail : nullptr);
      complete = complete && finished;
      if (search.out_of_memory()) why = "more than 2^20 partial routes to keep";
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
