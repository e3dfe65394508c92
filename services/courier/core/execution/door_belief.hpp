#pragma once
// The courier's policy of watching doors (the paper: "whenever you pass a door estimate the opening
// angle"): every door sighting of the courier's own robots is folded into one belief per door. A
// door never seen is assumed open (the schedule's optimism); a belief flips only past a hysteresis
// band, so a noisy estimate near the threshold does not reschedule every tick.
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::courier {

struct DoorBeliefSettings {
  double closed_below_rad = 0.35;  // about 20 degrees
  double open_above_rad = 0.6;     // > closed_below_rad
};

enum class DoorChange { none, closed, opened };

struct DoorView {
  double angle_rad = 0.0;
  bool open = true;
  double seen_at_s = 0.0;  // seconds of the day of the last sighting
  std::string seen_by;     // robot
  bool open_assumed = false;  // open because a closed sighting expired, not because it was seen open
};

class DoorBelief {
 public:
  // Throws std::invalid_argument unless 0 <= closed_below_rad < open_above_rad (finite).
  explicit DoorBelief(DoorBeliefSettings settings = {});

  // One sighting; says whether the belief flipped. Non-finite angles are ignored.
  DoorChange observe(const std::string& door_id, double angle_rad, double now_s, const std::string& robot);

  bool believed_open(const std::string& door_id) const;
  // A door believed closed and not seen since `before_s` is assumed open again (returned), as a
  // door never seen is: a closed door says little about the same door minutes later.
  std::vector<std::string> expire_closed(double before_s);
  std::optional<DoorView> view(const std::string& door_id) const;
  const std::map<std::string, DoorView>& doors() const { return doors_; }

 private:
  DoorBeliefSettings settings_;
  std::map<std::string, DoorView> doors_;
};

}  // namespace autonomy::courier
