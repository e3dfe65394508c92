#pragma once
// The conflict rule of the fleet (docs/traffic.md argues it free of deadlock and livelock): a robot
// drives into a narrow passage only when it holds the passage's reservation, and waits outside it
// otherwise. Among the robots that claim one passage the order is total:
//
//   1. a robot whose centre is inside the passage's box (it is there: it drives on, never waits);
//   2. else the earlier request time (a request keeps its time while the robot keeps wanting the
//      same passage, so waiting never loses a robot its place);
//   3. ties by robot id.
//
// A robot waits only outside every passage box (the wait starts `approach_m` before the box), so
// it never holds one passage while waiting for another. A request is granted once it has stood
// `grant_delay_s` with nobody ahead of it, so that two robots asking at the same moment see each
// other's requests before either drives in (the itineraries carry the requests); at once when no
// other robot is within `quiet_radius_m` of the passage (none could ask in time).
// A robot inside the box whose itinerary is missing or older than `itinerary_expiry_s` (its
// behavior died, or it never had one), or whose itinerary says it is parked there (no path, no
// claim), holds nothing: the passage is an obstacle, and the node plans around it or ends the
// goal Blocked with this rule's reason. A wait longer than `max_wait_s` ends the goal too.
//
// Pure logic: positions, itineraries and the time arrive as arguments.
#include "common/geometry/geometry.hpp"
#include "services/behavior/core/traffic/passage.hpp"

#include <optional>
#include <string>
#include <vector>

namespace autonomy::behavior::traffic {

enum class ClaimState { None, Waiting, Holding };
const char* to_string(ClaimState s);  // "", "waiting", "holding" (as in the Itinerary message)
// Parses the message's words; nullopt for anything else.
std::optional<ClaimState> claim_state_from(const std::string& word);

struct Claim {
  std::string passage;  // Passage::id, "" with ClaimState::None
  ClaimState state = ClaimState::None;
  double request_time_s = 0.0;
};

// Another robot as this one knows it: its true position (the simulator's robot state) and, when
// its behavior publishes one, its itinerary.
struct OtherRobot {
  std::string id;
  geometry::Vec2 position = geometry::Vec2::Zero();
  bool has_itinerary = false;
  double itinerary_age_s = 0.0;  // now - the itinerary's time
  bool has_path = false;         // the itinerary has points: the robot means to move
  std::vector<geometry::Vec2> path;  // the itinerary's points (give_way.hpp compares paths)
  Claim claim;
};

struct TrafficSettings {
  double lookahead_m = 4.0;         // passages on the path within this are claimed
  double approach_m = 1.5;          // a robot not granted stops to wait this far from the box
  double grant_delay_s = 0.5;       // a request stands this long before it is granted...
  double quiet_radius_m = 8.0;      // ...unless no other robot is this close to the passage
  double itinerary_expiry_s = 2.0;  // an older itinerary holds nothing
  double max_wait_s = 90.0;         // a longer wait ends the goal with the reason
};

enum class TrafficAction {
  Drive,     // go on along the path
  Wait,      // stay outside the passage (at a holding point) until granted
  Obstacle,  // the passage is blocked by a robot that holds nothing: plan around it
  GiveUp,    // waited max_wait_s: end the goal (reason)
};

struct TrafficDecision {
  TrafficAction action = TrafficAction::Drive;
  Claim claim;                          // what this robot's itinerary says now
  std::optional<Passage> passage;       // the passage claimed, if any
  std::string blocker;                  // Wait / Obstacle / GiveUp: the robot in the way
  std::string reason;                   // "waiting for r2 to clear doorway A-114", ...
};

class TrafficRule {
 public:
  // Throws std::invalid_argument on an empty robot id or non-positive or non-finite settings.
  TrafficRule(std::vector<Passage> passages, std::string robot_id, TrafficSettings settings = {});

  // One decision per control step: `me` is this robot's position, `path_ahead` the points it is
  // about to drive through in order (from its position towards the goal; empty without a goal),
  // `others` every other robot known.
  TrafficDecision decide(const geometry::Vec2& me, const std::vector<geometry::Vec2>& path_ahead,
                         const std::vector<OtherRobot>& others, double now_s);

  // The goal ended or changed: the claim is dropped (a new goal requests anew).
  void reset();

  const std::vector<Passage>& passages() const { return passages_; }
  const Claim& claim() const { return claim_; }
  const TrafficSettings& settings() const { return settings_; }

 private:
  const Passage* inside(const geometry::Vec2& p) const;
  const Passage* find(const std::string& id) const;

  std::vector<Passage> passages_;
  std::string robot_id_;
  TrafficSettings settings_;
  Claim claim_;
  std::optional<double> waiting_since_s_;
};

}  // namespace autonomy::behavior::traffic
