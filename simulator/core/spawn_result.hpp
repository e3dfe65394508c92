#pragma once
// The verdict on a request to put a robot into the world.
#include <string>

namespace autonomy::sim {

struct [[nodiscard]] SpawnResult {
  bool accepted = false;
  // Accepted without change: the robot was already there and no pose was asked for, which is
  // what a restarted controller re-attaching to its robot looks like.
  bool already_present = false;
  std::string reason;  // why it was rejected; empty when accepted

  static SpawnResult spawned() { return {true, false, {}}; }
  static SpawnResult reattached() { return {true, true, {}}; }
  static SpawnResult reject(std::string why) { return {false, false, std::move(why)}; }
};

}  // namespace autonomy::sim
