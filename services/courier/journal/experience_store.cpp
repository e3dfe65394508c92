// The journal's tables of what experience taught (experience.hpp): per person handover
// statistics and presence votes by half hour, per door open/closed votes by half hour, per place
// pair driving times. Counts only: a half hour without votes has no row.
#include <sqlite3.h>

#include "services/courier/journal/journal.hpp"
#include "common/sqlite/statement.hpp"

namespace autonomy::courier {

namespace {

using sql::Statement;

void load_into(sqlite3* db, Experience& e) {
  {
    Statement s(db, "SELECT person, n, mean, m2 FROM learned_handovers");
    while (s.step())
      e.restore_handover(s.column_text(0), {s.column_integer(1), s.column_real(2).value_or(0), s.column_real(3).value_or(0)});
  }
  {
    Statement s(db, "SELECT person, slot, yes, no FROM learned_presence");
    while (s.step())
      e.restore_presence(s.column_text(0), static_cast<int>(s.column_integer(1)), static_cast<int>(s.column_integer(2)),
                         static_cast<int>(s.column_integer(3)));
  }
  {
    Statement s(db, "SELECT door, slot, open, closed FROM learned_doors");
    while (s.step())
      e.restore_door(s.column_text(0), static_cast<int>(s.column_integer(1)), static_cast<int>(s.column_integer(2)),
                     static_cast<int>(s.column_integer(3)));
  }
  Statement s(db, "SELECT from_place, to_place, n, mean, m2 FROM learned_travel");
  while (s.step())
    e.restore_travel(s.column_text(0), s.column_text(1),
                     {s.column_integer(2), s.column_real(3).value_or(0), s.column_real(4).value_or(0)});
}

void save_votes(Statement& s, const std::map<std::string, HalfHourCounts>& all) {
  for (const auto& [who, counts] : all)
    for (int slot = 0; slot < HalfHourCounts::kSlots; ++slot) {
      const auto i = static_cast<std::size_t>(slot);
      if (counts.yes[i] == 0 && counts.no[i] == 0) continue;
      s.text(1, who).integer(2, slot).integer(3, counts.yes[i]).integer(4, counts.no[i]);
      s.step();
      s.reset();
    }
}

}  // namespace

void Journal::create_experience_tables() const {
  exec("CREATE TABLE IF NOT EXISTS learned_handovers (person TEXT PRIMARY KEY, n INTEGER, mean REAL, m2 REAL)");
  exec("CREATE TABLE IF NOT EXISTS learned_presence (person TEXT, slot INTEGER, yes INTEGER, no INTEGER, "
       "PRIMARY KEY (person, slot))");
  exec("CREATE TABLE IF NOT EXISTS learned_doors (door TEXT, slot INTEGER, open INTEGER, closed INTEGER, "
       "PRIMARY KEY (door, slot))");
  exec("CREATE TABLE IF NOT EXISTS learned_travel (from_place TEXT, to_place TEXT, n INTEGER, mean REAL, m2 REAL, "
       "PRIMARY KEY (from_place, to_place))");
}

void Journal::save_experience(const Experience& e) {
  exec("BEGIN IMMEDIATE");
  try {
    for (const char* table : {"learned_handovers", "learned_presence", "learned_doors", "learned_travel"})
      exec((std::string("DELETE FROM ") + table).c_str());
    Statement h(db_, "INSERT INTO learned_handovers VALUES (?, ?, ?, ?)");
    for (const auto& [person, stats] : e.handovers()) {
      h.text(1, person).integer(2, stats.n).real(3, stats.mean).real(4, stats.m2);
      h.step();
      h.reset();
    }
    Statement p(db_, "INSERT INTO learned_presence VALUES (?, ?, ?, ?)");
    save_votes(p, e.presence());
    Statement d(db_, "INSERT INTO learned_doors VALUES (?, ?, ?, ?)");
    save_votes(d, e.doors());
    Statement t(db_, "INSERT INTO learned_travel VALUES (?, ?, ?, ?, ?)");
    for (const auto& [pair, stats] : e.travel()) {
      t.text(1, pair.first).text(2, pair.second).integer(3, stats.n).real(4, stats.mean).real(5, stats.m2);
      t.step();
      t.reset();
    }
    exec("COMMIT");
  } catch (...) {
    exec("ROLLBACK");
    throw;
  }
}

Experience Journal::load_experience() const {
  Experience e;
  load_into(db_, e);
  return e;
}

Experience Journal::read_experience(const std::string& path) {
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
    const std::string why = db ? sqlite3_errmsg(db) : "out of memory";
    sqlite3_close(db);
    throw std::runtime_error("journal " + path + ": " + why);
  }
  Experience e;
  try {
    Statement check(db, "SELECT count(*) FROM sqlite_master WHERE name = 'learned_doors'");
    if (!check.step() || check.column_integer(0) == 0)
      throw std::runtime_error("no learned knowledge in it (a journal of an older courier, or not a journal)");
    load_into(db, e);
  } catch (const std::runtime_error& err) {
    sqlite3_close(db);
    throw std::runtime_error("journal " + path + ": " + err.what());
  }
  sqlite3_close(db);
  return e;
}

}  // namespace autonomy::courier
