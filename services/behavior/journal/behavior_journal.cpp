#include "services/behavior/journal/behavior_journal.hpp"

#include "common/sqlite/database.hpp"
#include "common/sqlite/statement.hpp"

#include <sqlite3.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace autonomy::behavior {

namespace {

using sql::Statement;

constexpr int kSchemaVersion = 1;

// A REAL column keeps a text that is no number as text, and SQLite reads that back as 0: such a
// value comes back NULL instead, which finite_real() refuses.
#define NUMBER(column) "CASE WHEN typeof(" column ") IN ('real', 'integer') THEN " column " END"

constexpr GoalState kAllStates[] = {GoalState::Accepted, GoalState::Active,    GoalState::Reached,  GoalState::Blocked,
                                    GoalState::Preempted, GoalState::Rejected, GoalState::Cancelled};

std::optional<GoalState> state_named(const std::string& name) {
  for (GoalState s : kAllStates)
    if (name == to_string(s)) return s;
  return std::nullopt;
}

std::optional<std::string> setting(sqlite3* db, const char* key) {
  Statement s(db, "SELECT value FROM behavior WHERE key = ?");
  s.text(1, key);
  if (!s.step()) return std::nullopt;
  return s.column_text(0);
}

// Tables another service's journal (or any other database) has, when it has no behavior table.
std::vector<std::string> tables(sqlite3* db) {
  std::vector<std::string> out;
  Statement s(db, "SELECT name FROM sqlite_master WHERE type = 'table' ORDER BY name");
  while (s.step()) out.push_back(s.column_text(0));
  return out;
}

std::string mode_of(const std::string& mission) { return mission.empty() ? "goal mode" : "mission " + mission; }

double finite_real(const Statement& s, int column, const char* what) {
  const auto v = s.column_real(column);
  if (!v || !std::isfinite(*v)) throw std::runtime_error(std::string("a damaged value: ") + what + " is not a number");
  return *v;
}

}  // namespace

BehaviorJournal::BehaviorJournal(const std::string& path, const std::string& robot_id, const std::string& mission)
    : path_(path) {
  db_ = sql::open_journal(path);
  try {
    const std::vector<std::string> existing = tables(db_);
    const bool known = std::find(existing.begin(), existing.end(), "behavior") != existing.end();
    if (!known && !existing.empty()) {
      std::string list;
      for (const std::string& t : existing) list += (list.empty() ? "" : ", ") + t;
      throw std::runtime_error("not a behavior journal (its tables: " + list +
                               "); name another file, e.g. {run}/behavior-<robot>.db");
    }
    // Checked before anything is written: a refused journal stays as it was.
    const auto robot = known ? setting(db_, "robot") : std::nullopt;
    const auto mode = known ? setting(db_, "mission") : std::nullopt;
    if (robot && *robot != robot_id)
      throw std::runtime_error("it is the journal of robot " + *robot + ", not of " + robot_id +
                               "; name another journal file or remove this one");
    if (mode && *mode != mission)
      throw std::runtime_error("it is the journal of " + mode_of(*mode) + ", not of " + mode_of(mission) +
                               "; name another journal file or remove this one");
    run_ = sql::count_opening(db_, kSchemaVersion);
    sql::exec(db_, "CREATE TABLE IF NOT EXISTS behavior (key TEXT PRIMARY KEY, value TEXT NOT NULL)");
    sql::exec(db_,
              "CREATE TABLE IF NOT EXISTS goals (seq INTEGER PRIMARY KEY AUTOINCREMENT, goal_id TEXT NOT NULL, "
              "x REAL, y REAL, tolerance REAL, constraint_set TEXT NOT NULL, state TEXT, reason TEXT NOT NULL)");
    sql::exec(db_,
              "CREATE TABLE IF NOT EXISTS mission (id INTEGER PRIMARY KEY CHECK (id = 1), state TEXT NOT NULL, "
              "entered_at_s REAL, plan TEXT NOT NULL, finished INTEGER NOT NULL)");
    sql::exec(db_,
              "CREATE TABLE IF NOT EXISTS mission_events (seq INTEGER PRIMARY KEY AUTOINCREMENT, time_s REAL, "
              "event TEXT NOT NULL, state TEXT NOT NULL, reason TEXT NOT NULL)");
    if (!robot || !mode) {
      sql::in_transaction(db_, [&] {
        Statement(db_, "INSERT OR REPLACE INTO behavior VALUES ('robot', ?)").text(1, robot_id).step();
        Statement(db_, "INSERT OR REPLACE INTO behavior VALUES ('mission', ?)").text(1, mission).step();
      });
    }
    // Read everything once now, so that a damaged value stops the start, not a later step.
    (void)goals();
    (void)this->mission();
  } catch (const std::runtime_error& e) {
    sqlite3_close(db_);
    db_ = nullptr;
    throw std::runtime_error("journal " + path + ": " + e.what());
  }
}

