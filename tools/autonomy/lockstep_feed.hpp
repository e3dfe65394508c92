#pragma once
// Lockstep drops and rejoins as they happen, from the simulator's status samples
// (autonomy/sim/status carries the last 32 changes, numbered per simulator run): each change once,
// in order, whichever status samples a reader happened to get. `autonomy node watch` prints them
// beside the liveliness events.
#include <cstdint>
#include <string>
#include <vector>

#include "common/msg/simulation.hpp"

namespace autonomy::tools {

class LockstepFeed {
 public:
  // The changes of `status` not returned before, oldest first. A status whose numbers restart
  // (a new simulator run) starts afresh. `missed` gets how many changes fell out of the status's
  // list before this reader saw them.
  std::vector<msg::LockstepChange> take(const msg::SimulatorStatus& status, uint64_t* missed = nullptr);

 private:
  uint64_t last_ = 0;  // the number of the last change returned
};

// One line for people: "lockstep_dropped behavior/r2 at tick 1870: REASON" (or lockstep_rejoined).
std::string describe(const msg::LockstepChange& change);
const char* event_name(const msg::LockstepChange& change);

}  // namespace autonomy::tools
