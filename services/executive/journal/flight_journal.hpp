#pragma once
// The executive's journal of a flight: what it must not forget when it is killed (-9) and started
// again. Written before the executive acts on it, in SQLite (common/sqlite: WAL, synchronous=FULL):
//   - the mission it flies (a journal of another mission is refused at start);
//   - each goal's outcome, achieved or lost with the reason (a restart never reports a goal it
//     achieved as lost, or asks for it again);
//   - the devices given up and the sensors judged false (never commanded or believed again);
//   - the plan in execution: its id, its horizon's end, the timeline values it leaves the
//     spacecraft in (the value each state timeline holds, or will hold once the token the world
//     ends has ended) and the goals under way, updated whenever a token starts or ends and at
//     every abort;
//   - the last mission time it was alive (every minute of mission time and with every write):
//     goals whose window passed while it was down are lost "executive down from T1 to T2".
// A restart does not resume the old plan's dispatch in the middle: the world went on without
// it (tokens ended uncommanded, a turn finished), so it plans again from the journalled values
// corrected by the telemetry, as after an abort. Pure: no DDS.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "common/msg/planner.hpp"

struct sqlite3;

namespace autonomy::executive {

using MissionSeconds = std::int64_t;

// A token the world ends (a turn) that was under way: the value journalled for its timeline is
// the one after it, reached once `device` reports `end_mode` (or `if_blocked`, the one before it,
// when the device reports "blocked": a robot's drive given up).
struct SettlingRecord {
  std::string end_mode;
  std::string timeline;
  std::optional<msg::PlannerTimelineValue> if_blocked;
};

struct FlightRecord {
  int run = 0;  // this opening's number (1: a new flight)
  std::optional<MissionSeconds> alive_until;  // the last mission time the executive ran
  std::map<std::string, std::string> achieved, lost;  // goal label -> how / why
  std::map<std::string, std::string> disabled;        // device -> why
  std::set<std::string> ignored_sensors;
  std::string plan_id;
  MissionSeconds horizon_end = 0;
  MissionSeconds state_at = 0;  // when `state` was journalled
  std::vector<msg::PlannerTimelineValue> state;
  std::map<std::string, SettlingRecord> settling;  // by device
  std::set<std::string> executing_goals;  // goals under way (asked for again from the restart)
  bool fresh() const { return !alive_until.has_value(); }
};

class FlightJournal {
 public:
  // Opens or creates the journal of `mission` (the problem file's path, as configured). Throws
  // std::runtime_error naming the path when it cannot, when its schema is newer, or when it
  // is the journal of another mission.
  FlightJournal(const std::string& path, const std::string& mission);
  ~FlightJournal();
  FlightJournal(const FlightJournal&) = delete;
  FlightJournal& operator=(const FlightJournal&) = delete;

  const FlightRecord& record() const { return record_; }  // as loaded at start, then kept current

  void goal(const std::string& label, bool achieved, const std::string& detail, MissionSeconds now);
  void device_disabled(const std::string& device, const std::string& why, MissionSeconds now);
  void sensor_ignored(const std::string& sensor, MissionSeconds now);
  void plan(const std::string& plan_id, MissionSeconds horizon_end, const std::vector<msg::PlannerTimelineValue>& state,
            const std::map<std::string, SettlingRecord>& settling, const std::set<std::string>& executing_goals,
            MissionSeconds now);
  // Alive at `now`: written when a minute of mission time has passed since the last write.
  void alive(MissionSeconds now);

  const std::string& path() const { return path_; }

 private:
  void load();
  void write_alive(MissionSeconds now);  // inside a transaction

  std::string path_;
  sqlite3* db_ = nullptr;
  FlightRecord record_;
  MissionSeconds written_alive_ = -1;
};

}  // namespace autonomy::executive
