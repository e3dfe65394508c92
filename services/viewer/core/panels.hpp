#pragma once
// The viewer's side panels: the latest sample of what is not drawn on the map, as JSON by group
// and key (every field, as `autonomy topic echo` prints it: the DDS node walks the samples with
// their type information, tools/xtypes): spacecraft telemetry by spacecraft, spacecraft faults
// by fault id (ground truth), executive status by executive, the planner's latest plan by
// requester. Sent to the pages as {"type":"panels", GROUP: {KEY: sample}} when it changed, less
// often than the state frames (telemetry changes every tick).
#include <nlohmann/json.hpp>

#include <cstdint>
#include <map>
#include <string>

namespace autonomy::viewer {

class Panels {
 public:
  // The latest sample of key in group (any JSON: the page shows it as it is).
  void apply(const std::string& group, const std::string& key, nlohmann::json sample);
  // The sample of this key is gone (its writer disposed it or was lost).
  void erase(const std::string& group, const std::string& key);

  uint64_t version() const { return version_; }
  nlohmann::json frame() const;

 private:
  std::map<std::string, std::map<std::string, nlohmann::json>> groups_;
  uint64_t version_ = 0;
};

}  // namespace autonomy::viewer
