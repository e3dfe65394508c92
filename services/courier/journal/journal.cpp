#include "services/courier/journal/journal.hpp"

#include <sqlite3.h>

#include <stdexcept>

#include "common/sqlite/database.hpp"
#include "common/sqlite/statement.hpp"

namespace autonomy::courier {

namespace {

using sql::Statement;

constexpr int kSchemaVersion = 1;

const char* kJobColumns =
    "job_id, command_id, object_id, object_kind, object_colour, pickup, destination, deadline_s, accepted_at_s, "
    "state, phase, robot, reason, estimated_completion_s, object_place, object_carrier, return_to, "
    "end_state_after_return, return_reason";

void bind_job(Statement& s, const Job& j) {
  s.text(1, j.id).text(2, j.command_id).text(3, j.object.id).text(4, j.object.kind).text(5, j.object.colour);
  s.text(6, j.pickup).text(7, j.destination).real(8, j.deadline_s).real(9, j.accepted_at_s);
  s.text(10, to_string(j.state)).integer(11, static_cast<int>(j.phase)).text(12, j.robot).text(13, j.reason);
  s.real(14, j.estimated_completion_s).text(15, j.object_place).text(16, j.object_carrier).text(17, j.return_to);
  s.text(18, to_string(j.end_state_after_return)).text(19, j.return_reason);
}

}  // namespace

Journal::Journal(const std::string& path) : path_(path) {
  db_ = sql::open_journal(path);
  try {
    run_ = sql::count_opening(db_, kSchemaVersion);
    exec("INSERT OR IGNORE INTO meta VALUES ('jobs_created', 0)");
    exec("CREATE TABLE IF NOT EXISTS commands (command_id TEXT PRIMARY KEY, reply TEXT NOT NULL)");
    exec("CREATE TABLE IF NOT EXISTS jobs (job_id TEXT PRIMARY KEY, command_id TEXT, object_id TEXT, "
         "object_kind TEXT, object_colour TEXT, pickup TEXT, destination TEXT, deadline_s REAL, accepted_at_s REAL, "
         "state TEXT, phase INTEGER, robot TEXT, reason TEXT, estimated_completion_s REAL, object_place TEXT, "
         "object_carrier TEXT, return_to TEXT, end_state_after_return TEXT, return_reason TEXT)");
    exec("CREATE TABLE IF NOT EXISTS handovers (request_id TEXT PRIMARY KEY, robot TEXT, load INTEGER, place TEXT, "
         "object_id TEXT, job_id TEXT, outcome TEXT)");
    create_experience_tables();
  } catch (const std::runtime_error& e) {
    sqlite3_close(db_);
    db_ = nullptr;
    throw std::runtime_error("journal " + path + ": " + e.what());
  }
}

Journal::~Journal() { sqlite3_close(db_); }

void Journal::exec(const char* statement) const { sql::exec(db_, statement); }

void Journal::record_command(const std::string& command_id, const std::string& reply_json, const Job* job,
                             bool new_job) {
  exec("BEGIN IMMEDIATE");
  try {
    Statement(db_, "INSERT OR REPLACE INTO commands VALUES (?, ?)").text(1, command_id).text(2, reply_json).step();
    if (job) {
      Statement s(db_, (std::string("INSERT OR REPLACE INTO jobs (") + kJobColumns +
                        ") VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)")
                           .c_str());
      bind_job(s, *job);
      s.step();
      if (new_job) exec("UPDATE meta SET value = value + 1 WHERE key = 'jobs_created'");
    }
    exec("COMMIT");
  } catch (...) {
    exec("ROLLBACK");
    throw;
  }
}

std::optional<std::string> Journal::reply_for(const std::string& command_id) const {
  Statement s(db_, "SELECT reply FROM commands WHERE command_id = ?");
  s.text(1, command_id);
  if (!s.step()) return std::nullopt;
  return s.column_text(0);
}

void Journal::save_progress(const std::vector<const Job*>& jobs,
                            const std::vector<std::pair<std::string, std::string>>& answers) {
  if (jobs.empty() && answers.empty()) return;
  exec("BEGIN IMMEDIATE");
  try {
    Statement s(db_, (std::string("INSERT OR REPLACE INTO jobs (") + kJobColumns +
                      ") VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)")
                         .c_str());
    for (const Job* j : jobs) {
      bind_job(s, *j);
      s.step();
      s.reset();
    }
    Statement answer(db_, "UPDATE handovers SET outcome = ? WHERE request_id = ?");
    for (const auto& [request_id, outcome] : answers) {
      answer.text(1, outcome).text(2, request_id);
      answer.step();
      answer.reset();
    }
    exec("COMMIT");
  } catch (...) {
    exec("ROLLBACK");
    throw;
  }
}

void Journal::record_handover(const HandoverOrder& o) {
  Statement(db_, "INSERT OR IGNORE INTO handovers VALUES (?, ?, ?, ?, ?, ?, '')")
      .text(1, o.request_id)
      .text(2, o.robot)
      .integer(3, o.load ? 1 : 0)
      .text(4, o.place)
      .text(5, o.object_id)
      .text(6, o.job_id)
      .step();
}

Journal::Contents Journal::load() const {
  Contents c;
  {
    Statement s(db_, (std::string("SELECT ") + kJobColumns + " FROM jobs ORDER BY rowid").c_str());
    while (s.step()) {
      Job j;
      j.id = s.column_text(0);
      j.command_id = s.column_text(1);
      j.object = {s.column_text(2), s.column_text(3), s.column_text(4)};
      j.pickup = s.column_text(5);
      j.destination = s.column_text(6);
      j.deadline_s = s.column_real(7);
      j.accepted_at_s = s.column_real(8).value_or(0.0);
      const auto state = job_state_from(s.column_text(9));
      const long long phase = s.column_integer(10);
      if (!state || phase < 0 || phase > static_cast<long long>(JobPhase::returning))
        throw std::runtime_error("journal " + path_ + ": job " + j.id + " has an unknown state '" + s.column_text(9) +
                                 "' or phase " + std::to_string(phase) + "; the file is damaged or from another version");
      j.state = *state;
      j.phase = static_cast<JobPhase>(phase);
      j.robot = s.column_text(11);
      j.reason = s.column_text(12);
      j.estimated_completion_s = s.column_real(13);
      j.object_place = s.column_text(14);
      j.object_carrier = s.column_text(15);
      j.return_to = s.column_text(16);
      j.end_state_after_return = job_state_from(s.column_text(17)).value_or(JobState::cancelled);
      j.return_reason = s.column_text(18);
      c.jobs.push_back(std::move(j));
    }
  }
  {
    // Accepted is not an answer that moves anything: only completed, failed or rejected close it.
    Statement s(db_, "SELECT request_id, robot, load, place, object_id, job_id FROM handovers "
                     "WHERE outcome IN ('', 'accepted') ORDER BY rowid");
    while (s.step())
      c.unanswered.push_back({s.column_text(1), s.column_text(0), s.column_integer(2) != 0, s.column_text(3),
                              s.column_text(4), s.column_text(5)});
  }
  Statement s(db_, "SELECT value FROM meta WHERE key = 'jobs_created'");
  if (s.step()) c.jobs_created = static_cast<int>(s.column_integer(0));
  return c;
}

}  // namespace autonomy::courier
