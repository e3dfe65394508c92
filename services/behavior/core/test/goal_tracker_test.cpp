#include "services/behavior/core/goal_tracker.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace autonomy::behavior {
namespace {

using geometry::Pose2;
using geometry::Rect;

// 10 m x 8 m with a wall [4.8, 5.2] x [0, 6] and a closed box [7, 9] x [5, 7.5] whose inside
// (8, 6.25) is free but unreachable.
OccupancyGrid test_grid() {
  const WorldMap world{10.0,
                       8.0,
                       {Rect{4.8, 0.0, 5.2, 6.0}, Rect{7.0, 5.0, 9.0, 5.2}, Rect{7.0, 7.3, 9.0, 7.5},
                        Rect{7.0, 5.0, 7.2, 7.5}, Rect{8.8, 5.0, 9.0, 7.5}}};
  return OccupancyGrid(world, 0.1, 0.35);
}

std::vector<GoalState> states(const std::vector<GoalStatus>& changes) {
  std::vector<GoalState> out;
  for (const auto& c : changes) out.push_back(c.state);
  return out;
}

TEST(GoalTracker, AcceptedThenActiveThenReachedInOrder) {
  GoalTracker tracker(test_grid());
  EXPECT_FALSE(tracker.status());
  EXPECT_EQ(tracker.field(), nullptr);

  auto r = tracker.set_goal("g1", 2.0, 1.0, 0.2, 0.0);
  ASSERT_EQ(r.changes.size(), 1u);
  EXPECT_EQ(r.changes[0].goal_id, "g1");
  EXPECT_EQ(r.changes[0].state, GoalState::Accepted);
  EXPECT_TRUE(tracker.active());
  ASSERT_NE(tracker.field(), nullptr);
  EXPECT_EQ(tracker.field()->goal(), geometry::Vec2(2.0, 1.0));

  r = tracker.update(Pose2{1.0, 1.0, 0.0}, 0.1);
  ASSERT_EQ(r.changes.size(), 1u);
  EXPECT_EQ(r.changes[0].state, GoalState::Active);
  EXPECT_DOUBLE_EQ(r.changes[0].distance_to_goal, 1.0);

  r = tracker.update(Pose2{1.5, 1.0, 0.0}, 0.6);
  EXPECT_TRUE(r.changes.empty());
  ASSERT_TRUE(r.current);
  EXPECT_EQ(r.current->state, GoalState::Active);
  EXPECT_DOUBLE_EQ(r.current->distance_to_goal, 0.5);

  r = tracker.update(Pose2{1.85, 1.0, 0.0}, 1.0);
  ASSERT_EQ(r.changes.size(), 1u);
  EXPECT_EQ(r.changes[0].state, GoalState::Reached);
  EXPECT_TRUE(r.changes[0].reason.empty());
  EXPECT_FALSE(tracker.active());
  EXPECT_EQ(tracker.field(), nullptr);
  EXPECT_EQ(tracker.status()->state, GoalState::Reached);

  r = tracker.update(Pose2{3.0, 1.0, 0.0}, 2.0);  // after the end nothing more happens
  EXPECT_TRUE(r.changes.empty());
  EXPECT_EQ(r.current->state, GoalState::Reached);
}

// A goal pursued again after a restart (behavior --journal): its Active says why, later
// transitions have their own reasons; a note after activation changes nothing.
TEST(GoalTracker, ResumedGoalsActiveTransitionCarriesTheNote) {
  GoalTracker tracker(test_grid());
  (void)tracker.set_goal("g1", 2.0, 1.0, 0.2, 0.0);
  tracker.note_resumed("resumed after a restart");
  auto r = tracker.update(Pose2{1.0, 1.0, 0.0}, 0.1);
  ASSERT_EQ(r.changes.size(), 1u);
  EXPECT_EQ(r.changes[0].state, GoalState::Active);
  EXPECT_EQ(r.changes[0].reason, "resumed after a restart");
  tracker.note_resumed("too late");
  r = tracker.update(Pose2{1.85, 1.0, 0.0}, 1.0);
  ASSERT_EQ(r.changes.size(), 1u);
  EXPECT_EQ(r.changes[0].state, GoalState::Reached);
  EXPECT_EQ(r.changes[0].reason, "");
  tracker.note_resumed("nothing pursued");
  EXPECT_EQ(tracker.status()->reason, "");
}

TEST(GoalTracker, GoalAlreadyWithinToleranceIsActiveThenReachedInOneUpdate) {
  GoalTracker tracker(test_grid());
  (void)tracker.set_goal("here", 1.0, 1.0, 0.3, 0.0);
  const auto r = tracker.update(Pose2{1.1, 1.1, 0.0}, 0.0);
  EXPECT_EQ(states(r.changes), (std::vector<GoalState>{GoalState::Active, GoalState::Reached}));
}

TEST(GoalTracker, ZeroToleranceMeansTheDefaultAndNegativeIsRejected) {
  GoalTracker tracker(test_grid(), GoalTrackerConfig{0.5});
  (void)tracker.set_goal("g", 2.0, 1.0, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(tracker.tolerance_m(), 0.5);
  const auto negative = tracker.set_goal("h", 2.0, 1.0, -1.0, 0.0);
  ASSERT_EQ(negative.changes.size(), 1u);
  EXPECT_EQ(negative.changes[0].state, GoalState::Rejected);
  EXPECT_EQ(negative.changes[0].reason, "goal tolerance -1.000 m is negative (0 means the controller's default)");
  EXPECT_EQ(tracker.target()->id, "g");  // the pursued goal is untouched
  (void)tracker.set_goal("g", 2.0, 1.0, 0.05, 0.0);
  EXPECT_DOUBLE_EQ(tracker.tolerance_m(), 0.05);
}

TEST(GoalTracker, NewGoalPreemptsTheActiveOne) {
  GoalTracker tracker(test_grid());
  (void)tracker.set_goal("a", 2.0, 1.0, 0.2, 0.0);
  (void)tracker.update(Pose2{1.0, 1.0, 0.0}, 0.1);
  const auto r = tracker.set_goal("b", 3.0, 3.0, 0.2, 0.2);
  ASSERT_EQ(r.changes.size(), 2u);
  EXPECT_EQ(r.changes[0].goal_id, "a");
  EXPECT_EQ(r.changes[0].state, GoalState::Preempted);
  EXPECT_EQ(r.changes[0].reason, "preempted by goal b");
  EXPECT_DOUBLE_EQ(r.changes[0].distance_to_goal, 1.0);
  EXPECT_EQ(r.changes[1].goal_id, "b");
  EXPECT_EQ(r.changes[1].state, GoalState::Accepted);
  EXPECT_EQ(tracker.field()->goal(), geometry::Vec2(3.0, 3.0));  // field recomputed for b
  EXPECT_EQ(states(tracker.update(Pose2{1.0, 1.0, 0.0}, 0.3).changes),
            (std::vector<GoalState>{GoalState::Active}));
}

TEST(GoalTracker, AcceptedGoalCanBePreemptedBeforeItIsActive) {
  GoalTracker tracker(test_grid());
  (void)tracker.set_goal("a", 2.0, 1.0, 0.2, 0.0);
  const auto r = tracker.set_goal("a", 2.5, 1.0, 0.2, 0.0);  // same id: still a new goal
  EXPECT_EQ(states(r.changes), (std::vector<GoalState>{GoalState::Preempted, GoalState::Accepted}));
}

TEST(GoalTracker, RejectionReasons) {
  GoalTracker tracker(test_grid());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto reason = [&](const std::string& id, double x, double y, double tol) {
    const auto r = tracker.set_goal(id, x, y, tol, 0.0);
    EXPECT_EQ(r.changes.size(), 1u);
    EXPECT_EQ(r.changes.back().state, GoalState::Rejected);
    EXPECT_EQ(r.changes.back().goal_id, id);
    return r.changes.back().reason;
  };
  EXPECT_EQ(reason("", 1.0, 1.0, 0.2), "goal id is empty");
  EXPECT_EQ(reason("g", nan, 1.0, 0.2), "goal coordinates are not finite");
  EXPECT_EQ(reason("g", 1.0, inf, 0.2), "goal coordinates are not finite");
  EXPECT_EQ(reason("g", 1.0, 1.0, nan), "goal tolerance is not finite");
  EXPECT_EQ(reason("g", 12.0, 3.0, 0.2), "goal (12.00, 3.00) is outside the world [0, 10.00] x [0, 8.00]");
  EXPECT_EQ(reason("g", 1.0, -0.5, 0.2), "goal (1.00, -0.50) is outside the world [0, 10.00] x [0, 8.00]");
  EXPECT_FALSE(tracker.active());
  EXPECT_EQ(tracker.status()->state, GoalState::Rejected);
}

TEST(GoalTracker, OverlongGoalIdIsRejectedAndEchoedCutToTheLimit) {
  GoalTracker tracker(test_grid());
  const std::string id(100000, 'x');
  const auto r = tracker.set_goal(id, 2.0, 1.0, 0.2, 0.0);
  ASSERT_EQ(r.changes.size(), 1u);
  EXPECT_EQ(r.changes[0].state, GoalState::Rejected);
  EXPECT_EQ(r.changes[0].reason, "goal_id has 100000 bytes, more than 128");
  EXPECT_EQ(r.changes[0].goal_id, std::string(128, 'x'));
  EXPECT_TRUE(tracker.set_goal(std::string(128, 'y'), 2.0, 1.0, 0.2, 0.0).changes[0].state == GoalState::Accepted);
}

TEST(GoalTracker, RejectedGoalLeavesTheActiveOneRunning) {
  GoalTracker tracker(test_grid());
  (void)tracker.set_goal("a", 2.0, 1.0, 0.2, 0.0);
  (void)tracker.update(Pose2{1.0, 1.0, 0.0}, 0.1);
  const auto r = tracker.set_goal("bad", 20.0, 1.0, 0.2, 0.2);
  EXPECT_EQ(states(r.changes), (std::vector<GoalState>{GoalState::Rejected}));
  ASSERT_TRUE(r.current);
  EXPECT_EQ(r.current->goal_id, "a");
  EXPECT_EQ(r.current->state, GoalState::Active);
  EXPECT_TRUE(tracker.active());
}

TEST(GoalTracker, FailsWhenNoProgressForTheStallTime) {
  GoalTracker tracker(test_grid());
  (void)tracker.set_goal("g", 4.2, 1.0, 0.2, 0.0);
  EXPECT_EQ(states(tracker.update(Pose2{1.0, 1.0, 0.0}, 0.0).changes),
            (std::vector<GoalState>{GoalState::Active}));
  for (double t = 0.5; t < 10.0; t += 0.5) {
    // Jitter smaller than the progress threshold is not progress.
    EXPECT_TRUE(tracker.update(Pose2{1.0 + 0.02 * std::sin(t), 1.0, 0.0}, t).changes.empty()) << t;
  }
  const auto r = tracker.update(Pose2{1.0, 1.0, 0.0}, 10.0);
  ASSERT_EQ(r.changes.size(), 1u);
  EXPECT_EQ(r.changes[0].state, GoalState::Blocked);
  EXPECT_EQ(r.changes[0].reason, "no progress for 10.0 s, 3.2 m from goal");
  EXPECT_FALSE(tracker.active());
}

TEST(GoalTracker, StallTimeIsConfigurableAndProgressResetsIt) {
  GoalTrackerConfig config;
  config.stall_timeout_s = 2.5;
  GoalTracker tracker(test_grid(), config);
  (void)tracker.set_goal("g", 4.2, 1.0, 0.2, 0.0);
  double x = 1.0;
  for (double t = 0.0; t < 20.0; t += 1.0) {  // 0.15 m every second: slow but steady
    EXPECT_TRUE(tracker.update(Pose2{x, 1.0, 0.0}, t).changes.size() <= 1u);
    EXPECT_TRUE(tracker.active()) << t;
    x += 0.15;
  }
  (void)tracker.update(Pose2{x, 1.0, 0.0}, 21.0);
  const auto r = tracker.update(Pose2{x, 1.0, 0.0}, 22.5);
  ASSERT_EQ(r.changes.size(), 1u);
  EXPECT_EQ(r.changes[0].reason, "no progress for 2.5 s, 0.2 m from goal");
}

TEST(GoalTracker, GoingAroundAWallCountsAsProgress) {
  GoalTrackerConfig config;
  config.stall_timeout_s = 3.0;
  GoalTracker tracker(test_grid(), config);
  (void)tracker.set_goal("g", 6.0, 1.0, 0.2, 0.0);
  // Up along the wall: the straight-line distance grows, the path left to go shrinks.
  double t = 0.0;
  for (double y = 1.0; y < 6.5; y += 0.25, t += 1.0) {
    (void)tracker.update(Pose2{4.2, y, 0.0}, t);
    ASSERT_TRUE(tracker.active()) << "y = " << y;
  }
}

TEST(GoalTracker, UnreachableGoalFailsOnTheFirstUpdate) {
  GoalTracker tracker(test_grid());
  EXPECT_EQ(states(tracker.set_goal("boxed", 8.0, 6.25, 0.2, 0.0).changes),
            (std::vector<GoalState>{GoalState::Accepted}));
  const auto r = tracker.update(Pose2{1.0, 1.0, 0.0}, 0.1);
  ASSERT_EQ(r.changes.size(), 1u);
  EXPECT_EQ(r.changes[0].state, GoalState::Blocked);
  EXPECT_EQ(r.changes[0].reason, "no route to goal (8.00, 6.25)");
  EXPECT_FALSE(tracker.active());
}

TEST(GoalTracker, GoalInABlockedCellFails) {
  GoalTracker tracker(test_grid());
  (void)tracker.set_goal("in-wall", 5.0, 2.0, 0.2, 0.0);
  EXPECT_FALSE(tracker.field()->has_route_anywhere());
  const auto r = tracker.update(Pose2{1.0, 1.0, 0.0}, 0.1);
  ASSERT_EQ(r.changes.size(), 1u);
  EXPECT_EQ(r.changes[0].reason, "no route to goal (5.00, 2.00)");

  (void)tracker.set_goal("on-border", 0.1, 4.0, 0.2, 1.0);  // within the robot radius of the border
  EXPECT_EQ(tracker.update(Pose2{1.0, 1.0, 0.0}, 1.1).changes.at(0).state, GoalState::Blocked);
}

TEST(GoalTracker, RobotInTheInflationMarginStillHasARoute) {
  GoalTracker tracker(test_grid());
  (void)tracker.set_goal("g", 2.0, 2.0, 0.2, 0.0);
  const auto r = tracker.update(Pose2{4.5, 1.0, 0.0}, 0.0);  // 0.3 m from the wall, cell blocked
  EXPECT_EQ(states(r.changes), (std::vector<GoalState>{GoalState::Active}));
}

TEST(GoalTracker, NonFinitePoseChangesNothing) {
  GoalTracker tracker(test_grid());
  (void)tracker.set_goal("g", 2.0, 1.0, 0.2, 0.0);
  const auto r = tracker.update(Pose2{std::nan(""), 1.0, 0.0}, 0.1);
  EXPECT_TRUE(r.changes.empty());
  EXPECT_EQ(r.current->state, GoalState::Accepted);
}

TEST(GoalTracker, StateNames) {
  EXPECT_STREQ(to_string(GoalState::Preempted), "preempted");
  EXPECT_TRUE(is_terminal(GoalState::Rejected));
  EXPECT_FALSE(is_terminal(GoalState::Active));
}

}  // namespace
}  // namespace autonomy::behavior
