#pragma once
// Which robots are couriers right now, from their behavior processes' heartbeats: a robot joins
// when its behavior says ready and it is a courier (declared so in the scenario or named on the
// courier's command line, or its heartbeat announces the "courier" capability); it leaves when its
// heartbeat says stopping, its instance is disposed, its writer is gone (DDS lease expired: kill
// -9) or no heartbeat came for lost_after_s. Times are the caller's (the node passes a steady
// clock); nothing here reads a clock.
#include <map>
#include <set>
#include <string>
#include <vector>

namespace autonomy::courier {

constexpr char kCourierCapability[] = "courier";

enum class BeatKind {
  ready,      // alive and serving
  starting,   // alive, not serving yet
  stopping,   // a clean stop
  disposed,   // the instance ended cleanly
  no_writers  // the process is gone without a word (lease expired)
};

struct RosterChange {
  std::string robot;
  bool joined = false;
  std::string why;  // for a leave: "stopped", "heartbeat lost", ...
};

class FleetRoster {
 public:
  FleetRoster(std::set<std::string> declared, double lost_after_s);

  std::vector<RosterChange> on_heartbeat(const std::string& robot, BeatKind kind,
                                         const std::vector<std::string>& capabilities,
                                         double now_s);
  // Members not heard of for longer than lost_after_s leave.
  std::vector<RosterChange> expire(double now_s);
  bool member(const std::string& robot) const { return last_heard_.count(robot) != 0; }

 private:
  std::set<std::string> declared_;
  double lost_after_s_;
  std::map<std::string, double> last_heard_;  // members
};

}  // namespace autonomy::courier
