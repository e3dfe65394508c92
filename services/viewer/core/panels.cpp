#include "services/viewer/core/panels.hpp"

namespace autonomy::viewer {

void Panels::apply(const std::string& group, const std::string& key, nlohmann::json sample) {
  groups_[group][key] = std::move(sample);
  ++version_;
}

void Panels::erase(const std::string& group, const std::string& key) {
  const auto g = groups_.find(group);
  if (g == groups_.end() || g->second.erase(key) == 0) return;
  ++version_;
}

nlohmann::json Panels::frame() const {
  nlohmann::json out = {{"type", "panels"}};
  for (const auto& [group, samples] : groups_) {
    nlohmann::json g = nlohmann::json::object();
    for (const auto& [key, value] : samples) g[key] = value;
    out[group] = std::move(g);
  }
  return out;
}

}  // namespace autonomy::viewer
