// BehaviorNode in mission mode (--mission): perception from the simulator's sensor and radio
// models, one MissionExecutor step per tick, mission events on autonomy/mission/status.
#include "services/behavior/dds/behavior_node.hpp"

#include <spdlog/spdlog.h>

#include <cmath>
#include <iterator>

namespace autonomy::behavior {

namespace {

const char* event_name(MissionEvent::Kind k) {
  switch (k) {
    case MissionEvent::Kind::Started: return "started";
    case MissionEvent::Kind::Transition: return "transition";
    case MissionEvent::Kind::PlanChosen: return "plan_chosen";
    case MissionEvent::Kind::NoViablePlan: return "no_viable_plan";
    case MissionEvent::Kind::Finished: return "finished";
    case MissionEvent::Kind::Resumed: return "resumed";
  }
  return "?";
}

}  // namespace

Perception BehaviorNode::perceive() const {
  const msg::RobotState& st = *state_;
  Perception p;
  p.time_s = static_cast<double>(st.sim_time_ns) * 1e-9;
  p.pose = {st.x, st.y, st.theta};
  // The robot's own estimate when its pose sensor publishes one for this tick (or the previous).
  if (pose_estimate_ && pose_estimate_->tick >= st.tick - 1)
    p.pose = {pose_estimate_->x, pose_estimate_->y, pose_estimate_->theta};
  p.kinematics = st.kinematics == msg::Kinematics::Holonomic ? Kinematics::Holonomic : Kinematics::Unicycle;
  p.velocity = p.kinematics == Kinematics::Holonomic
                   ? geometry::Vec2(st.vx, st.vy)
                   : geometry::Vec2(st.vx * std::cos(st.theta), st.vx * std::sin(st.theta));
  p.limits = {st.max_speed, st.max_omega};
  if (scan_) {
    p.rays.reserve(scan_->ranges.size());
    for (std::size_t i = 0; i < scan_->ranges.size(); ++i) {
      p.rays.push_back({scan_->angle_min + static_cast<double>(i) * scan_->angle_increment,
                        static_cast<double>(scan_->ranges[i]), scan_->max_range});
    }
  }
  for (const std::string& id : options_.mission->teammates) {
    TeammateState t;
    t.id = id;
    if (const auto link = link_connected_.find(id); link != link_connected_.end()) {
      t.in_contact = link->second;
    } else if (radio_links_seen_) {
      t.in_contact = false;  // the radio runs and this pair never connected
    } else if (!last_heard_s_.empty()) {
      const auto heard = last_heard_s_.find(id);
      t.in_contact = heard != last_heard_s_.end() && p.time_s - heard->second <= options_.contact_freshness_s;
    } else {
      t.in_contact = true;  // no radio model running: everyone is in contact
    }
    if (const auto pos = last_known_position_.find(id); pos != last_known_position_.end()) t.position = pos->second;
    p.teammates.push_back(std::move(t));
  }
  return p;
}

uint32_t BehaviorNode::control_mission(int64_t tick) {
  // Teammates' positions are known while in contact (as if they reported them), kept when lost.
  Perception p = perceive();
  for (TeammateState& t : p.teammates) {
    t.in_contact = contact_.update(t.id, p.time_s, t.in_contact);
    const auto st = teammate_states_.find(t.id);
    if (t.in_contact && st != teammate_states_.end()) {
      last_known_position_[t.id] = geometry::Vec2(st->second.x, st->second.y);
      t.position = last_known_position_[t.id];
    }
  }
  const bool was_finished = executor_->finished();
  std::vector<MissionEvent> events;
  if (journalled_mission_) {  // the first step after a restart: on from where the journal says
    const JournalledMission& j = *journalled_mission_;
    events = executor_->resume({j.state, j.entered_at_s, j.plan}, p,
                               "after a restart of behavior " + options_.robot_id + " (journal run " +
                                   std::to_string(journal_->run()) + "): in " + j.state + " since t=" +
                                   fmt::format("{:.1f}", j.entered_at_s) + " s, " + std::to_string(j.events) +
                                   " mission events before");
    journalled_mission_.reset();
  }
  MissionStep step = executor_->step(p);
  events.insert(events.end(), std::make_move_iterator(step.events.begin()), std::make_move_iterator(step.events.end()));
  if (journal_ && !events.empty()) {
    // Before the events go out and the robot acts on the new state.
    const MissionProgress progress = *executor_->progress();
    std::vector<JournalledMissionEvent> logged;
    for (const MissionEvent& e : events) logged.push_back({e.time_s, event_name(e.kind), e.state, e.reason});
    journal_->mission_progress({progress.state, progress.entered_at_s, progress.plan, executor_->finished(), 0}, logged);
  }
  for (const MissionEvent& e : events) {
    spdlog::info("mission {}: {}", options_.mission->name, e.to_string());
    publish_mission(e, tick);
  }
  if (!was_finished || !stopped_robot_) {
    send_command(step.finished ? VelocityCommand{} : step.command, tick);
    return 1;
  }
  return 0;
}

void BehaviorNode::publish_mission(const MissionEvent& e, int64_t tick) {
  msg::MissionStatus s;
  s.robot_id = options_.robot_id;
  s.mission = options_.mission->name;
  s.state = e.state;
  s.event = event_name(e.kind);
  s.reason = e.kind == MissionEvent::Kind::Transition ? e.from + " -> " + e.state + ": " + e.reason : e.reason;
  s.finished = e.kind == MissionEvent::Kind::Finished || executor_->finished();
  s.tick = tick;
  mission_status_writer_.write(s);
}

}  // namespace autonomy::behavior
