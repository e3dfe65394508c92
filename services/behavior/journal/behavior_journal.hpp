#pragma once
// The behavior controller's journal (behavior --journal FILE): what a behavior killed (-9) and
// started again must not forget, in SQLite (common/sqlite: WAL, synchronous=FULL). Goals arrive
// on a volatile command topic, so a goal lost by a dead process is never sent again; a mission
// restarted from its initial state would redo what it had done. Written before acting:
//   - goal mode: every goal as it arrives (all the NavGoal fields needed to pursue it again), then
//     each state published for it (accepted, active, reached, ...) with its reason, written
//     before the status is published;
//   - mission mode: the mission's progress (the state it is in, when it entered it, the plan its
//     static selection chose there, finished) and the log of its events, written after each
//     executor step that changed something and before its events and command go out.
// A journal belongs to one robot and one mode (goal mode, or one named mission): another one's,
// a foreign database (another service's journal) or a damaged file is refused at opening,
// naming the path. Pure: no DDS.
#include "common/msg/navigation.hpp"
#include "services/behavior/core/goal_status.hpp"

#include <optional>
#include <string>
#include <vector>

struct sqlite3;

namespace autonomy::behavior {

struct JournalledGoal {
  long long seq = 0;  // arrival order
  msg::NavGoal goal;
  std::optional<GoalState> state;  // the last state published; nullopt: arrived, none published yet
  std::string reason;              // of that state
  // Still to be driven on: nothing published yet, accepted or active.
  bool open() const { return !state || !is_terminal(*state); }
};

struct JournalledMission {
  std::string state;          // the mission state the robot is in
  double entered_at_s = 0.0;  // sim time it entered that state (Timeout triggers count from it)
  std::string plan;           // the plan static selection chose in that state; "" for none
  bool finished = false;
  long long events = 0;       // mission events journalled so far (the log's length)
};

struct JournalledMissionEvent {
  double time_s = 0.0;
  std::string event;  // started, transition, plan_chosen, no_viable_plan, finished, resumed
  std::string state;
  std::string reason;
};

class BehaviorJournal {
 public:
  // Opens or creates the journal of robot `robot_id`, in goal mode (mission "") or running
  // `mission` (its name). Throws std::runtime_error naming the path when it cannot open it, when
  // it is no behavior journal, when it is another robot's or another mode's, or when a value in
  // it is damaged.
  BehaviorJournal(const std::string& path, const std::string& robot_id, const std::string& mission);
  ~BehaviorJournal();
  BehaviorJournal(const BehaviorJournal&) = delete;
  BehaviorJournal& operator=(const BehaviorJournal&) = delete;

  const std::string& path() const { return path_; }
  int run() const { return run_; }  // this opening's number (1: a new journal)

  // Goal mode. The goals kept, in arrival order: every open one, and the last one to end (a
  // restarted behavior publishes that one's end again). Older ended goals are dropped.
  std::vector<JournalledGoal> goals() const;
  // A goal arrived: journalled with no state yet. Returns its seq.
  long long goal_arrived(const msg::NavGoal& goal);
  // A state about to be published for the latest goal with this id (nothing when none has it).
  void goal_state(const std::string& goal_id, GoalState state, const std::string& reason);

  // Mission mode.
  std::optional<JournalledMission> mission() const;
  // The progress after a step, with the events that step caused (appended to the log).
  void mission_progress(const JournalledMission& progress, const std::vector<JournalledMissionEvent>& events);
  std::vector<JournalledMissionEvent> mission_events() const;

 private:
  std::string path_;
  sqlite3* db_ = nullptr;
  int run_ = 0;
};

}  // namespace autonomy::behavior
