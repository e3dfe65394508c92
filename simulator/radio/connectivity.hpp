#pragma once
// Who can reach whom over connected links, possibly through other robots (multi-hop relaying):
// connected components, "the whole team is one network" (the paper's "single complete mobile ad
// hoc network"), hop counts and fewest-hop routes.
//
// Routes are breadth-first over neighbours in index order, so among routes with the fewest hops
// the one through the lowest indices is chosen: deterministic for a given table.
#include "simulator/radio/near_links.hpp"
#include "simulator/radio/radio_model.hpp"

#include <cstddef>
#include <optional>
#include <vector>

namespace autonomy::sim::radio {

class Connectivity {
 public:
  explicit Connectivity(const LinkTable& links);
  // The same from the connected links alone (equal results for the same connected pairs).
  explicit Connectivity(const NearLinkTable& links);

  size_t size() const { return neighbours_.size(); }
  // Members of each component in increasing order; components ordered by their first member.
  const std::vector<std::vector<size_t>>& components() const { return components_; }
  size_t component_of(size_t i) const { return component_of_[i]; }
  bool reachable(size_t from, size_t to) const { return component_of_[from] == component_of_[to]; }
  // One component holding every radio (true for a team of 0 or 1).
  bool fully_connected() const { return components_.size() <= 1; }
  // Radios with a connected direct link to i, increasing.
  const std::vector<size_t>& neighbours(size_t i) const { return neighbours_[i]; }

  // Hops from `from` to every radio; -1 where unreachable, 0 for `from` itself.
  std::vector<int> hop_counts(size_t from) const;
  // from, relays..., to with the fewest hops; {from} when from == to; nothing when unreachable.
  std::optional<std::vector<size_t>> route(size_t from, size_t to) const;

 private:
  void find_components();  // from neighbours_

  std::vector<std::vector<size_t>> neighbours_;
  std::vector<std::vector<size_t>> components_;
  std::vector<size_t> component_of_;
};

// The links along `route` (hop k is route[k] - route[k + 1]).
std::vector<LinkQuality> route_links(const LinkTable& links, const std::vector<size_t>& route);
std::vector<LinkQuality> route_links(const NearLinkTable& links, const std::vector<size_t>& route);

}  // namespace autonomy::sim::radio
