#include "simulator/radio/link_changes.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <tuple>

namespace autonomy::sim::radio {

LinkChangeFilter::LinkChangeFilter(double signal_change_db) : signal_change_db_(signal_change_db) {
  if (!std::isfinite(signal_change_db) || signal_change_db < 0.0)
    throw std::invalid_argument("link signal change threshold must be finite and >= 0");
}

std::vector<LinkSample> LinkChangeFilter::update(const std::vector<std::string>& ids, const NearLinkTable& table,
                                                 const std::function<LinkQuality(size_t, size_t)>& exact_link) {
  ++updates_;
  std::vector<LinkSample> out;
  for (const NearLink& l : table.links()) {
    auto key = std::make_pair(ids[l.i], ids[l.j]);
    const auto it = last_.find(key);
    if (it == last_.end()) {
      last_.emplace(key, LastSample{l.quality.signal_dbm, updates_});
      out.push_back({std::move(key.first), std::move(key.second), l.quality, false});
      continue;
    }
    it->second.seen = updates_;
    if (std::abs(it->second.signal_dbm - l.quality.signal_dbm) <= signal_change_db_) continue;
    it->second.signal_dbm = l.quality.signal_dbm;
    out.push_back({key.first, key.second, l.quality, false});
  }
  const auto index_of = [&ids](const std::string& id) -> std::optional<size_t> {
    const auto it = std::lower_bound(ids.begin(), ids.end(), id);
    if (it == ids.end() || *it != id) return std::nullopt;
    return static_cast<size_t>(it - ids.begin());
  };
  for (auto it = last_.begin(); it != last_.end();) {
    if (it->second.seen == updates_) {
      ++it;
      continue;
    }
    const auto a = index_of(it->first.first);
    const auto b = index_of(it->first.second);
    if (a && b) out.push_back({it->first.first, it->first.second, exact_link(*a, *b), true});
    it = last_.erase(it);
  }
  std::sort(out.begin(), out.end(), [](const LinkSample& x, const LinkSample& y) {
    return std::tie(x.robot_a, x.robot_b) < std::tie(y.robot_a, y.robot_b);
  });
  return out;
}

}  // namespace autonomy::sim::radio
