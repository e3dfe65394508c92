#include "services/viewer/core/latest_samples.hpp"

#include "tools/xtypes/cdr_json.hpp"

namespace autonomy::viewer {

std::string panel_key(const nlohmann::ordered_json& key) {
  std::string out;
  for (const auto& [name, value] : key.items())
    out += (out.empty() ? "" : "/") + (value.is_string() ? value.get<std::string>() : value.dump());
  return out;
}

LatestSamples::LatestSamples(xtypes::TypePtr type, std::string group) : type_(std::move(type)), group_(std::move(group)) {}

void LatestSamples::add(uint64_t instance, bool alive, std::string cdr) {
  Instance& i = instances_[instance];
  if (!alive) {
    i.ended = true;
    i.changed = false;
    i.cdr.clear();
    return;
  }
  i.ended = false;
  i.changed = true;
  i.cdr = std::move(cdr);
}

std::vector<std::string> LatestSamples::flush(Panels& panels) {
  std::vector<std::string> errors;
  for (auto it = instances_.begin(); it != instances_.end();) {
    Instance& i = it->second;
    if (i.ended) {
      if (!i.key.empty()) panels.erase(group_, i.key);
      it = instances_.erase(it);
      continue;
    }
    if (i.changed) {
      i.changed = false;
      ++walked_;
      try {
        xtypes::Json sample = xtypes::cdr_to_json(*type_, i.cdr);
        // A key member changed under one instance handle cannot happen in DDS; the key is
        // computed again anyway, so that a panel never shows under a stale name.
        const std::string key = panel_key(xtypes::key_of(*type_, sample));
        if (!i.key.empty() && i.key != key) panels.erase(group_, i.key);
        i.key = key;
        panels.apply(group_, key, nlohmann::json(std::move(sample)));
      } catch (const xtypes::CdrError& e) {
        errors.push_back(e.what());
      }
      i.cdr.clear();
      i.cdr.shrink_to_fit();
    }
    ++it;
  }
  return errors;
}

}  // namespace autonomy::viewer
