#include "fault_responses.hpp"

#include <cmath>

namespace autonomy::executive {

const char* to_string(FaultAction::Kind kind) {
  switch (kind) {
    case FaultAction::Kind::kAbortAndReplan:
      return "abort_and_replan";
    case FaultAction::Kind::kReset:
      return "reset";
    case FaultAction::Kind::kIgnoreSensor:
      return "ignore_sensor";
    case FaultAction::Kind::kSwitchControlMode:
      return "switch_control_mode";
    case FaultAction::Kind::kStopCommanding:
      return "stop_commanding";
  }
  return "?";
}

std::vector<FaultAction> StuckDeviceResponse::assess(const Observations& seen,
                                                     const PlanState& plan) {
  std::vector<FaultAction> actions;
  for (const auto& [device, expected] : plan.expected_modes) {
    auto it = seen.device_modes.find(device);
    if (it == seen.device_modes.end() || it->second == expected || it->second == "failed" ||
        it->second == "stuck_closed") {
      disagreeing_[device] = 0;  // no report, agreement, or a fault another part handles
      continue;
    }
    if (++disagreeing_[device] == samples_)
      actions.push_back({FaultAction::Kind::kAbortAndReplan, device, "", "",
                         device + " reports " + it->second + " but the plan expects " + expected +
                             " (" + std::to_string(samples_) + " samples)"});
  }
  return actions;
}

std::vector<FaultAction> ResetUnitResponse::assess(const Observations& seen, const PlanState&) {
  std::vector<FaultAction> actions;
  for (const auto& [device, mode] : seen.device_modes) {
    bool failed = mode == "failed";
    bool newly = failed && !was_failed_[device];
    was_failed_[device] = failed;
    if (!newly) continue;  // one response per failure, not one per tick
    int& used = resets_[device];
    if (used < max_resets_) {
      ++used;
      actions.push_back({FaultAction::Kind::kReset, device, "", "",
                         device + " reports failed; reset " + std::to_string(used) + " of " +
                             std::to_string(max_resets_)});
    } else {
      actions.push_back(
          {FaultAction::Kind::kStopCommanding, device, "", "",
           device + " failed again after " + std::to_string(max_resets_) + " resets"});
    }
  }
  return actions;
}

std::vector<FaultAction> FalseSensorResponse::assess(const Observations& seen, const PlanState&) {
  std::vector<FaultAction> actions;
  for (const RedundantEvidence& r : rules_) {
    if (ignored_[r.sensor]) continue;
    auto s = seen.readings.find(r.sensor);
    if (s == seen.readings.end()) continue;  // no reading this tick: the count waits
    double sum = 0, lo = INFINITY, hi = -INFINITY;
    std::size_t count = 0;
    for (const std::string& e : r.evidence) {
      auto it = seen.readings.find(e);
      if (it == seen.readings.end()) continue;
      sum += it->second;
      lo = std::min(lo, it->second);
      hi = std::max(hi, it->second);
      ++count;
    }
    // The evidence must be present and agree within itself, or it cannot judge the sensor.
    if (count == 0 || hi - lo > r.tolerance) {
      disagreeing_[r.sensor] = 0;
      continue;
    }
    double predicted = sum / count;
    if (std::fabs(s->second - predicted) <= r.tolerance) {
      disagreeing_[r.sensor] = 0;
      continue;
    }
    if (++disagreeing_[r.sensor] >= r.samples) {
      ignored_[r.sensor] = true;
      actions.push_back({FaultAction::Kind::kIgnoreSensor, r.sensor, "", "",
                         r.sensor + " reads " + std::to_string(s->second) + " but " +
                             std::to_string(count) + " redundant readings say " +
                             std::to_string(predicted) + " for " + std::to_string(r.samples) +
                             " samples"});
    }
  }
  return actions;
}

std::vector<FaultAction> ActuatorStuckResponse::assess(const Observations& seen, const PlanState&) {
  std::vector<FaultAction> actions;
  for (const ActuatorFallback& f : table_) {
    auto it = seen.device_modes.find(f.actuator);
    if (it == seen.device_modes.end() || it->second != "stuck_closed" || switched_[f.actuator])
      continue;
    switched_[f.actuator] = true;
    actions.push_back(
        {FaultAction::Kind::kSwitchControlMode, f.actuator, f.fallback_mode, f.control_device,
         f.actuator + " stuck closed; " + f.control_device + " to " + f.fallback_mode});
  }
  return actions;
}

std::vector<FaultAction> UnconfirmedCommandResponse::assess(const Observations& seen,
                                                            const PlanState&) {
  std::vector<FaultAction> actions;
  for (const std::string& device : seen.unconfirmed_devices)
    actions.push_back({FaultAction::Kind::kStopCommanding, device, "", "",
                       "command to " + device + " not confirmed in time"});
  return actions;
}

std::vector<std::unique_ptr<FaultResponse>> ds1_fault_table(
    std::vector<RedundantEvidence> sensors, std::vector<ActuatorFallback> actuators) {
  std::vector<std::unique_ptr<FaultResponse>> table;
  table.push_back(std::make_unique<FalseSensorResponse>(std::move(sensors)));
  table.push_back(std::make_unique<ResetUnitResponse>());
  table.push_back(std::make_unique<ActuatorStuckResponse>(std::move(actuators)));
  table.push_back(std::make_unique<UnconfirmedCommandResponse>());
  table.push_back(std::make_unique<StuckDeviceResponse>());
  return table;
}

}  // namespace autonomy::executive
