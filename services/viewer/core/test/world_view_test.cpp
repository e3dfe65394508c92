// WorldView: what the viewer keeps of the samples it reads.
#include "services/viewer/core/world_view.hpp"

#include <gtest/gtest.h>

namespace autonomy::viewer {
namespace {

msg::RobotState robot_at(const std::string& id, int64_t tick, double x, double y) {
  msg::RobotState s;
  s.robot_id = id;
  s.tick = tick;
  s.sim_time_ns = tick * 50'000'000;
  s.x = x;
  s.y = y;
  return s;
}

msg::CourierJobStatus job(const std::string& id, msg::JobState state, const std::string& phase, int64_t tick) {
  msg::CourierJobStatus j;
  j.job_id = id;
  j.state = state;
  j.phase = phase;
  j.tick = tick;
  return j;
}

TEST(WorldViewTest, TrailKeepsRecentPositionsSpacedAndBounded) {
  WorldViewLimits limits;
  limits.trail_points = 3;
  limits.trail_spacing_m = 0.1;
  WorldView view(limits);
  view.apply(robot_at("r1", 1, 0.0, 0.0));
  view.apply(robot_at("r1", 2, 0.05, 0.0));  // closer than the spacing: no new point
  view.apply(robot_at("r1", 3, 0.2, 0.0));
  view.apply(robot_at("r1", 4, 0.4, 0.0));
  view.apply(robot_at("r1", 5, 0.6, 0.0));
  const RobotView& r = view.robots().at("r1");
  ASSERT_EQ(r.trail.size(), 3u);
  EXPECT_DOUBLE_EQ(r.trail.front().x, 0.2);
  EXPECT_DOUBLE_EQ(r.trail.back().x, 0.6);
  EXPECT_DOUBLE_EQ(r.state.x, 0.6);
  EXPECT_EQ(view.tick(), 5);
}

TEST(WorldViewTest, OlderTickDoesNotMoveTheRobotBack) {
  WorldView view;
  view.apply(robot_at("r1", 10, 5.0, 5.0));
  view.apply(robot_at("r1", 9, 1.0, 1.0));
  EXPECT_DOUBLE_EQ(view.robots().at("r1").state.x, 5.0);
}

TEST(WorldViewTest, RemovedRobotLeavesAndVersionsMove) {
  WorldView view;
  const uint64_t before = view.state_version();
  view.apply(robot_at("r1", 1, 0.0, 0.0));
  EXPECT_GT(view.state_version(), before);
  view.remove_robot("r1");
  EXPECT_TRUE(view.robots().empty());
  const uint64_t map_before = view.map_version();
  view.apply(msg::WorldMap{});
  EXPECT_EQ(view.map_version(), map_before + 1);
}

TEST(WorldViewTest, GoalJoinsPositionAndStatusInEitherOrder) {
  WorldView view;
  msg::GoalStatus status;
  status.robot_id = "r1";
  status.goal_id = "g1";
  status.state = msg::GoalState::Active;
  view.apply(status);  // the status first (a late joiner hears the state topic only)
  view.apply(msg::NavGoal{"r1", "g1", 7.0, 8.0, 0.1, ""});
  const auto& goal = view.robots().at("r1").goal;
  ASSERT_TRUE(goal);
  EXPECT_TRUE(goal->has_position);
  EXPECT_DOUBLE_EQ(goal->x, 7.0);
  EXPECT_TRUE(goal->has_status);
  EXPECT_EQ(goal->state, msg::GoalState::Active);

  status.state = msg::GoalState::Reached;
  view.apply(status);
  EXPECT_EQ(view.robots().at("r1").goal->state, msg::GoalState::Reached);
  EXPECT_DOUBLE_EQ(view.robots().at("r1").goal->y, 8.0);

  view.apply(msg::NavGoal{"r1", "g2", 1.0, 2.0, 0.1, ""});  // a new goal: no status yet
  EXPECT_FALSE(view.robots().at("r1").goal->has_status);
}

TEST(WorldViewTest, JobHistoryRecordsStateAndPhaseChangesOnly) {
  WorldView view;
  view.apply(job("j1", msg::JobState::Queued, "", 1));
  view.apply(job("j1", msg::JobState::Queued, "", 2));  // the same state again (a new estimate)
  view.apply(job("j1", msg::JobState::Underway, "to pickup", 3));
  view.apply(job("j1", msg::JobState::Underway, "to delivery", 9));
  view.apply(job("j1", msg::JobState::Completed, "", 20));
  const JobView& j = view.jobs().at("j1");
  ASSERT_EQ(j.history.size(), 4u);
  EXPECT_EQ(j.history[0].tick, 1);
  EXPECT_EQ(j.history[2].phase, "to delivery");
  EXPECT_EQ(j.history[3].state, msg::JobState::Completed);
  EXPECT_EQ(j.latest.tick, 20);
}

TEST(WorldViewTest, TooManyJobsForgetTheOldestEndedOne) {
  WorldViewLimits limits;
  limits.max_jobs = 2;
  WorldView view(limits);
  view.apply(job("a", msg::JobState::Completed, "", 1));
  view.apply(job("b", msg::JobState::Underway, "", 2));
  view.apply(job("c", msg::JobState::Queued, "", 3));
  EXPECT_EQ(view.jobs().count("a"), 0u);
  EXPECT_EQ(view.jobs().count("b"), 1u);
  EXPECT_EQ(view.jobs().count("c"), 1u);
}

}  // namespace
}  // namespace autonomy::viewer
