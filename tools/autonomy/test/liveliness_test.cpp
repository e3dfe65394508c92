// ProcessTable, LivelinessMonitor and LockstepFeed without DDS: heartbeats folded into one row per process,
// and the silent / heard again / hung / stopped / gone judgement on a clock the test drives.
#include "tools/autonomy/liveliness.hpp"
#include "tools/autonomy/lockstep_feed.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace autonomy::tools {
namespace {

constexpr int64_t kMs = 1'000'000;
constexpr int64_t kS = 1'000'000'000;
using Kind = LivelinessEvent::Kind;

msg::Heartbeat beat(const std::string& service, const std::string& instance, int32_t pid,
                    uint32_t period_ms = 500) {
  msg::Heartbeat b;
  b.service = service;
  b.instance = instance;
  b.host = "h1";
  b.pid = pid;
  b.state = msg::ServiceState::Ready;
  b.period_ms = period_ms;
  return b;
}

dds::Sample<msg::Heartbeat> sample(const msg::Heartbeat& b, dds_instance_handle_t writer, dds_time_t ts) {
  dds::Sample<msg::Heartbeat> s{b};
  s.source_timestamp = ts;
  s.publication_handle = writer;
  return s;
}

dds::Sample<msg::Heartbeat> state_change(const msg::Heartbeat& b, dds_instance_handle_t writer,
                                         dds::InstanceState state) {
  dds::Sample<msg::Heartbeat> s{b};
  s.valid = false;
  s.instance_state = state;
  s.publication_handle = writer;
  return s;
}

std::vector<Kind> kinds(const std::vector<LivelinessEvent>& events) {
  std::vector<Kind> out;
  for (const auto& e : events) out.push_back(e.kind);
  return out;
}

const auto never_gone = [](const ProcessKey&) { return false; };

TEST(ProcessTableTest, TwoProcessesOfOneNameAreTwoRows) {
  ProcessTable table;
  table.update({sample(beat("behavior", "r1", 100), 1, 10), sample(beat("behavior", "r1", 200), 2, 20)}, 0);
  ASSERT_EQ(table.rows().size(), 2u);
  EXPECT_EQ(table.find("behavior", "r1")->last.pid, 200);  // the one that spoke last

  // One of them stops cleanly: only its row is disposed; find() prefers the live one.
  table.update({state_change(beat("behavior", "r1", 0), 2, dds::InstanceState::Disposed)}, 0);
  EXPECT_EQ(table.rows().at({"behavior", "r1", "h1", 200}).state(), "stopped");
  EXPECT_EQ(table.rows().at({"behavior", "r1", "h1", 100}).state(), "ready");
  EXPECT_EQ(table.find("behavior", "r1")->last.pid, 100);

  // No writer left for the name: every row of it is lost.
  table.update({state_change(beat("behavior", "r1", 0), 1, dds::InstanceState::NoWriters)}, 0);
  EXPECT_EQ(table.rows().at({"behavior", "r1", "h1", 100}).state(), "lost");
}

TEST(LivelinessMonitorTest, SilentAfterThreePeriodsThenHeardAgainWithoutHung) {
  ProcessTable table;
  LivelinessMonitor monitor({});
  const auto b = beat("behavior", "r1", 100);
  table.update({sample(b, 1, 1)}, 0);
  const auto heard = monitor.check(table, 0, never_gone);
  ASSERT_EQ(kinds(heard), std::vector<Kind>{Kind::Heard});
  EXPECT_EQ(heard[0].process.pid, 100);
  EXPECT_EQ(heard[0].last.state, msg::ServiceState::Ready);
  EXPECT_TRUE(monitor.check(table, 1500 * kMs, never_gone).empty());  // 3 periods: not yet
  const auto silent = monitor.check(table, 1600 * kMs, never_gone);
  ASSERT_EQ(kinds(silent), std::vector<Kind>{Kind::Silent});
  EXPECT_DOUBLE_EQ(silent[0].silent_s, 1.6);
  EXPECT_EQ(silent[0].process.pid, 100);
  EXPECT_EQ(monitor.silent(table).size(), 1u);
  EXPECT_TRUE(monitor.check(table, 5 * kS, never_gone).empty());  // said once

  table.update({sample(b, 1, 2)}, 6 * kS);
  const auto again = monitor.check(table, 6 * kS, never_gone);
  ASSERT_EQ(kinds(again), std::vector<Kind>{Kind::HeardAgain});
  EXPECT_DOUBLE_EQ(again[0].silent_s, 6.0);
  EXPECT_TRUE(monitor.silent(table).empty());
  EXPECT_TRUE(monitor.check(table, 7 * kS, never_gone).empty());
}

TEST(LivelinessMonitorTest, HungOnceAtItsLimitAndAgainAfterANewSilence) {
  ProcessTable table;
  LivelinessRules rules;
  rules.hang_after_s = 4.0;
  LivelinessMonitor monitor(rules);
  const auto b = beat("simulator", "main", 7);
  table.update({sample(b, 1, 1)}, 0);
  EXPECT_EQ(kinds(monitor.check(table, 2 * kS, never_gone)), (std::vector<Kind>{Kind::Heard, Kind::Silent}));
  EXPECT_TRUE(monitor.check(table, 3999 * kMs, never_gone).empty());
  const auto hung = monitor.check(table, 4 * kS, never_gone);
  ASSERT_EQ(kinds(hung), std::vector<Kind>{Kind::Hung});
  EXPECT_DOUBLE_EQ(hung[0].silent_s, 4.0);
  EXPECT_DOUBLE_EQ(hung[0].limit_s, 4.0);
  EXPECT_TRUE(monitor.check(table, 20 * kS, never_gone).empty());

  table.update({sample(b, 1, 2)}, 21 * kS);
  EXPECT_EQ(kinds(monitor.check(table, 21 * kS, never_gone)), std::vector<Kind>{Kind::HeardAgain});
  EXPECT_EQ(kinds(monitor.check(table, 25 * kS, never_gone)), (std::vector<Kind>{Kind::Silent, Kind::Hung}));
}

TEST(LivelinessMonitorTest, LimitsPerNameAndNeverHungWithZero) {
  ProcessTable table;
  LivelinessRules rules;
  rules.hang_after_s = 0.0;
  rules.hang_after_by_name["behavior/r1"] = 2.0;
  LivelinessMonitor monitor(rules);
  table.update({sample(beat("behavior", "r1", 1), 1, 1), sample(beat("behavior", "r2", 2), 2, 1)}, 0);
  const auto events = monitor.check(table, 60 * kS, never_gone);
  ASSERT_EQ(kinds(events), (std::vector<Kind>{Kind::Heard, Kind::Silent, Kind::Hung, Kind::Heard, Kind::Silent}));
  EXPECT_EQ(events[2].process.instance, "r1");
  EXPECT_EQ(events[4].process.instance, "r2");
}

TEST(LivelinessMonitorTest, ALimitBelowThreePeriodsWaitsForThreePeriods) {
  ProcessTable table;
  LivelinessRules rules;
  rules.hang_after_s = 2.0;
  LivelinessMonitor monitor(rules);
  table.update({sample(beat("planner", "main", 3, 5000), 1, 1)}, 0);
  EXPECT_EQ(kinds(monitor.check(table, 10 * kS, never_gone)), std::vector<Kind>{Kind::Heard});
  EXPECT_EQ(kinds(monitor.check(table, 15001 * kMs, never_gone)), (std::vector<Kind>{Kind::Silent, Kind::Hung}));
}

TEST(LivelinessMonitorTest, LostWriterIsSilentAtOnce) {
  ProcessTable table;
  LivelinessMonitor monitor({});
  const auto b = beat("behavior", "r1", 100);
  table.update({sample(b, 1, 1)}, 0);
  EXPECT_EQ(kinds(monitor.check(table, 0, never_gone)), std::vector<Kind>{Kind::Heard});
  table.update({state_change(b, 1, dds::InstanceState::NoWriters)}, 200 * kMs);
  EXPECT_EQ(kinds(monitor.check(table, 200 * kMs, never_gone)), std::vector<Kind>{Kind::Silent});
}

TEST(LivelinessMonitorTest, CleanStopAndGoneAreSaidOnceAndForgotten) {
  ProcessTable table;
  LivelinessMonitor monitor({});
  const auto a = beat("behavior", "r1", 100), b = beat("behavior", "r2", 200);
  table.update({sample(a, 1, 1), sample(b, 2, 1)}, 0);
  EXPECT_EQ(kinds(monitor.check(table, 100 * kMs, never_gone)), (std::vector<Kind>{Kind::Heard, Kind::Heard}));
  table.update({state_change(a, 1, dds::InstanceState::Disposed)}, 200 * kMs);
  const auto gone = [](const ProcessKey& k) { return k.pid == 200; };
  // r2 is silent and gone: said as gone, not as silent.
  EXPECT_EQ(kinds(monitor.check(table, 3 * kS, gone)), (std::vector<Kind>{Kind::Stopped, Kind::Gone}));
  EXPECT_TRUE(table.rows().empty());
  EXPECT_TRUE(monitor.check(table, 10 * kS, gone).empty());
}

TEST(LivelinessMonitorTest, DuplicateNamesAreJudgedApart) {
  ProcessTable table;
  LivelinessMonitor monitor({});
  const auto old = beat("behavior", "r1", 100), fresh = beat("behavior", "r1", 200);
  table.update({sample(old, 1, 1), sample(fresh, 2, 1)}, 0);
  EXPECT_EQ(kinds(monitor.check(table, 0, never_gone)), (std::vector<Kind>{Kind::Heard, Kind::Heard}));
  table.update({sample(fresh, 2, 2)}, 1 * kS);
  const auto events = monitor.check(table, 2 * kS, never_gone);
  ASSERT_EQ(kinds(events), std::vector<Kind>{Kind::Silent});
  EXPECT_EQ(events[0].process.pid, 100);
}

TEST(LivelinessMonitorTest, WatchesOnlyTheNamedProcesses) {
  ProcessTable table;
  LivelinessRules rules;
  rules.only = {"behavior/r1"};
  LivelinessMonitor monitor(rules);
  table.update({sample(beat("behavior", "r1", 1), 1, 1), sample(beat("behavior", "r2", 2), 2, 1)}, 0);
  const auto events = monitor.check(table, 5 * kS, never_gone);
  // Not yet hung: the default is 10 s.
  ASSERT_EQ(kinds(events), (std::vector<Kind>{Kind::Heard, Kind::Silent}));
  EXPECT_EQ(events[1].process.instance, "r1");
}

msg::SimulatorStatus status_with(std::vector<msg::LockstepChange> changes) {
  msg::SimulatorStatus s;
  s.lockstep_changes = std::move(changes);
  return s;
}

std::vector<uint64_t> numbers(const std::vector<msg::LockstepChange>& changes) {
  std::vector<uint64_t> out;
  for (const auto& c : changes) out.push_back(c.number);
  return out;
}

// Each change once, in order, whichever status samples arrive; a gap beyond the status's list is
// counted; a new simulator run (numbers from 1 again) starts afresh.
TEST(LockstepFeedTest, EachChangeOnceInOrderWithGapsCountedAndNewRunsAfresh) {
  LockstepFeed feed;
  const msg::LockstepChange d1{1, 40, "behavior/r2", true, "it did not acknowledge tick 40"};
  const msg::LockstepChange r2{2, 90, "behavior/r2", false, "it acknowledged tick 90 again"};
  const msg::LockstepChange d3{3, 95, "courier", true, "it did not acknowledge tick 95"};
  uint64_t missed = 99;
  EXPECT_TRUE(feed.take(status_with({}), &missed).empty());
  EXPECT_EQ(missed, 0u);
  EXPECT_EQ(numbers(feed.take(status_with({d1}), &missed)), std::vector<uint64_t>{1});
  EXPECT_TRUE(feed.take(status_with({d1}), &missed).empty());  // the same status again: nothing new
  EXPECT_EQ(numbers(feed.take(status_with({d1, r2, d3}), &missed)), (std::vector<uint64_t>{2, 3}));
  EXPECT_EQ(missed, 0u);
  // 4..9 fell out of the list before this reader saw them.
  const msg::LockstepChange d10{10, 500, "behavior/r1", true, "x"};
  EXPECT_EQ(numbers(feed.take(status_with({d10}), &missed)), std::vector<uint64_t>{10});
  EXPECT_EQ(missed, 6u);
  // A new simulator run.
  EXPECT_EQ(numbers(feed.take(status_with({d1, r2}), &missed)), (std::vector<uint64_t>{1, 2}));
  EXPECT_EQ(describe(d1), "lockstep_dropped behavior/r2 at tick 40: it did not acknowledge tick 40");
  EXPECT_EQ(describe(r2), "lockstep_rejoined behavior/r2 at tick 90: it acknowledged tick 90 again");
}

}  // namespace
}  // namespace autonomy::tools