BehaviorJournal::~BehaviorJournal() { sqlite3_close(db_); }

std::vector<JournalledGoal> BehaviorJournal::goals() const {
  std::vector<JournalledGoal> out;
  Statement s(db_, "SELECT seq, goal_id, " NUMBER("x") ", " NUMBER("y") ", " NUMBER("tolerance") ", constraint_set, state, reason "
                   "FROM goals ORDER BY seq");
  while (s.step()) {
    JournalledGoal g;
    g.seq = s.column_integer(0);
    g.goal.goal_id = s.column_text(1);
    const std::string where = "goal " + g.goal.goal_id;
    g.goal.x = finite_real(s, 2, (where + " x").c_str());
    g.goal.y = finite_real(s, 3, (where + " y").c_str());
    g.goal.tolerance = finite_real(s, 4, (where + " tolerance").c_str());
    g.goal.constraint_set = s.column_text(5);
    const std::string state = s.column_text(6);
    if (!state.empty()) {
      g.state = state_named(state);
      if (!g.state) throw std::runtime_error("a damaged value: " + where + " has state '" + state + "'");
    }
    g.reason = s.column_text(7);
    out.push_back(std::move(g));
  }
  return out;
}

long long BehaviorJournal::goal_arrived(const msg::NavGoal& goal) {
  long long seq = 0;
  sql::in_transaction(db_, [&] {
    Statement(db_, "INSERT INTO goals (goal_id, x, y, tolerance, constraint_set, state, reason) "
                   "VALUES (?, ?, ?, ?, ?, NULL, '')")
        .text(1, goal.goal_id)
        .real(2, goal.x)
        .real(3, goal.y)
        .real(4, goal.tolerance)
        .text(5, goal.constraint_set)
        .step();
    seq = sqlite3_last_insert_rowid(db_);
    // Ended goals before the last one to end are history nobody resumes: kept bounded.
    sql::exec(db_,
              "DELETE FROM goals WHERE state IN ('reached', 'blocked', 'preempted', 'rejected', 'cancelled') "
              "AND seq < (SELECT max(seq) FROM goals WHERE state IN "
              "('reached', 'blocked', 'preempted', 'rejected', 'cancelled'))");
  });
  return seq;
}

void BehaviorJournal::goal_state(const std::string& goal_id, GoalState state, const std::string& reason) {
  Statement(db_, "UPDATE goals SET state = ?, reason = ? WHERE seq = (SELECT max(seq) FROM goals WHERE goal_id = ?)")
      .text(1, to_string(state))
      .text(2, reason)
      .text(3, goal_id)
      .step();
}

std::optional<JournalledMission> BehaviorJournal::mission() const {
  Statement s(db_, "SELECT state, " NUMBER("entered_at_s") ", plan, finished, (SELECT count(*) FROM mission_events) "
                   "FROM mission");
  if (!s.step()) return std::nullopt;
  JournalledMission m;
  m.state = s.column_text(0);
  m.entered_at_s = finite_real(s, 1, "the mission state's entry time");
  m.plan = s.column_text(2);
  m.finished = s.column_integer(3) != 0;
  m.events = s.column_integer(4);
  if (m.state.empty()) throw std::runtime_error("a damaged value: the mission state is empty");
  return m;
}

void BehaviorJournal::mission_progress(const JournalledMission& progress,
                                       const std::vector<JournalledMissionEvent>& events) {
  sql::in_transaction(db_, [&] {
    Statement(db_, "INSERT OR REPLACE INTO mission VALUES (1, ?, ?, ?, ?)")
        .text(1, progress.state)
        .real(2, progress.entered_at_s)
        .text(3, progress.plan)
        .integer(4, progress.finished ? 1 : 0)
        .step();
    Statement row(db_, "INSERT INTO mission_events (time_s, event, state, reason) VALUES (?, ?, ?, ?)");
    for (const JournalledMissionEvent& e : events) {
      row.real(1, e.time_s).text(2, e.event).text(3, e.state).text(4, e.reason);
      row.step();
      row.reset();
    }
  });
}

std::vector<JournalledMissionEvent> BehaviorJournal::mission_events() const {
  std::vector<JournalledMissionEvent> out;
  Statement s(db_, "SELECT " NUMBER("time_s") ", event, state, reason FROM mission_events ORDER BY seq");
  while (s.step()) out.push_back({finite_real(s, 0, "a mission event's time"), s.column_text(1), s.column_text(2), s.column_text(3)});
  return out;
}

}  // namespace autonomy::behavior
