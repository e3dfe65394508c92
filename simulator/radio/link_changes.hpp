#pragma once
// Which RadioLink samples the simulator writes, from the connected links of each update
// (NearLinkTable). The rule, per robot pair (a < b):
//   - a pair that becomes connected (first time, or again after it was lost) gets a sample;
//   - a connected pair whose signal moved by more than signal_change_db (1 dB by default: about
//     the step of 802.11 RSSI readings, and a tenth of the delivery model's good margin) since
//     its last sample gets one;
//   - a pair that was connected at its last sample and is not now (walls between, or out of the
//     model's range) gets exactly one sample with connected = false and its exact signal; after
//     that it has no sample until it connects again.
// So a reader that keeps the last sample of each pair holds the connected links, and a pair it
// never heard of, or whose last sample says not connected, has no link. Pairs that never connect
// cost nothing, whatever the team size. A pair whose robot left the world is forgotten without a
// sample (its robot has no links to keep).
#include "simulator/radio/near_links.hpp"

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace autonomy::sim::radio {

constexpr double kDefaultLinkSignalChangeDb = 1.0;

struct LinkSample {
  std::string robot_a;  // robot_a < robot_b
  std::string robot_b;
  LinkQuality quality;
  bool lost = false;  // the one sample of a pair that was connected and is not now
};

class LinkChangeFilter {
 public:
  // signal_change_db must be >= 0 and finite (std::invalid_argument otherwise).
  explicit LinkChangeFilter(double signal_change_db = kDefaultLinkSignalChangeDb);

  // The samples to write for this update, ordered by (robot_a, robot_b). `ids` are the table's
  // radios by index, increasing. `exact_link(i, j)` is the full link of a pair the table does not
  // hold (for its "lost" sample).
  std::vector<LinkSample> update(const std::vector<std::string>& ids, const NearLinkTable& table,
                                 const std::function<LinkQuality(size_t, size_t)>& exact_link);

  // Pairs whose last sample said connected.
  size_t connected_pairs() const { return last_.size(); }

 private:
  struct LastSample {
    double signal_dbm = 0.0;
    uint64_t seen = 0;  // update number that last found the pair connected
  };
  double signal_change_db_;
  uint64_t updates_ = 0;
  std::map<std::pair<std::string, std::string>, LastSample> last_;
};

}  // namespace autonomy::sim::radio
