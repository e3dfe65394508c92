// The executive restarted from its flight journal (flight_journal.hpp): what it settled stays
// settled, the spacecraft is safed first (while no executive ran an engine may have gone on
// thrusting), and the rest of the horizon is planned from the journalled state values, as after
// an abort; goals whose window closed while it was down are lost saying so.
#include <spdlog/spdlog.h>

#include "executive_node.hpp"

#include <algorithm>

namespace autonomy::executive {

void ExecutiveNode::disable(const std::string& device, const std::string& why) {
  if (journal_) journal_->device_disabled(device, why, now_);
  disabled_[device] = why;
}

void ExecutiveNode::ignore_sensor(const std::string& sensor) {
  if (ignored_sensors_.count(sensor)) return;
  if (journal_) journal_->sensor_ignored(sensor, now_);
  ignored_sensors_.insert(sensor);
}

void ExecutiveNode::journal_state(const Observations& seen) {
  if (!journal_ || !executive_) return;
  std::vector<msg::PlannerTimelineValue> values;
  std::map<std::string, SettlingRecord> settling;
  settle_target(executive_->state_now(seen), values, settling);
  journal_->plan(plan_id_, horizon_end_, values, settling, executing_goals(), seen.time);
}

void ExecutiveNode::restore_from_journal() {
  const FlightRecord& r = journal_->record();
  if (r.fresh()) {
    spdlog::info("journal {}: a new flight", journal_->path());
    return;
  }
  achieved_ = r.achieved;
  lost_ = r.lost;
  disabled_ = r.disabled;
  ignored_sensors_ = r.ignored_sensors;
  plan_id_ = r.plan_id;
  horizon_end_ = r.horizon_end;
  resume_pending_ = true;
  spdlog::info("journal {}: run {}, alive until {} s: {} goals achieved, {} lost, {} devices given up; resuming",
               journal_->path(), r.run, *r.alive_until, achieved_.size(), lost_.size(), disabled_.size());
}

void ExecutiveNode::resume(std::vector<DeviceCommand>& out) {
  resume_pending_ = false;
  const FlightRecord& r = journal_->record();
  lost_while_down_ =
      "executive down from " + std::to_string(*r.alive_until) + " s to " + std::to_string(now_) + " s";
  event("resumed", now_,
        "journal " + journal_->path() + " (run " + std::to_string(r.run) + "): " + std::to_string(achieved_.size()) +
            " goals achieved, " + std::to_string(lost_.size()) + " lost, " + std::to_string(disabled_.size()) +
            " devices given up; " + lost_while_down_);
  // Safe first: nothing commanded the spacecraft while no executive ran.
  for (DeviceCommand c : config_.safing) {
    if (disabled_.count(c.device)) continue;
    c.sent = now_;
    event("command", now_, c.device + " " + c.command + " (safing on resume)");
    out.push_back(std::move(c));
  }
  if (r.state.empty()) {
    // Killed before any plan began: the first horizon is asked for as at a start.
    state_ = State::kWaitingForPlan;
    return;
  }
  // The journalled values with the safe ones in force (as after an abort).
  settle_state_ = r.state;
  apply_safe_values(settle_state_);
  settling_.clear();
  for (const auto& [device, s] : r.settling)
    if (!disabled_.count(device)) settling_[device] = s;
  settle_purpose_ = "resume: " + lost_while_down_;
  settle_deadline_ = now_ + kSettleLimit;
  state_ = State::kSafeWaiting;
  if (settling_.empty()) ask_for_plan(now_, horizon_end_for(now_), settle_state_, settle_purpose_);
  // else settle() asks once the devices have reported their end modes (a turn finished)
}

}  // namespace autonomy::executive
