#pragma once
// A side panel's topic as the panels need it: the latest sample of each DDS instance, kept as
// bytes as samples arrive and walked into JSON (tools/xtypes, the same JSON `autonomy topic echo`
// prints) only when the panels are about to be sent, at most twice a second. Spacecraft
// telemetry comes at the world's tick rate (thousands of samples a second in a lockstep day):
// walking each one as it came cost the viewer about a quarter of a core in the DS1 demo, for
// panels that show one sample in hundreds.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "services/viewer/core/panels.hpp"
#include "tools/xtypes/type_tree.hpp"

namespace autonomy::viewer {

class LatestSamples {
 public:
  // `group`: the panels' group the samples go to; its keys are the samples' key members.
  LatestSamples(xtypes::TypePtr type, std::string group);

  // A sample taken from the reader, in order. `alive` false: the instance was disposed or lost
  // its writers (no data); `cdr` empty then.
  void add(uint64_t instance, bool alive, std::string cdr);
  // Walks the latest bytes of every instance changed since the last call into `panels`, and
  // takes the ended ones out. Returns one text per sample whose bytes did not fit the type (that
  // instance's panel keeps its previous sample).
  std::vector<std::string> flush(Panels& panels);

  uint64_t walked() const { return walked_; }  // samples walked so far (for tests and benches)

 private:
  struct Instance {
    std::string cdr;  // the latest bytes not yet walked
    bool changed = false;
    bool ended = false;
    std::string key;  // the panel key it was shown under ("" before its first walk)
  };
  xtypes::TypePtr type_;
  std::string group_;
  std::map<uint64_t, Instance> instances_;
  uint64_t walked_ = 0;
};

// A panel key from a sample's key members: their values joined by "/" (strings unquoted).
std::string panel_key(const nlohmann::ordered_json& key);

}  // namespace autonomy::viewer
