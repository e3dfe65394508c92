#pragma once
// What one robot knows about the doors of its map, from its own door sightings: a door it saw
// closed blocks its doorway in the robot's plans; a door it has not seen, or saw open, is assumed
// open (the courier robots' optimism: plan through doors, find out on the way). A closed-door
// belief is forgotten after `memory_s` without a sighting, so a door that reopened out of sight
// is tried again instead of being avoided for ever.
//
// An open door's leaf is an obstacle too (a robot beside it must plan around it, and a range hit on
// it is the map's, not something unexpected): where the map says the leaf stands when open
// (Doorway::open_angle), or at the angle this robot last saw it open. A doorway whose map entry
// says nothing of its leaf (open_angle 0) gets no leaf.
#include "common/geometry/geometry.hpp"
#include "services/behavior/core/world_map.hpp"

#include <map>
#include <string>
#include <vector>

namespace autonomy::behavior {

struct DoorKnowledgeSettings {
  double closed_below_rad = 0.35;  // an opening narrower than this (about 20 degrees) is closed
  double open_above_rad = 0.6;     // > closed_below_rad: a closed door counts as open again only
                                   // this wide, so a noisy estimate near the threshold does not
                                   // make the robot replan every tick
  double memory_s = 120.0;         // > 0: how long a closed door is believed closed unseen
  double thickness_m = 0.2;        // > 0: the doorway blocked as a slab this thick
  // An open leaf as a slab this thick along it (the simulator's leaf: 0.05 m; thicker closes the
  // 1 m pocket between a leaf and the room's wall to a 0.6 m robot), reaching this far past its
  // tip: a path follower cuts the corner round the point-like tip (without the margin rhino touched
  // a leaf coming round its tip on an OMPL path: ompl_go_to_test).
  double leaf_thickness_m = 0.05;  // > 0
  double leaf_tip_margin_m = 0.1;  // >= 0
  double leaf_moved_rad = 0.3;     // > 0: a leaf seen this far from where it is believed to stand
                                   // moves there (well above sighting noise, so no replan a tick)
};

struct DoorSighting {
  std::string door_id;
  double angle_estimate = 0.0;  // rad, 0 = closed
};

class DoorKnowledge {
 public:
  // Throws std::invalid_argument on non-finite or non-positive settings.
  explicit DoorKnowledge(DoorKnowledgeSettings settings = {});

  // Takes the sightings of one tick (ids not on the map are ignored) and lets beliefs older than
  // memory_s lapse. Returns true when what plans see changed: the set of closed doors, or where
  // an open leaf stands.
  bool update(const std::vector<DoorSighting>& sightings, double now_s, const WorldMap& map);

  // Ids of the doors believed closed, sorted.
  std::vector<std::string> closed() const;
  bool believed_closed(const std::string& id) const { return closed_since_.count(id) != 0; }

  // `map` with a slab across the doorway of every door believed closed and a slab along the leaf
  // of every door believed open (polygons named "door ID" and "door ID leaf"), so a grid built from
  // it plans around closed doors and beside open leaves.
  WorldMap apply(const WorldMap& map) const;

  // The opening angle (rad, >= 0) at which the leaf of door `d` is believed to stand while open.
  double open_leaf_angle(const Doorway& d) const;

 private:
  DoorKnowledgeSettings settings_;
  std::map<std::string, double> closed_since_;  // id -> time of the last sighting closed
  std::map<std::string, double> leaf_angle_;    // id -> opening believed (seen open), rad
};

// "door d1 closed", "doors d1, d2 closed": for reasons in goal statuses and logs.
std::string describe_closed_doors(const std::vector<std::string>& ids);

}  // namespace autonomy::behavior
