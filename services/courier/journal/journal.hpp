#pragma once
// The courier's journal: every accepted command, its reply, every job's state and every handover
// request, in an SQLite database (WAL, synchronous=FULL) so that nothing accepted is lost. The node
// writes a command's job before it publishes the acceptance, and a handover request before it
// sends it; after kill -9 and a restart, load() gives back the unfinished jobs and the requests
// whose answers never arrived (they are sent again with the same id: the simulator answers a
// repeat with its latest answer, so what the robot carries is reconciled, not guessed).
#include "services/courier/core/execution/courier_executive.hpp"
#include "services/courier/core/knowledge/experience.hpp"

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

struct sqlite3;

namespace autonomy::courier {

class Journal {
 public:
  // Opens or creates the database at `path`. Throws std::runtime_error naming the path and SQLite's
  // message when it cannot (unwritable folder, not a database, newer schema).
  explicit Journal(const std::string& path);
  ~Journal();
  Journal(const Journal&) = delete;
  Journal& operator=(const Journal&) = delete;

  // A command's reply (JSON text) and the job it created or changed, in one transaction;
  // new_job counts it for the next job id.
  void record_command(const std::string& command_id, const std::string& reply_json, const Job* job,
                      bool new_job = true);
  // The reply once given to `command_id`, for a repeated command.
  std::optional<std::string> reply_for(const std::string& command_id) const;

  // Job states and the final answers of handover requests (request id -> completed / failed /
  // rejected) that led to them, in one transaction: a restart never sees an answer without its
  // consequence, or the other way round.
  void save_progress(const std::vector<const Job*>& jobs, const std::vector<std::pair<std::string, std::string>>& answers);
  void record_handover(const HandoverOrder& order);

  // This opening's number (1 for a new journal): goal and request ids carry it, so that ids
  // never repeat across restarts.
  int run() const { return run_; }

  struct Contents {
    std::vector<Job> jobs;                // every job, finished ones too
    std::vector<HandoverOrder> unanswered;  // sent, no final answer journalled
    int jobs_created = 0;                 // for the next job id
  };
  Contents load() const;

  const std::string& path() const { return path_; }

  // What experience taught (experience_store.cpp): saved whole in one transaction, replacing
  // what was there; loaded at start so that learning goes on across runs.
  void save_experience(const Experience& experience);
  Experience load_experience() const;
  // The same from a journal opened read-only (no run counted): `autonomy courier knowledge`.
  // Throws std::runtime_error naming the path when it cannot be read.
  static Experience read_experience(const std::string& path);

 private:
  void exec(const char* sql) const;
  void create_experience_tables() const;
  std::string path_;
  sqlite3* db_ = nullptr;
  int run_ = 0;
};

}  // namespace autonomy::courier
