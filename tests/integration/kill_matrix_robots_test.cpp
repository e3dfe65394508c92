// The kill matrix's robot sets: demo.set (r1 driven to a goal beyond the wall, as deploy/demo.sh
// sends it) and recon-parallel.set (three robots on their missions across the reconnaissance
// area). Domains and the matrix's rules: kill_matrix.hpp.
#include "tests/integration/kill_matrix.hpp"

namespace autonomy::test {
namespace {

class RobotSetKillTest : public KillMatrixTest {};

TEST_P(RobotSetKillTest, Cell) {
  if (std::string(GetParam().set) == "demo") {
    // The demo's goal, sent once (a command: nobody sends it again), reached in the end.
    Recorder<msg::GoalStatus> statuses(participant(), dds::topics::goal_status);
    dds::Topic<msg::NavGoal> goal_topic(participant(), dds::topics::nav_goal);
    dds::Writer<msg::NavGoal> goals(participant(), goal_topic);
    prepare("demo");
    ASSERT_NO_FATAL_FAILURE(launch());
    ASSERT_TRUE(goals.wait_for_readers(1, kDeadline));
    msg::NavGoal goal{};
    goal.robot_id = "r1";
    goal.goal_id = "demo-1";
    goal.x = 18;
    goal.y = 2;
    goals.write(goal);
    ASSERT_TRUE(step_until("r1 under way to its goal", [&] {
      statuses.poll();
      const auto active = statuses.matching([](const msg::GoalStatus& s) { return s.state == msg::GoalState::Active; });
      return !active.empty() && tick() >= active.front().tick + 40;
    }));
    ASSERT_NO_FATAL_FAILURE(blow());
    if (world_killed()) {
      ASSERT_NO_FATAL_FAILURE(expect_the_set_stopped_with_the_world());
      return;
    }
    auto story = [&] {
      std::string s;
      for (const auto& g : statuses.all())
        s += g.goal_id + " " + msg::to_string(g.state) + " " + g.reason + " @" + std::to_string(g.tick) + "\n";
      return s + launcher_output();
    };
    ASSERT_TRUE(await("the goal ended", [&] {
      statuses.poll();
      return !statuses.matching([](const msg::GoalStatus& s) {
        return s.state != msg::GoalState::Accepted && s.state != msg::GoalState::Active;
      }).empty();
    }, kMission)) << story();
    const auto last = statuses.all().back();
    EXPECT_EQ(last.goal_id, "demo-1");
    EXPECT_EQ(last.state, msg::GoalState::Reached) << story();
    expect_the_set_still_runs();
    return;
  }
  // recon-parallel: each robot's mission finished.
  Recorder<msg::MissionStatus> missions(participant(), dds::topics::mission_status);
  prepare("recon-parallel");
  ASSERT_NO_FATAL_FAILURE(launch());
  ASSERT_TRUE(step_until("the robots a minute into their missions", [&] { return tick() >= 600; }));
  ASSERT_NO_FATAL_FAILURE(blow());
  if (world_killed()) {
    ASSERT_NO_FATAL_FAILURE(expect_the_set_stopped_with_the_world());
    return;
  }
  auto finished = [&](const std::string& robot) {
    return !missions.matching([&](const msg::MissionStatus& m) { return m.robot_id == robot && m.finished; }).empty();
  };
  auto story = [&] {
    std::string s;
    for (const auto& m : missions.all())
      s += m.robot_id + " " + m.event + " " + m.state + " " + m.reason + " @" + std::to_string(m.tick) + "\n";
    return s + launcher_output();
  };
  ASSERT_TRUE(await("the three missions finished", [&] {
    missions.poll();
    return finished("r1") && finished("r2") && finished("r3");
  }, kMission)) << story();
  // None started over: one "started" per robot.
  for (const char* robot : {"r1", "r2", "r3"})
    EXPECT_EQ(missions.matching([&](const msg::MissionStatus& m) { return m.robot_id == robot && m.event == "started"; })
                  .size(),
              1u)
        << robot << "\n" << story();
  expect_the_set_still_runs();
}

INSTANTIATE_TEST_SUITE_P(Sets, RobotSetKillTest,
                         ::testing::Values(Cell{"demo", "", Blow::none, 1},
                                           Cell{"demo", "simulator/main", Blow::kill, 2},
                                           Cell{"demo", "simulator/main", Blow::stop, 3},
                                           Cell{"demo", "behavior/r1", Blow::kill, 4},
                                           Cell{"demo", "behavior/r1", Blow::stop, 5},
                                           Cell{"recon-parallel", "", Blow::none, 38},
                                           Cell{"recon-parallel", "simulator/main", Blow::kill, 39},
                                           Cell{"recon-parallel", "simulator/main", Blow::stop, 40},
                                           Cell{"recon-parallel", "behavior/r1", Blow::kill, 41},
                                           Cell{"recon-parallel", "behavior/r2", Blow::stop, 42},
                                           Cell{"recon-parallel", "behavior/r3", Blow::kill, 43},
                                           Cell{"recon-parallel", "behavior/r1", Blow::stop, 46}),
                         cell_name);

}  // namespace
}  // namespace autonomy::test
