#include "simulator/radio/connectivity.hpp"

#include <algorithm>
#include <deque>

namespace autonomy::sim::radio {

namespace {
constexpr size_t kNone = static_cast<size_t>(-1);
}

Connectivity::Connectivity(const LinkTable& links)
    : neighbours_(links.size()), component_of_(links.size(), kNone) {
  const size_t n = links.size();
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = i + 1; j < n; ++j) {
      if (links.connected(i, j)) {
        neighbours_[i].push_back(j);
        neighbours_[j].push_back(i);
      }
    }
  }
  find_components();
}

Connectivity::Connectivity(const NearLinkTable& links)
    : neighbours_(links.size()), component_of_(links.size(), kNone) {
  for (const NearLink& l : links.links()) {
    neighbours_[l.i].push_back(l.j);
    neighbours_[l.j].push_back(l.i);
  }
  find_components();
}

void Connectivity::find_components() {
  const size_t n = neighbours_.size();
  for (auto& list : neighbours_) std::sort(list.begin(), list.end());
  std::vector<size_t> stack;
  for (size_t s = 0; s < n; ++s) {
    if (component_of_[s] != kNone) continue;
    const size_t c = components_.size();
    components_.emplace_back();
    component_of_[s] = c;
    stack.assign(1, s);
    while (!stack.empty()) {
      const size_t u = stack.back();
      stack.pop_back();
      components_[c].push_back(u);
      for (size_t w : neighbours_[u]) {
        if (component_of_[w] == kNone) {
          component_of_[w] = c;
          stack.push_back(w);
        }
      }
    }
    std::sort(components_[c].begin(), components_[c].end());
  }
}

std::vector<int> Connectivity::hop_counts(size_t from) const {
  std::vector<int> hops(size(), -1);
  std::deque<size_t> queue{from};
  hops[from] = 0;
  while (!queue.empty()) {
    const size_t u = queue.front();
    queue.pop_front();
    for (size_t w : neighbours_[u]) {
      if (hops[w] < 0) {
        hops[w] = hops[u] + 1;
        queue.push_back(w);
      }
    }
  }
  return hops;
}

std::optional<std::vector<size_t>> Connectivity::route(size_t from, size_t to) const {
  if (!reachable(from, to)) return std::nullopt;
  std::vector<size_t> parent(size(), kNone);
  std::deque<size_t> queue{from};
  parent[from] = from;
  while (!queue.empty() && parent[to] == kNone) {
    const size_t u = queue.front();
    queue.pop_front();
    for (size_t w : neighbours_[u]) {
      if (parent[w] == kNone) {
        parent[w] = u;
        queue.push_back(w);
      }
    }
  }
  std::vector<size_t> path{to};
  while (path.back() != from) path.push_back(parent[path.back()]);
  std::reverse(path.begin(), path.end());
  return path;
}

std::vector<LinkQuality> route_links(const LinkTable& links, const std::vector<size_t>& route) {
  std::vector<LinkQuality> hops;
  for (size_t k = 0; k + 1 < route.size(); ++k) hops.push_back(links.at(route[k], route[k + 1]));
  return hops;
}

std::vector<LinkQuality> route_links(const NearLinkTable& links, const std::vector<size_t>& route) {
  std::vector<LinkQuality> hops;
  for (size_t k = 0; k + 1 < route.size(); ++k) {
    const LinkQuality* hop = links.find(route[k], route[k + 1]);
    // A route only uses connected links, which the table holds; a stale route gets a dead hop.
    hops.push_back(hop != nullptr ? *hop : LinkQuality{});
  }
  return hops;
}

}  // namespace autonomy::sim::radio
