#include "flight_journal.hpp"

#include <sqlite3.h>

#include <stdexcept>

#include "common/sqlite/database.hpp"
#include "common/sqlite/statement.hpp"

namespace autonomy::executive {

namespace {

using sql::Statement;

constexpr int kSchemaVersion = 1;
constexpr MissionSeconds kAliveEveryS = 60;
constexpr char kSeparator = '\x1f';  // between a value's parameters (never in a parameter)

std::string joined(const std::vector<std::string>& parts) {
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i) out += (i ? std::string(1, kSeparator) : "") + parts[i];
  return out;
}

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> out;
  if (text.empty()) return out;
  std::size_t from = 0;
  for (;;) {
    const std::size_t at = text.find(kSeparator, from);
    out.push_back(text.substr(from, at == std::string::npos ? std::string::npos : at - from));
    if (at == std::string::npos) return out;
    from = at + 1;
  }
}

void set_text(sqlite3* db, const char* key, const std::string& value) {
  Statement(db, "INSERT OR REPLACE INTO flight VALUES (?, ?)").text(1, key).text(2, value).step();
}

std::optional<std::string> text_of(sqlite3* db, const char* key) {
  Statement s(db, "SELECT value FROM flight WHERE key = ?");
  s.text(1, key);
  if (!s.step()) return std::nullopt;
  return s.column_text(0);
}

}  // namespace

FlightJournal::FlightJournal(const std::string& path, const std::string& mission) : path_(path) {
  db_ = sql::open_journal(path);
  try {
    record_.run = sql::count_opening(db_, kSchemaVersion);
    sql::exec(db_, "CREATE TABLE IF NOT EXISTS flight (key TEXT PRIMARY KEY, value TEXT NOT NULL)");
    sql::exec(db_, "CREATE TABLE IF NOT EXISTS goals (label TEXT PRIMARY KEY, achieved INTEGER, detail TEXT)");
    sql::exec(db_, "CREATE TABLE IF NOT EXISTS devices (device TEXT PRIMARY KEY, why TEXT)");
    sql::exec(db_, "CREATE TABLE IF NOT EXISTS sensors (sensor TEXT PRIMARY KEY)");
    sql::exec(db_, "CREATE TABLE IF NOT EXISTS state (timeline TEXT PRIMARY KEY, predicate TEXT, parameters TEXT)");
    sql::exec(db_, "CREATE TABLE IF NOT EXISTS settling (device TEXT PRIMARY KEY, end_mode TEXT, timeline TEXT, "
                   "blocked_predicate TEXT, blocked_parameters TEXT)");
    sql::exec(db_, "CREATE TABLE IF NOT EXISTS executing (label TEXT PRIMARY KEY)");
    const auto flown = text_of(db_, "mission");
    if (flown && *flown != mission)
      throw std::runtime_error("it is the journal of mission " + *flown + ", not of " + mission +
                               "; name another journal file or remove this one");
    if (!flown) set_text(db_, "mission", mission);
    load();
  } catch (const std::logic_error& e) {  // std::stoll on a value that is no number
    sqlite3_close(db_);
    db_ = nullptr;
    throw std::runtime_error("journal " + path + ": a damaged value (" + e.what() +
                             "); the file is damaged or from another version");
  } catch (const std::runtime_error& e) {
    sqlite3_close(db_);
    db_ = nullptr;
    throw std::runtime_error("journal " + path + ": " + e.what());
  }
}

FlightJournal::~FlightJournal() { sqlite3_close(db_); }

void FlightJournal::load() {
  if (const auto alive = text_of(db_, "alive_until")) record_.alive_until = std::stoll(*alive);
  record_.plan_id = text_of(db_, "plan_id").value_or("");
  record_.horizon_end = std::stoll(text_of(db_, "horizon_end").value_or("0"));
  record_.state_at = std::stoll(text_of(db_, "state_at").value_or("0"));
  Statement goals(db_, "SELECT label, achieved, detail FROM goals ORDER BY rowid");
  while (goals.step())
    (goals.column_integer(1) ? record_.achieved : record_.lost)[goals.column_text(0)] = goals.column_text(2);
  Statement devices(db_, "SELECT device, why FROM devices ORDER BY rowid");
  while (devices.step()) record_.disabled[devices.column_text(0)] = devices.column_text(1);
  Statement sensors(db_, "SELECT sensor FROM sensors ORDER BY rowid");
  while (sensors.step()) record_.ignored_sensors.insert(sensors.column_text(0));
  Statement state(db_, "SELECT timeline, predicate, parameters FROM state ORDER BY timeline");
  while (state.step())
    record_.state.push_back({state.column_text(0), state.column_text(1), split(state.column_text(2))});
  Statement settling(db_, "SELECT device, end_mode, timeline, blocked_predicate, blocked_parameters FROM settling");
  while (settling.step()) {
    SettlingRecord r{settling.column_text(1), settling.column_text(2), std::nullopt};
    if (!settling.column_text(3).empty())
      r.if_blocked = msg::PlannerTimelineValue{r.timeline, settling.column_text(3), split(settling.column_text(4))};
    record_.settling[settling.column_text(0)] = std::move(r);
  }
  Statement executing(db_, "SELECT label FROM executing");
  while (executing.step()) record_.executing_goals.insert(executing.column_text(0));
  if (record_.alive_until) written_alive_ = *record_.alive_until;
}

