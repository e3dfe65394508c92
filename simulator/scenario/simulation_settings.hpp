#pragma once
// How the simulator runs its clock, as resolved from a scenario file (defaults applied).
#include <cstdint>

namespace autonomy::sim {

enum class ClockMode {
  Lockstep,  // a tick advances when every registered participant acknowledged it
  Paced,     // ticks follow wall time times `warp`
};

struct SimulationSettings {
  ClockMode mode = ClockMode::Lockstep;
  double step_s = 0.05;        // simulated seconds per tick
  double warp = 1.0;           // paced mode: simulated seconds per wall second
  std::uint64_t seed = 0;      // seeds every random choice of the run
  double ack_timeout_s = 2.0;  // lockstep: wall seconds before a silent participant is dropped
  // The command timeout is world behaviour and lives in WorldSpec::command_timeout_s.
};

}  // namespace autonomy::sim
