// Cancelling goals, blocking on collisions, goals with their own fields, and constraint sets.
#include "services/behavior/core/constraint_sets.hpp"
#include "services/behavior/core/goal_tracker.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace autonomy::behavior {
namespace {

using geometry::Pose2;
using geometry::Rect;

WorldMap test_world() { return WorldMap{10.0, 8.0, {Rect{4.8, 0.0, 5.2, 6.0}}}; }
OccupancyGrid cancel_test_grid() { return OccupancyGrid(test_world(), 0.1, 0.35); }

std::vector<GoalState> cancel_states(const std::vector<GoalStatus>& changes) {
  std::vector<GoalState> out;
  for (const auto& c : changes) out.push_back(c.state);
  return out;
}

TEST(GoalCancel, CancelActiveGoalEndsItAsCancelled) {
  GoalTracker tracker(cancel_test_grid());
  (void)tracker.set_goal("g1", 8.0, 1.0, 0.2, 0.0);
  EXPECT_EQ(cancel_states(tracker.update(Pose2{1.0, 1.0, 0.0}, 0.0).changes), (std::vector<GoalState>{GoalState::Active}));
  const auto r = tracker.cancel("g1", "operator");
  ASSERT_EQ(r.changes.size(), 1u);
  EXPECT_EQ(r.changes[0].goal_id, "g1");
  EXPECT_EQ(r.changes[0].state, GoalState::Cancelled);
  EXPECT_EQ(r.changes[0].reason, "operator");
  EXPECT_FALSE(tracker.active());
  EXPECT_EQ(tracker.field(), nullptr);
  EXPECT_EQ(tracker.status()->state, GoalState::Cancelled);
  EXPECT_TRUE(is_terminal(GoalState::Cancelled));
  // Nothing follows a cancelled goal.
  EXPECT_TRUE(tracker.update(Pose2{2.0, 1.0, 0.0}, 1.0).changes.empty());
}

// A path planner that finds no path blocks the goal from outside, with its reason; once.
TEST(GoalCancel, BlockEndsThePursuedGoalWithTheGivenReason) {
  GoalTracker tracker(cancel_test_grid());
  EXPECT_TRUE(tracker.block("no path").changes.empty());
  (void)tracker.set_goal("g1", 8.0, 1.0, 0.2, 0.0);
  const auto r = tracker.block("RRTConnect found no path in 0.05 s");
  EXPECT_EQ(cancel_states(r.changes), (std::vector<GoalState>{GoalState::Blocked}));
  EXPECT_EQ(r.changes[0].goal_id, "g1");
  EXPECT_EQ(r.changes[0].reason, "RRTConnect found no path in 0.05 s");
  EXPECT_FALSE(tracker.active());
  EXPECT_TRUE(tracker.block("again").changes.empty());
  EXPECT_TRUE(tracker.update(Pose2{1.0, 1.0, 0.0}, 1.0).changes.empty());
}

TEST(GoalCancel, EmptyIdCancelsWhateverIsPursuedAndAcceptedGoalsToo) {
  GoalTracker tracker(cancel_test_grid());
  (void)tracker.set_goal("g1", 8.0, 1.0, 0.2, 0.0);  // accepted, not yet active
  const auto r = tracker.cancel("", "");
  EXPECT_EQ(cancel_states(r.changes), (std::vector<GoalState>{GoalState::Cancelled}));
  EXPECT_EQ(r.changes[0].reason, "cancelled");
}

TEST(GoalCancel, CancelOfAnotherOrEndedGoalChangesNothing) {
  GoalTracker tracker(cancel_test_grid());
  EXPECT_TRUE(tracker.cancel("nothing", "").changes.empty());
  (void)tracker.set_goal("g1", 8.0, 1.0, 0.2, 0.0);
  EXPECT_TRUE(tracker.cancel("g0", "").changes.empty());
  EXPECT_TRUE(tracker.active());
  (void)tracker.cancel("g1", "");
  EXPECT_TRUE(tracker.cancel("g1", "").changes.empty());  // twice: once only
  // A new goal after a cancel is pursued normally, without a preemption.
  EXPECT_EQ(cancel_states(tracker.set_goal("g2", 2.0, 1.0, 0.2, 2.0).changes), (std::vector<GoalState>{GoalState::Accepted}));
}

TEST(GoalBlocked, CollisionRuleIsOffByDefault) {
  GoalTracker tracker(cancel_test_grid());
  (void)tracker.set_goal("g", 8.0, 1.0, 0.2, 0.0);
  for (double t = 0.0; t < 9.0; t += 0.5) EXPECT_TRUE(tracker.update(Pose2{1.0 + t * 0.1, 1.0, 0.0}, t, true).changes.size() <= 1u);
  EXPECT_TRUE(tracker.active());
}

TEST(GoalBlocked, InCollisionForTheTimeoutBlocksTheGoal) {
  GoalTrackerConfig config;
  config.collision_timeout_s = 1.0;
  GoalTracker tracker(cancel_test_grid(), config);
  (void)tracker.set_goal("g", 8.0, 1.0, 0.2, 0.0);
  (void)tracker.update(Pose2{1.0, 1.0, 0.0}, 0.0, true);
  EXPECT_TRUE(tracker.update(Pose2{1.0, 1.0, 0.0}, 0.5, true).changes.empty());
  EXPECT_TRUE(tracker.update(Pose2{1.0, 1.0, 0.0}, 0.9, false).changes.empty());  // a break resets
  EXPECT_TRUE(tracker.update(Pose2{1.0, 1.0, 0.0}, 1.0, true).changes.empty());
  EXPECT_TRUE(tracker.update(Pose2{1.0, 1.0, 0.0}, 1.5, true).changes.empty());
  const auto r = tracker.update(Pose2{1.0, 1.0, 0.0}, 2.0, true);
  ASSERT_EQ(r.changes.size(), 1u);
  EXPECT_EQ(r.changes[0].state, GoalState::Blocked);
  EXPECT_EQ(r.changes[0].reason, "in collision for 1.0 s, 7.0 m from goal");
}

TEST(GoalTracker, RejectKeepsThePursuedGoal) {
  GoalTracker tracker(cancel_test_grid());
  (void)tracker.set_goal("g1", 8.0, 1.0, 0.2, 0.0);
  const auto r = tracker.reject("g2", 2.0, 1.0, "unknown constraint set 'x'");
  EXPECT_EQ(cancel_states(r.changes), (std::vector<GoalState>{GoalState::Rejected}));
  EXPECT_EQ(r.changes[0].reason, "unknown constraint set 'x'");
  EXPECT_TRUE(tracker.active());
  EXPECT_EQ(r.current->goal_id, "g1");
}

TEST(ConstraintSets, ParseAndNameCanonically) {
  EXPECT_EQ(parse_constraint_set("")->name(), "obstacles");
  EXPECT_EQ(parse_constraint_set("obstacles")->name(), "obstacles");
  EXPECT_EQ(parse_constraint_set("comm")->name(), "obstacles+comm");
  EXPECT_EQ(parse_constraint_set("obstacles+comm+comm+b")->name(), "obstacles+comm+b");
  std::string error;
  EXPECT_FALSE(parse_constraint_set("a++b", &error));
  EXPECT_EQ(error, "constraint set 'a++b' has an empty layer name");
}

TEST(ConstraintSets, LayersBecomeObstaclesAndUnknownOnesAreNamed) {
  const ConstraintLayers known{{"comm_attenuation", {Rect{6.0, 0.0, 7.0, 8.0}}}};
  std::string error;
  const auto world = apply_constraints(test_world(), *parse_constraint_set("comm_attenuation"), known, &error);
  ASSERT_TRUE(world);
  EXPECT_EQ(world->obstacles.size(), 2u);
  // The layer closes the way east: a goal beyond it has no route with the constraint, one without.
  GoalTracker with(OccupancyGrid(*world, 0.1, 0.35));
  (void)with.set_goal("g", 8.0, 7.0, 0.2, 0.0);
  EXPECT_EQ(cancel_states(with.update(Pose2{1.0, 1.0, 0.0}, 0.0).changes), (std::vector<GoalState>{GoalState::Blocked}));

  EXPECT_FALSE(apply_constraints(test_world(), *parse_constraint_set("obstacles+smoke"), known, &error));
  EXPECT_EQ(error,
            "unknown constraint set 'obstacles+smoke': layer 'smoke' is not defined (known layers: obstacles, "
            "comm_attenuation)");
}

TEST(GoalTracker, GoalWithItsOwnFieldUsesIt) {
  GoalTracker tracker(cancel_test_grid());
  const ConstraintLayers known{{"wall2", {Rect{6.0, 0.0, 7.0, 8.0}}}};
  const auto world = apply_constraints(test_world(), *parse_constraint_set("wall2"), known);
  CostToGoField field(OccupancyGrid(*world, 0.1, 0.35), geometry::Vec2(8.0, 7.0));
  (void)tracker.set_goal("g", 8.0, 7.0, 0.2, 0.0, std::move(field));
  EXPECT_EQ(cancel_states(tracker.update(Pose2{1.0, 1.0, 0.0}, 0.0).changes), (std::vector<GoalState>{GoalState::Blocked}));
  // A field on another grid is refused.
  CostToGoField coarse(OccupancyGrid(test_world(), 0.2, 0.35), geometry::Vec2(8.0, 7.0));
  EXPECT_THROW((void)tracker.set_goal("g2", 8.0, 7.0, 0.2, 0.0, std::move(coarse)), std::invalid_argument);
}

}  // namespace
}  // namespace autonomy::behavior
