#include "services/viewer/core/panels.hpp"

#include "tools/json/msg_json.hpp"

namespace autonomy::viewer {

void Panels::set(const std::string& group, const std::string& key, nlohmann::json value) {
  groups_[group][key] = std::move(value);
  ++version_;
}

void Panels::erase(const std::string& group, const std::string& key) {
  const auto g = groups_.find(group);
  if (g == groups_.end() || g->second.erase(key) == 0) return;
  ++version_;
}

void Panels::apply(const msg::SpacecraftTelemetry& telemetry) {
  set("spacecraft", telemetry.spacecraft, ::autonomy::json::to_json(telemetry));
}

void Panels::apply(const msg::SpacecraftFaultState& fault) { set("faults", fault.fault_id, ::autonomy::json::to_json(fault)); }

void Panels::apply(const msg::ExecutiveStatus& status) { set("executive", status.executive, ::autonomy::json::to_json(status)); }

void Panels::apply(const msg::LatestPlan& plan) { set("plans", plan.requester, ::autonomy::json::to_json(plan)); }

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
