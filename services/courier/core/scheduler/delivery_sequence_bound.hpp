#pragma once
// Internal to the exact engine: a lower bound on the completion time still to come that knows
// which jobs are left and in which order their deliveries can come, tabulated once per search
// (the exact engine adds the pickups per partial route: exact_engine.cpp, sequence_completion).
//
// Look at a route from one delivery to the next. It travels at least the shortest path between
// the two delivery places, plus, for every other place it visits in between (pickups), that
// place's detour: the least sp(u, v) + sp(v, w) - sp(u, w) over places u, w other than v. (Cut
// the stretch short to its distinct places in between, in order, none of them an end: no
// longer, by the triangle inequality; then take them out one at a time, each from between two
// places other than itself.) Each leg and handover counts once for each job still undelivered
// when it is spent (sum of completion times). So f(U, p), the cheapest order of the deliveries
// of the jobs U from place p priced that way from time 0 (legs between delivery places and
// delivery handovers only), plus each pickup's handover and share of its place's detour (only
// for places that are neither a delivery place left nor where the courier stands), each at the
// weight of a distinct position no later than its own delivery's, is a lower bound on the
// completion still to come; waiting, capacity and look-alikes only add. In the loose offices of
// the benchmark a room's detour is its two door legs (about 25 s), which the bound of shares of
// nearest legs (exact_engine.cpp) does not see between two deliveries.
#include <cstdint>
#include <vector>

namespace autonomy::courier::scheduling::detail {

class DeliverySequenceBound {
 public:
  // Jobs beyond which no table is built (2^jobs x places doubles: 8.9 MB at 16 jobs and 17
  // places).
  static constexpr int kMaxJobs = 16;

  // `del_place[i]` / `del_dur[i]`: job i's delivery place (0..places-1) and handover;
  // `travel[a * places + b]`: shortest travel from place a to place b (+inf: no route).
  // Throws std::invalid_argument on sizes that do not match, more than kMaxJobs jobs or a place
  // out of range.
  DeliverySequenceBound(const std::vector<int>& del_place, const std::vector<double>& del_dur,
                        const std::vector<double>& travel, int places);

  // f(undelivered, place) (bit i = job i); +inf when a delivery place cannot be reached.
  double cost(std::uint32_t undelivered, int place) const {
    return table_[static_cast<std::size_t>(undelivered) * places_ +
                  static_cast<std::size_t>(place)];
  }
  // The least extra travel of a visit to `place` between two other places (0 when it can lie on
  // a shortest path between two of them).
  double detour(int place) const { return detour_[static_cast<std::size_t>(place)]; }

 private:
  std::size_t places_ = 0;
  std::vector<double> table_;  // table_[U * places + p] = f(U, p)
  std::vector<double> detour_;
};

}  // namespace autonomy::courier::scheduling::detail
