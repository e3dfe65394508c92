#pragma once
// The executive's thin DDS shell: one event loop, lockstep ticks, the spacecraft link, the
// planner link and the watchdog around the pure core (services/executive/core) and the mission
// (services/executive/planning).
//
// Life of a run:
//   waiting_for_plan   the first horizon's plan is asked for; in lockstep the first tick is
//                      held (not acknowledged) for at most --plan-hold-s so that planning takes
//                      no simulated time, then the world goes on with the spacecraft safe
//   executing          each tick: telemetry -> confirmations -> Executive::step -> commands,
//                      events; the next horizon is asked for request_lead_s before this one
//                      ends and joined at its end (its origin is this plan's end: no gap)
//   safe_waiting_for_plan
//                      after an abort (safing sent): the rest of the horizon is asked for
//                      from now, with the current values as state, the faulty devices never
//                      commanded again; the tick is held as above; an unanswered request is
//                      sent again every --plan-timeout-s (the planner may have died)
//   finished           the mission's horizon is over (checked in every state: a mission always
//                      ends, with its report, even while no plan executes)
// With --journal (flight_journal.hpp) every goal outcome, device given up, sensor judged false
// and the plan's state values are journalled before they are acted on; a restarted executive
// safes the spacecraft, takes them back and plans from the journalled values corrected by the
// configured safe values (resume.cpp), as after an abort.
// Holds: a lockstep tick is held while a plan is awaited for at most --plan-hold-s in total per
// planner outage (any reply from the planner renews it), not per request: while the planner is
// away the world goes on with the spacecraft safe and the request is asked again every
// --plan-timeout-s. A refused plan (not dispatchable, rejected) is asked again after 1, 2, 4 ...
// s (at most --plan-timeout-s).
// Every response, plan and goal is an event on autonomy/executive/event; the status
// (autonomy/executive/status) follows every change and every second.
#include <atomic>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"
#include "common/service/lockstep_client.hpp"
#include "common/service/service.hpp"
#include "executive.hpp"
#include "executive_config.hpp"
#include "flight_journal.hpp"
#include "mission.hpp"
#include "planner_link.hpp"
#include "robot_link.hpp"
#include "run_report.hpp"
#include "spacecraft_link.hpp"
#include "watchdog.hpp"

namespace autonomy::executive {

struct ExecutiveNodeOptions {
  std::string config_path;
  std::string spacecraft;      // the only telemetry instance read; "" = the first one heard
  double plan_timeout_s = 5;   // ask again when a request stays unanswered this long (wall)
  double plan_hold_s = 10;     // hold a lockstep tick at most this long for a plan (wall)
  double watchdog_s = 2;       // a tick handler running longer raises the alarm and safes
  std::string report_dir;      // where plan.svg and report.md go when the mission ends ("": none)
  std::string journal_path;    // the flight journal ("": none; a restart then starts afresh)
};

class ExecutiveNode {
 public:
  ExecutiveNode(service::Service& service, ExecutiveNodeOptions options, ExecutiveConfig config,
                Mission mission);
  ExecutiveNode(const ExecutiveNode&) = delete;
  ExecutiveNode& operator=(const ExecutiveNode&) = delete;

 private:
  enum class State { kWaitingForPlan, kExecuting, kSafeWaiting, kFinished };
  struct HeldTick {  // how long it may be held: hold_limit() from hold_since_
    msg::SimClock clock;
  };

  void on_tick(const msg::SimClock& clock);
  void run_tick(const msg::SimClock& clock);  // the tick's work and its acknowledgement
  // Acknowledges the tick with `sent` commands, or holds it while a plan is awaited.
  void finish_tick(const msg::SimClock& clock, std::uint32_t sent);
  PlannerLink::Clock::duration hold_limit() const;
  void dispatch(Time now, std::vector<DeviceCommand>& out);
  std::uint32_t send(const std::vector<DeviceCommand>& commands, std::int64_t tick);
  // The newest telemetry and the robots' reports as the core's Observations at `now`.
  Observations observed(Time now) const;
  std::map<std::string, std::string> device_modes() const;  // the spacecraft's and the robots' 
  bool step_plan(const Observations& seen, std::vector<DeviceCommand>& out);  // false: aborted
  void on_reply();
  void on_timer();
  void settle();  // after an abort: ask for the new plan once world-ended tokens have ended
  void ask_first();
  bool accept(const msg::PlanningReply& reply, Time now);
  void start_plan(const msg::PlanningReply& reply, Time origin, Time horizon_end,
                  const std::vector<std::string>& goals);
  void ask_for_plan(Time origin, Time end, std::vector<msg::PlannerTimelineValue> state,
                    const std::string& purpose, bool every_goal_optional = false);
  void finish_held_tick();
  void ask_again();
  void reask();                           // a late request asked again, at a tick
  Time horizon_end_for(Time now) const;
  std::vector<msg::PlannerTimelineValue> held_values() const;  // the plan's values at its end
  std::vector<msg::PlannerTimelineValue> current_values(const ReplanRequest& r) const;
  // The configuration's safe values (the engine off) replace what the state says.
  void apply_safe_values(std::vector<msg::PlannerTimelineValue>& state) const;
  std::set<std::string> executing_goals() const;  // labels of the plan's goal tokens under way
  void note_goals(const ExecutiveEvent& e);
  void lose_goals(const std::map<std::string, std::string>& lost, Time now);
  void event(const std::string& kind, Time now, const std::string& text);
  void publish_status();
  void write_report();
  void safe_from_watchdog(PlannerLink::Clock::duration busy);
  // The values a replan from `r` starts with and the devices it waits for (a token the world
  // ends that is under way: its next value, once its device reports the end mode).
  void settle_target(const ReplanRequest& r, std::vector<msg::PlannerTimelineValue>& values,
                     std::map<std::string, SettlingRecord>& settling) const;
  // Journals the plan's state values when tokens started or ended (journal_state), the first
  // tick after a restart (resume.cpp): safing sent, journalled outcomes restored, replan asked.
  void journal_state(const Observations& seen);
  void resume(std::vector<DeviceCommand>& out);
  void restore_from_journal();
  void disable(const std::string& device, const std::string& why);
  void ignore_sensor(const std::string& sensor);
  // The mission's horizon is over: whatever state it is in, goals not settled are lost with
  // `why`, the report is written, the status says finished.
  void end_mission(const std::string& why);
  // A refused reply or plan: asked again after a back-off (1, 2, 4 ... s, at most the timeout).
  void reask_later();
  const char* state_name() const;