void FlightJournal::write_alive(MissionSeconds now) {
  if (record_.alive_until && *record_.alive_until >= now) return;
  set_text(db_, "alive_until", std::to_string(now));
  record_.alive_until = now;
  written_alive_ = now;
}

void FlightJournal::goal(const std::string& label, bool achieved, const std::string& detail, MissionSeconds now) {
  if (record_.achieved.count(label) || record_.lost.count(label)) return;  // an outcome is final
  sql::in_transaction(db_, [&] {
    Statement(db_, "INSERT OR IGNORE INTO goals VALUES (?, ?, ?)")
        .text(1, label)
        .integer(2, achieved ? 1 : 0)
        .text(3, detail)
        .step();
    write_alive(now);
  });
  (achieved ? record_.achieved : record_.lost)[label] = detail;
}

void FlightJournal::device_disabled(const std::string& device, const std::string& why, MissionSeconds now) {
  if (record_.disabled.count(device)) return;
  sql::in_transaction(db_, [&] {
    Statement(db_, "INSERT OR IGNORE INTO devices VALUES (?, ?)").text(1, device).text(2, why).step();
    write_alive(now);
  });
  record_.disabled[device] = why;
}

void FlightJournal::sensor_ignored(const std::string& sensor, MissionSeconds now) {
  if (record_.ignored_sensors.count(sensor)) return;
  sql::in_transaction(db_, [&] {
    Statement(db_, "INSERT OR IGNORE INTO sensors VALUES (?)").text(1, sensor).step();
    write_alive(now);
  });
  record_.ignored_sensors.insert(sensor);
}

void FlightJournal::plan(const std::string& plan_id, MissionSeconds horizon_end,
                         const std::vector<msg::PlannerTimelineValue>& state,
                         const std::map<std::string, SettlingRecord>& settling,
                         const std::set<std::string>& executing_goals, MissionSeconds now) {
  sql::in_transaction(db_, [&] {
    set_text(db_, "plan_id", plan_id);
    set_text(db_, "horizon_end", std::to_string(horizon_end));
    set_text(db_, "state_at", std::to_string(now));
    sql::exec(db_, "DELETE FROM state");
    Statement row(db_, "INSERT INTO state VALUES (?, ?, ?)");
    for (const auto& v : state) {
      row.text(1, v.timeline).text(2, v.predicate).text(3, joined(v.parameters));
      row.step();
      row.reset();
    }
    sql::exec(db_, "DELETE FROM settling");
    Statement wait(db_, "INSERT INTO settling VALUES (?, ?, ?, ?, ?)");
    for (const auto& [device, r] : settling) {
      wait.text(1, device).text(2, r.end_mode).text(3, r.timeline);
      wait.text(4, r.if_blocked ? r.if_blocked->predicate : "");
      wait.text(5, r.if_blocked ? joined(r.if_blocked->parameters) : "");
      wait.step();
      wait.reset();
    }
    sql::exec(db_, "DELETE FROM executing");
    Statement goal(db_, "INSERT INTO executing VALUES (?)");
    for (const std::string& label : executing_goals) {
      goal.text(1, label).step();
      goal.reset();
    }
    write_alive(now);
  });
  record_.executing_goals = executing_goals;
  record_.settling = settling;
  record_.plan_id = plan_id;
  record_.horizon_end = horizon_end;
  record_.state_at = now;
  record_.state = state;
}

void FlightJournal::alive(MissionSeconds now) {
  if (written_alive_ >= 0 && now - written_alive_ < kAliveEveryS) return;
  sql::in_transaction(db_, [&] { write_alive(now); });
}

}  // namespace autonomy::executive
