#include "services/courier/core/scheduler/delivery_sequence_bound.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace autonomy::courier::scheduling::detail {

DeliverySequenceBound::DeliverySequenceBound(const std::vector<int>& del_place,
                                             const std::vector<double>& del_dur,
                                             const std::vector<double>& travel, int places) {
  const std::string what = "DeliverySequenceBound: ";
  if (del_dur.size() != del_place.size())
    throw std::invalid_argument(what + std::to_string(del_place.size()) +
                                " delivery places but " + std::to_string(del_dur.size()) +
                                " handovers");
  if (del_place.size() > static_cast<std::size_t>(kMaxJobs))
    throw std::invalid_argument(what + std::to_string(del_place.size()) + " jobs, at most " +
                                std::to_string(kMaxJobs));
  if (places < 1 || travel.size() != static_cast<std::size_t>(places) * places)
    throw std::invalid_argument(what + "travel matrix of " + std::to_string(travel.size()) +
                                " entries for " + std::to_string(places) + " places");
  for (int p : del_place)
    if (p < 0 || p >= places)
      throw std::invalid_argument(what + "delivery place " + std::to_string(p) +
                                  " out of range (" + std::to_string(places) + " places)");
  places_ = static_cast<std::size_t>(places);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // Detours: u == w is a visit and back (the leg twice); unreachable pairs say nothing.
  detour_.assign(places_, 0.0);
  for (std::size_t v = 0; v < places_; ++v) {
    double least = kInf;
    for (std::size_t u = 0; u < places_; ++u) {
      const double uv = travel[u * places_ + v];
      if (u == v || !(uv < kInf)) continue;
      for (std::size_t w = 0; w < places_; ++w) {
        const double vw = travel[v * places_ + w];
        if (w == v || !(vw < kInf)) continue;
        least = std::min(least, uv + vw - (u == w ? 0.0 : travel[u * places_ + w]));
      }
    }
    if (least < kInf) detour_[v] = std::max(0.0, least);
  }
  // Legs into each place, contiguous (the inner loop runs over the places left from).
  std::vector<double> into(travel.size());
  for (std::size_t a = 0; a < places_; ++a)
    for (std::size_t b = 0; b < places_; ++b) into[b * places_ + a] = travel[a * places_ + b];
  const std::size_t subsets = std::size_t{1} << del_place.size();
  table_.assign(subsets * places_, 0.0);
  // Subsets in increasing order: U without j comes before U.
  for (std::size_t u = 1; u < subsets; ++u) {
    const double weight = static_cast<double>(__builtin_popcountll(u));
    double* row = &table_[u * places_];
    std::fill(row, row + places_, kInf);
    for (std::size_t rest = u; rest; rest &= rest - 1) {
      const int j = __builtin_ctzll(rest);
      const std::size_t to = static_cast<std::size_t>(del_place[static_cast<std::size_t>(j)]);
      // The rest of the order, from j's delivery place, and j's handover at weight |U|.
      const double after = table_[(u & ~(std::size_t{1} << j)) * places_ + to] +
                           weight * del_dur[static_cast<std::size_t>(j)];
      const double* legs = &into[to * places_];
      for (std::size_t p = 0; p < places_; ++p) {
        const double leg = legs[p];
        if (leg < kInf)
          row[p] = std::min(row[p], weight * leg + after);
      }
    }
  }
}

}  // namespace autonomy::courier::scheduling::detail
