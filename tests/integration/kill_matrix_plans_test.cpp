// The kill matrix's planning sets: planner.set (a plan asked for with `autonomy plan`), ds1.set
// (the DS1-like day: planner, executive, spacecraft) and rover.set (the field survey: planner,
// executive, the rover's behavior). Domains and the matrix's rules: kill_matrix.hpp.
#include "tests/integration/kill_matrix.hpp"
#include "tests/support/executive_watch.hpp"

#include <nlohmann/json.hpp>

namespace autonomy::test {
namespace {

// ---- planner.set: the request outlives its planner ---------------------------------------------

// A job shop the planner proves optimal in about a second here: long enough to be killed in the
// middle of its search, short enough for the cell.
const std::string kJobShop = std::string(AUTONOMY_SOURCE_DIR) + "/services/planner/examples/jobshop/la02";
constexpr int64_t kJobShopOptimum = 655;

class PlannerSetKillTest : public KillMatrixTest {};

TEST_P(PlannerSetKillTest, Cell) {
  clock_used_ = false;  // no world in this set
  prepare("planner");
  ASSERT_NO_FATAL_FAILURE(launch());
  Recorder<msg::PlanningProgress> progress(participant(), dds::topics::planner_progress);
  const std::string plan_json = dir().file("plan.json");
  auto& plan = start("plan", AUTONOMY_AUTONOMY_BIN,
                     {"plan", "--jobshop", kJobShop, "--engine", "discrepancy", "--budget-ms", "8000", "--json",
                      plan_json, "--quiet", "--timeout", "60", "--domain", std::to_string(domain_)},
                     false);
  ASSERT_TRUE(await("the search under way (a first plan found)", [&] { return !progress.poll().empty(); }));
  ASSERT_NO_FATAL_FAILURE(blow());
  const auto ended = plan.wait_for_exit(120s);
  ASSERT_TRUE(ended.has_value()) << plan.log_tail();
  EXPECT_TRUE(ended->exited && ended->code == 0) << ended->describe() << "\n" << plan.log_tail();
  const auto reply = nlohmann::json::parse(read_file(plan_json), nullptr, false);
  ASSERT_FALSE(reply.is_discarded()) << read_file(plan_json);
  // The plan's JSON is protobuf's: 64-bit integers are strings.
  const int64_t makespan = std::stoll(reply.value("makespan", std::string("-1")));
  if (GetParam().blow == Blow::stop) {
    // The budget is wall time (a caller's latency): stopped for 10 s of its 8 s, the planner
    // answers with the best plan it had, which may be above the optimum.
    EXPECT_GE(makespan, kJobShopOptimum);
  } else {
    EXPECT_EQ(makespan, kJobShopOptimum) << read_file(plan_json).substr(0, 400);
  }
  expect_the_set_still_runs();
}

INSTANTIATE_TEST_SUITE_P(Sets, PlannerSetKillTest,
                         ::testing::Values(Cell{"planner", "", Blow::none, 20},
                                           Cell{"planner", "planner/main", Blow::kill, 21},
                                           Cell{"planner", "planner/main", Blow::stop, 22}),
                         cell_name);

// ---- ds1.set and rover.set: the executive's day --------------------------------------------------

class ExecutiveSetKillTest : public KillMatrixTest {
 protected:
  // The set's day with the blow at `blow_tick`; true when the day ended with its report.
  void fly(const std::string& set, int64_t blow_tick) {
    watch_.emplace(participant());
    // The DS1 set's day is 86,400 published ticks (a spacecraft world has no quiet ticks), about a
    // minute of a loaded machine per cell: its cells fly the executive tests' four-hour day.
    prepare(set, [](const std::string& name, const std::string& line) {
      return name == "executive/main" ? replaced(line, "/examples/ds1.pbtxt", "/examples/ds1-4h.pbtxt") : line;
    });
    if (set == "ds1")  // ds1.set flies {run}/ds1.pbtxt: deploy/ds1-demo.sh puts the scenario there
      write_file(set_->file("ds1.pbtxt"), read_file(std::string(AUTONOMY_SOURCE_DIR) + "/deploy/scenarios/ds1.pbtxt"));
    ASSERT_NO_FATAL_FAILURE(launch());
    ASSERT_TRUE(step_until("the day at tick " + std::to_string(blow_tick), [&] { return tick() >= blow_tick; }));
    ASSERT_NO_FATAL_FAILURE(blow());
    if (world_killed()) {
      ASSERT_NO_FATAL_FAILURE(expect_the_set_stopped_with_the_world());
      return;
    }
    ASSERT_TRUE(await("the day finished", [&] {
      watch_->poll();
      return watch_->finished();
    }, kMission)) << watch_->story(false) << "\n" << launcher_output();
    EXPECT_TRUE(std::filesystem::exists(set_->file("report.md")));
    expect_the_set_still_runs();
  }
  std::optional<ExecutiveWatch> watch_;
};

TEST_P(ExecutiveSetKillTest, Cell) {
  const Cell& cell = GetParam();
  if (std::string(cell.set) == "ds1") {
    fly("ds1", 3000);
    if (world_killed() || HasFatalFailure()) return;
    if (killed() && blows("executive/main")) {
      // Killed at 3000 s while the engine thrusts the first arc: the successor safes the
      // spacecraft (engine to standby) before anything else, and from there thrust1 no longer
      // fits before its window closes, nor down1 beside it: both lost, saying why; the rest of
      // the day as without the kill.
      EXPECT_EQ(watch_->lost(), sorted({"down1", "thrust1"})) << watch_->story(false);
      for (const auto& why : watch_->final_status().goals_lost)
        EXPECT_NE(why.find("executive down from "), std::string::npos) << why;
      EXPECT_EQ(watch_->achieved().size(), 14u) << watch_->story(false);
    } else if (GetParam().blow == Blow::stop && blows("planner/main") && !watch_->lost().empty()) {
      // The world goes on while the planner is stopped (it is no lockstep participant) and asks
      // for the next horizon at 6600 s; the executive holds 7200 s for it at most 10 s in all
      // (--plan-hold-s, bounded per outage). Whether the planner is found again within that
      // hold after its 10 s stop depends on how fast the world got there: if not, the day goes
      // on safe, and the second horizon's goals are lost for want of a plan, saying so.
      EXPECT_EQ(watch_->events_where([](const auto& e) {
        return e.kind == "plan_late" && e.text.find("the world goes on with the spacecraft safe") != std::string::npos;
      }).size(), 1u) << watch_->story(false);
      for (const auto& why : watch_->final_status().goals_lost)
        EXPECT_NE(why.find("the mission ended before a plan had it"), std::string::npos) << why;
      EXPECT_EQ(watch_->achieved().size() + watch_->lost().size(), 16u) << watch_->story(false);
    } else {
      EXPECT_TRUE(watch_->lost().empty()) << watch_->story(false);
      EXPECT_EQ(watch_->achieved().size(), 16u) << watch_->story(false);
    }
  } else {
    fly("rover", 60);
    if (world_killed() || HasFatalFailure()) return;
    EXPECT_EQ(watch_->achieved(), sorted({"s1", "s2", "s3", "r1", "r2", "r3", "home"})) << watch_->story(false);
    EXPECT_TRUE(watch_->lost().empty()) << watch_->story(false);
  }
}

INSTANTIATE_TEST_SUITE_P(Sets, ExecutiveSetKillTest,
                         ::testing::Values(Cell{"ds1", "", Blow::none, 23},
                                           Cell{"ds1", "simulator/main", Blow::stop, 24},
                                           Cell{"ds1", "planner/main", Blow::kill, 25},
                                           Cell{"ds1", "planner/main", Blow::stop, 26},
                                           Cell{"ds1", "executive/main", Blow::kill, 27},
                                           Cell{"ds1", "executive/main", Blow::stop, 28},
                                           Cell{"ds1", "simulator/main", Blow::kill, 47},
                                           Cell{"rover", "", Blow::none, 29},
                                           Cell{"rover", "simulator/main", Blow::kill, 30},
                                           Cell{"rover", "simulator/main", Blow::stop, 31},
                                           Cell{"rover", "planner/main", Blow::kill, 32},
                                           Cell{"rover", "planner/main", Blow::stop, 33},
                                           Cell{"rover", "executive/main", Blow::kill, 34},
                                           Cell{"rover", "executive/main", Blow::stop, 35},
                                           Cell{"rover", "behavior/rover", Blow::kill, 36},
                                           Cell{"rover", "behavior/rover", Blow::stop, 37}),
                         cell_name);

}  // namespace
}  // namespace autonomy::test
