#pragma once
// One world per domain. Before a simulator publishes anything of its world it listens on its
// domain for a while: a clock it hears, or a heartbeat of another simulator that runs a world,
// means a world already runs there, and this simulator refuses to start, naming the other one
// (host, pid, scenario). Two simulators side by side would otherwise each drive their robots and
// every service would follow whichever clock came last (issue 22).
#include "common/dds/participant.hpp"

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

namespace autonomy::sim {

struct OtherWorld {
  uint64_t world_id = 0;
  std::string host;   // "" when only its clock was heard (no simulator heartbeat names it)
  int32_t pid = 0;
  std::string scenario;
};

// "another world runs on DDS domain 3: simulator on host h, pid 123, scenario s.pbtxt (world 99)".
std::string describe(const OtherWorld& w, uint32_t domain);

// Listens for `window` and returns the world heard, if any. Heartbeats of this very process are
// not another world.
std::optional<OtherWorld> find_other_world(const dds::Participant& participant, std::chrono::milliseconds window);

// A random non-zero id for a new world: 64 bits from the system's entropy source, so that two
// simulators started at the same moment on two hosts do not pick the same one.
uint64_t new_world_id();

}  // namespace autonomy::sim