  service::Service& service_;
  ExecutiveNodeOptions options_;
  ExecutiveConfig config_;
  Mission mission_;
  std::string name_;
  SpacecraftLink spacecraft_;
  std::unique_ptr<RobotLink> robots_;  // when the configuration names robots
  PlannerLink planner_;
  dds::Topic<msg::ExecutiveEvent> event_topic_;
  dds::Topic<msg::ExecutiveStatus> status_topic_;
  dds::Writer<msg::ExecutiveEvent> event_writer_;
  dds::Writer<msg::ExecutiveStatus> status_writer_;
  service::LockstepClient lockstep_;

  State state_ = State::kWaitingForPlan;
  std::unique_ptr<Executive> executive_;
  std::string plan_id_;
  Time plan_origin_ = 0, horizon_end_ = 0;
  std::optional<msg::PlanningReply> next_plan_;  // the next horizon's, until it is joined
  std::vector<std::string> next_goals_;           // the goals it was asked for
  std::vector<std::string> current_goals_;        // those the executing plan was asked for
  std::vector<std::string> asked_goals_;          // those of the outstanding request
  bool asked_optional_ = false;                   // ...asked for as optional (after infeasible)
  bool next_asked_ = false;
  Time asked_origin_ = 0, asked_end_ = 0;
  std::vector<msg::PlannerTimelineValue> asked_state_;
  std::string asked_purpose_;
  bool reask_ = false;
  PlannerLink::Clock::time_point reask_after_{};  // not before (after a rejection)
  bool lockstep_mode_ = true;  // of the last tick
  std::optional<HeldTick> held_;
  std::uint32_t held_commands_ = 0;      // already sent for the held tick
  std::optional<msg::SpacecraftTelemetry> telemetry_;
  std::int64_t last_tick_ = -1;
  std::atomic<std::int64_t> watched_tick_{-1};  // last_tick_ for the watchdog's thread
  Time now_ = 0;

  static constexpr Time kSettleLimit = 900;      // s of simulated time
  // A device whose token the abort left running (a drive): the replan waits for its end mode.
  // A device that reports "blocked" instead (a robot's goal given up) has settled too, where
  // it started: its timeline is asked for with the token's predecessor value.
  using Settling = SettlingRecord;
  static constexpr char kBlockedMode[] = "blocked";
  std::map<std::string, Settling> settling_;  // by device
  std::vector<msg::PlannerTimelineValue> settle_state_;
  std::string settle_purpose_;
  Time settle_deadline_ = 0;
  Time stepped_at_ = -1;                          // the current plan's last step

  std::map<std::string, std::string> disabled_;  // device -> why (known faults)
  std::set<std::string> ignored_sensors_;
  std::map<std::string, std::string> achieved_, lost_;  // goal label -> how
  std::uint64_t events_ = 0;
  unsigned replans_ = 0, horizons_ = 0;
  double decision_us_sum_ = 0, decision_us_max_ = 0;
  std::uint64_t decisions_ = 0;
  PlannerLink::Clock::time_point fault_seen_{};  // wall time of the last abort, for its figure

  RunReport report_;

  std::unique_ptr<FlightJournal> journal_;
  bool resume_pending_ = false;        // restarted from a journal: resume at the first tick
  std::string lost_while_down_;        // "executive down from T1 s to T2 s", for goals it cost
  unsigned refusals_ = 0;              // in a row, for the back-off
  std::optional<PlannerLink::Clock::time_point> hold_since_;  // this outage's first held tick

  Watchdog watchdog_;  // last: its thread starts when everything above exists
};

}  // namespace autonomy::executive
