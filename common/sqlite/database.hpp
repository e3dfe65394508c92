#pragma once
// The services' journals (the courier's accepted commands, the executive's flight) keep what they
// accepted in SQLite: opened in WAL mode with synchronous=FULL, so that a commit survives a
// kill -9 of the writer, and written in short transactions. Header-only; link SQLite::SQLite3.
#include <sqlite3.h>

#include <stdexcept>
#include <string>

namespace autonomy::sql {

// Runs one statement without results; throws std::runtime_error with SQLite's message.
inline void exec(sqlite3* db, const char* sql) {
  char* error = nullptr;
  if (sqlite3_exec(db, sql, nullptr, nullptr, &error) != SQLITE_OK) {
    const std::string why = error ? error : "unknown error";
    sqlite3_free(error);
    throw std::runtime_error(why);
  }
}

// Opens or creates the database at `path` for journalling. Throws std::runtime_error naming the
// path and SQLite's message (unwritable folder, not a database).
inline sqlite3* open_journal(const std::string& path) {
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) != SQLITE_OK) {
    const std::string why = db ? sqlite3_errmsg(db) : "out of memory";
    sqlite3_close(db);
    throw std::runtime_error("journal " + path + ": " + why);
  }
  try {
    exec(db, "PRAGMA journal_mode=WAL");
    exec(db, "PRAGMA synchronous=FULL");
  } catch (const std::runtime_error& e) {
    sqlite3_close(db);
    throw std::runtime_error("journal " + path + ": " + e.what());
  }
  return db;
}

// The meta table every journal has (key -> integer): the schema version, refused when newer than
// `schema_version`, and the number of openings, counted and returned (1 for a new journal).
inline int count_opening(sqlite3* db, int schema_version) {
  exec(db, "CREATE TABLE IF NOT EXISTS meta (key TEXT PRIMARY KEY, value INTEGER NOT NULL)");
  sqlite3_stmt* read = nullptr;
  const auto value_of = [&](const char* key) -> long long {
    const std::string sql = std::string("SELECT value FROM meta WHERE key = '") + key + "'";
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &read, nullptr) != SQLITE_OK) throw std::runtime_error(sqlite3_errmsg(db));
    const long long v = sqlite3_step(read) == SQLITE_ROW ? sqlite3_column_int64(read, 0) : -1;
    sqlite3_finalize(read);
    return v;
  };
  const long long version = value_of("schema");
  if (version > schema_version)
    throw std::runtime_error("schema " + std::to_string(version) + " is newer than " + std::to_string(schema_version));
  exec(db, ("INSERT OR IGNORE INTO meta VALUES ('schema', " + std::to_string(schema_version) + "), ('runs', 0)").c_str());
  exec(db, "UPDATE meta SET value = value + 1 WHERE key = 'runs'");
  return static_cast<int>(value_of("runs"));
}

// `write()` inside BEGIN IMMEDIATE .. COMMIT; rolled back when it throws.
template <class Write>
void in_transaction(sqlite3* db, Write&& write) {
  exec(db, "BEGIN IMMEDIATE");
  try {
    write();
    exec(db, "COMMIT");
  } catch (...) {
    exec(db, "ROLLBACK");
    throw;
  }
}

}  // namespace autonomy::sql
