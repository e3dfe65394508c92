#include "services/courier/core/knowledge/destination_frequencies.hpp"

#include "services/courier/core/knowledge/name_lookup.hpp"

namespace autonomy::courier {

void DestinationFrequencies::record(const std::string& source, const std::string& kind,
                                    const std::string& destination) {
  ++counts_[{lower_case(source), lower_case(kind)}][destination];
  ++total_;
}

std::optional<FrequentDestination> DestinationFrequencies::most_frequent_destination(
    const std::string& source, const std::string& kind) const {
  const std::string who = lower_case(source), what = lower_case(kind);
  std::map<std::string, int> merged;
  for (const auto& [key, destinations] : counts_) {
    if (key.first != who || (!what.empty() && key.second != what)) continue;
    for (const auto& [place, n] : destinations) merged[place] += n;
  }
  std::optional<FrequentDestination> best;
  int total = 0;
  for (const auto& [place, n] : merged) {
    total += n;
    if (!best || n > best->count) best = FrequentDestination{place, n, 0};
  }
  if (best) best->total = total;
  return best;
}

}  // namespace autonomy::courier
