#include "services/courier/core/execution/fleet_roster.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace autonomy::courier {

FleetRoster::FleetRoster(std::set<std::string> declared, double lost_after_s)
    : declared_(std::move(declared)), lost_after_s_(lost_after_s) {}

std::vector<RosterChange> FleetRoster::on_heartbeat(const std::string& robot, BeatKind kind,
                                                    const std::vector<std::string>& capabilities,
                                                    double now_s) {
  std::vector<RosterChange> out;
  const bool is_member = member(robot);
  switch (kind) {
    case BeatKind::ready: {
      const bool courier =
          declared_.count(robot) != 0 || std::find(capabilities.begin(), capabilities.end(),
                                                   kCourierCapability) != capabilities.end();
      if (is_member || courier) last_heard_[robot] = now_s;
      if (!is_member && courier) out.push_back({robot, true, ""});
      return out;
    }
    case BeatKind::starting:
      if (is_member) last_heard_[robot] = now_s;  // restarting under the same id: still heard
      return out;
    case BeatKind::stopping:
    case BeatKind::disposed:
    case BeatKind::no_writers:
      if (!is_member) return out;
      last_heard_.erase(robot);
      out.push_back({robot, false, kind == BeatKind::no_writers ? "heartbeat lost" : "stopped"});
      return out;
  }
  return out;
}

std::vector<RosterChange> FleetRoster::expire(double now_s) {
  std::vector<RosterChange> out;
  for (auto it = last_heard_.begin(); it != last_heard_.end();) {
    if (now_s - it->second > lost_after_s_) {
      out.push_back({it->first, false,
                     "heartbeat lost: none for " +
                         std::to_string(static_cast<long>(std::lround(now_s - it->second))) +
                         " s"});
      it = last_heard_.erase(it);
    } else {
      ++it;
    }
  }
  return out;
}

}  // namespace autonomy::courier
