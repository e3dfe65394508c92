#pragma once
// Where things from a source usually go, learned from completed deliveries. The paper's courier
// completes "pick up the letter from Wolfram and deliver it" from what it has seen before: the
// destination most often used for letters from Wolfram. A source is a person's name or a place
// name (when nobody sits at the pickup place); destinations are place names.
#include <map>
#include <optional>
#include <string>
#include <utility>

namespace autonomy::courier {

struct FrequentDestination {
  std::string destination;  // a place name
  int count = 0;            // deliveries there
  int total = 0;            // deliveries counted for the query
};

class DestinationFrequencies {
 public:
  // One completed delivery of an object of `kind` from `source` to `destination`. Names are kept as
  // given; lookups compare them case-insensitively.
  void record(const std::string& source, const std::string& kind, const std::string& destination);

  // The destination used most often for objects of `kind` from `source`; an empty kind counts
  // every kind. Ties go to the destination name that sorts first, so answers are repeatable.
  // Nothing when no delivery from source (of that kind) was recorded.
  std::optional<FrequentDestination> most_frequent_destination(const std::string& source,
                                                               const std::string& kind) const;

  // Deliveries recorded, over all sources and kinds.
  int total() const { return total_; }

 private:
  // (lower-cased source, lower-cased kind) -> destination -> count
  std::map<std::pair<std::string, std::string>, std::map<std::string, int>> counts_;
  int total_ = 0;
};

}  // namespace autonomy::courier
