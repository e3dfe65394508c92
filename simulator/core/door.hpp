#pragma once
// Doors: a leaf of `width` hinged at one side of a doorway, at an opening angle between 0
// (closed: the leaf lies across the doorway) and max_angle (open). The leaf is an obstacle at
// every angle: it blocks motion (a segment of half-thickness kDoorLeafHalfThicknessM) and line
// of sight (the segment itself); a closed door therefore seals its doorway, an open one stands
// against the room's side of the doorway.
//
// How a door changes: a DoorSchedule, pure and stepping with simulated time, says which angle the
// door is to have; the World moves the leaf there unless a robot stands in the sector the leaf
// would sweep (then it waits and tries again every step: a door never passes through a robot).
//   script  fixed (time, angle) events, as in the courier paper's run (A-120 closes, reopens);
//   random  a two-state Markov process: an open door closes at close_rate_hz, a closed one opens
//           at open_rate_hz (exponential dwell times from a seeded Rng).
#include "common/geometry/geometry.hpp"
#include "simulator/core/random.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::sim {

inline constexpr double kDoorLeafHalfThicknessM = 0.025;

// Which way the leaf turns from closed to open, seen from above.
enum class DoorSwing { CounterClockwise, Clockwise };

struct DoorScriptEvent {
  double time_s = 0.0;  // the door takes `angle` at the first step ending at or after time_s
  double angle = 0.0;   // rad, 0 .. max_angle
};

struct DoorRandomProcess {
  double close_rate_hz = 0.0;  // open -> closed transitions per second while open (0: never)
  double open_rate_hz = 0.0;   // closed -> open transitions per second while closed (0: never)
  double open_angle = M_PI / 2;  // the angle an opening door takes
};

struct DoorScheduleSpec {
  enum class Kind { Fixed, Script, Random };
  Kind kind = Kind::Fixed;  // Fixed: changes only through World::set_door
  std::vector<DoorScriptEvent> script;  // Script: times non-decreasing
  DoorRandomProcess random;             // Random
};

// The leaf as a segment from the hinge to its free end.
struct DoorLeaf {
  geometry::Vec2 hinge;
  geometry::Vec2 tip;
};

struct DoorSpec {
  std::string id;
  geometry::Vec2 position;     // centre of the doorway
  double width = 1.0;          // m, doorway and leaf length
  double heading = 0.0;        // rad, direction of the doorway line from the hinge to the latch
  DoorSwing swing = DoorSwing::CounterClockwise;
  double max_angle = M_PI / 2;  // rad, in (0, pi]
  double angle = M_PI / 2;      // rad, the opening angle at the start
  std::array<std::string, 2> rooms;  // the rooms it connects (names; informative for the core)
  DoorScheduleSpec schedule;

  geometry::Vec2 hinge() const;
  DoorLeaf leaf(double opening_angle) const;
};

// Why a door spec cannot be used (first problem found), or nothing.
std::optional<std::string> door_problem(const DoorSpec& door);

// The disc overlaps the leaf (inflated by its half-thickness).
bool disc_overlaps_leaf(const DoorLeaf& leaf, const geometry::Vec2& center, double radius);

// The disc overlaps what the leaf sweeps when it turns from angle `from` to angle `to`.
bool disc_in_sweep(const DoorSpec& door, double from, double to, const geometry::Vec2& center,
                   double radius);

class DoorSchedule {
 public:
  DoorSchedule() = default;  // Fixed
  // `initial_angle` tells a random process whether the door starts open (> 0) or closed.
  DoorSchedule(DoorScheduleSpec spec, double initial_angle, Rng rng);

  // Moves the schedule's time to `to_s` (non-decreasing) and returns the angle the door is to
  // have if any event happened in (previous time, to_s]; when several did, the last one wins.
  std::optional<double> advance(double to_s);

 private:
  void draw_next(double from_s);

  DoorScheduleSpec spec_;
  double now_s_ = 0.0;
  std::size_t next_event_ = 0;  // Script: first event not yet applied
  bool open_ = true;            // Random: current state
  double next_change_s_ = 0.0;  // Random: when the state changes next (inf: never)
  Rng rng_;
};

}  // namespace autonomy::sim

namespace autonomy::sim {

// A door as the World reports it.
struct DoorStatus {
  std::string id;
  double angle = 0.0;         // rad, current opening angle
  double target_angle = 0.0;  // rad, the angle its schedule or set_door asked for
  bool blocked = false;       // target_angle != angle because a robot is in the leaf's way
  DoorLeaf leaf;

  bool closed() const { return angle <= 0.0; }
};

}  // namespace autonomy::sim
