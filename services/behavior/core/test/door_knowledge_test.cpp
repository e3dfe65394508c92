// Door knowledge and replanning around doors seen closed: a wall at x = 5 with two doorways,
// d1 at y = 2 and d2 at y = 8 (each 1.6 m wide, heading north along the wall).
#include "services/behavior/core/door_knowledge.hpp"
#include "services/behavior/core/goal_tracker.hpp"
#include "services/behavior/core/occupancy_grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace autonomy::behavior {
namespace {

using geometry::Rect;
using geometry::Vec2;

WorldMap two_doors() {
  WorldMap w{10.0, 10.0};
  w.obstacles = {Rect{4.9, 0.0, 5.1, 1.2}, Rect{4.9, 2.8, 5.1, 7.2}, Rect{4.9, 8.8, 5.1, 10.0}};
  w.doors = {{"d1", Vec2(5.0, 2.0), 1.6, M_PI / 2}, {"d2", Vec2(5.0, 8.0), 1.6, M_PI / 2}};
  return w;
}

float cost_from(const WorldMap& w, Vec2 from, Vec2 to) {
  const CostToGoField field(OccupancyGrid(w, 0.1, 0.35), to);
  return field.cost_at(from);
}

TEST(DoorKnowledge, DoorsAreOpenUntilSeenClosed) {
  DoorKnowledge k;
  const WorldMap w = two_doors();
  EXPECT_TRUE(k.closed().empty());
  EXPECT_FALSE(k.update({}, 0.0, w));
  EXPECT_TRUE(k.update({{"d1", 0.0}}, 1.0, w));
  EXPECT_EQ(k.closed(), (std::vector<std::string>{"d1"}));
  EXPECT_FALSE(k.update({{"d1", 0.1}}, 2.0, w));  // still closed (0.1 rad): no change
  EXPECT_FALSE(k.update({{"d2", 1.2}}, 2.0, w));  // seen open: it was believed open already
  EXPECT_TRUE(k.update({{"d1", 1.5}}, 3.0, w));   // seen open again
  EXPECT_TRUE(k.closed().empty());
}

TEST(DoorKnowledge, ANoisyAngleBetweenTheThresholdsChangesNothing) {
  DoorKnowledge k;  // closed below 0.35 rad, open above 0.6 rad
  const WorldMap w = two_doors();
  EXPECT_TRUE(k.update({{"d1", 0.3}}, 0.0, w));
  EXPECT_FALSE(k.update({{"d1", 0.4}}, 0.1, w));
  EXPECT_FALSE(k.update({{"d1", 0.55}}, 0.2, w));
  EXPECT_TRUE(k.believed_closed("d1"));
  EXPECT_TRUE(k.update({{"d1", 0.65}}, 0.3, w));
  EXPECT_FALSE(k.update({{"d1", 0.4}}, 0.4, w));  // open stays open until below 0.35
  EXPECT_FALSE(k.believed_closed("d1"));
  EXPECT_THROW(DoorKnowledge({0.5, 0.4, 120.0, 0.2}), std::invalid_argument);
}

TEST(DoorKnowledge, UnknownDoorsAndNonFiniteAnglesAreIgnored) {
  DoorKnowledge k;
  EXPECT_FALSE(k.update({{"d9", 0.0}, {"d1", std::nan("")}}, 0.0, two_doors()));
  EXPECT_TRUE(k.closed().empty());
}

TEST(DoorKnowledge, AClosedDoorUnseenForTheMemoryTimeIsTriedAgain) {
  DoorKnowledge k({0.35, 0.6, 60.0, 0.2});
  const WorldMap w = two_doors();
  k.update({{"d1", 0.0}}, 10.0, w);
  EXPECT_FALSE(k.update({}, 70.0, w));
  EXPECT_TRUE(k.believed_closed("d1"));
  EXPECT_TRUE(k.update({}, 70.1, w));
  EXPECT_FALSE(k.believed_closed("d1"));
}

TEST(DoorKnowledge, ClosedDoorsBlockTheirDoorwayInPlans) {
  DoorKnowledge k;
  const WorldMap w = two_doors();
  const Vec2 west(2.0, 2.0), east(8.0, 2.0);
  const float open = cost_from(k.apply(w), west, east);
  EXPECT_NEAR(open, 6.0, 0.3);  // straight through d1
  k.update({{"d1", 0.0}}, 0.0, w);
  EXPECT_EQ(k.apply(w).polygons.size(), 1u);
  const float detour = cost_from(k.apply(w), west, east);
  EXPECT_GT(detour, 12.0);  // up to d2 and back down
  EXPECT_TRUE(std::isfinite(detour));
  k.update({{"d2", 0.0}}, 0.0, w);
  EXPECT_FALSE(std::isfinite(cost_from(k.apply(w), west, east)));
  EXPECT_EQ(describe_closed_doors(k.closed()), "doors d1, d2 closed");
  EXPECT_EQ(describe_closed_doors({"d1"}), "door d1 closed");
  EXPECT_THROW(DoorKnowledge({0.0, 0.6, 1.0, 1.0}), std::invalid_argument);
}

// d1's leaf (1.6 m, the doorway's width) hinged at (5, 1.2), opening counter-clockwise by `open`
// into the west room: open at a right angle it lies along y = 1.2 from x = 5 to x = 3.4.
WorldMap leaf_door(double open) {
  WorldMap w = two_doors();
  w.doors[0].open_angle = open;
  return w;
}

// A robot on one side of the open leaf plans around its tip to a goal on the other side, for any
// pair of points beside the leaf; a map that does not say where the leaf stands plans through it.
TEST(DoorKnowledge, AnOpenLeafIsAnObstacleInPlans) {
  DoorKnowledge k;
  const WorldMap with = leaf_door(M_PI / 2), without = leaf_door(0.0);
  ASSERT_EQ(k.apply(with).polygons.size(), 1u);
  EXPECT_EQ(k.apply(with).polygons[0].name, "door d1 leaf");
  EXPECT_TRUE(k.apply(without).polygons.empty());
  for (const double x : {4.3, 4.5}) {
    for (const double below : {0.6, 0.75}) {
      const Vec2 south(x, below), north(x, 2.4 - below);
      const float straight = cost_from(k.apply(without), south, north);
      const float around = cost_from(k.apply(with), south, north);
      EXPECT_LT(straight, 1.5) << x << " " << below;
      // Out past the tip (x = 3.4, less the 0.1 margin and the 0.35 inflation) and back: at least
      // 2 x 1 m further (x >= 4.3), less the diagonal steps' savings.
      EXPECT_GT(around, straight + 1.5) << x << " " << below;
      EXPECT_TRUE(std::isfinite(around)) << x << " " << below;
    }
  }
}

TEST(DoorKnowledge, AClosedDoorHasItsSlabAndNoLeaf) {
  DoorKnowledge k;
  const WorldMap w = leaf_door(M_PI / 2);
  EXPECT_TRUE(k.update({{"d1", 0.0}}, 0.0, w));
  const WorldMap applied = k.apply(w);
  ASSERT_EQ(applied.polygons.size(), 1u);
  EXPECT_EQ(applied.polygons[0].name, "door d1");
}

// The leaf stands where the robot last saw it open once that is farther than leaf_moved_rad from
// the belief; sighting noise below that changes nothing (no replan).
TEST(DoorKnowledge, TheLeafMovesToWhereItWasSeen) {
  DoorKnowledge k;  // leaf_moved_rad 0.3
  const WorldMap w = leaf_door(-M_PI / 2);  // clockwise: into the east room along y = 1.2
  EXPECT_DOUBLE_EQ(k.open_leaf_angle(w.doors[0]), M_PI / 2);
  EXPECT_FALSE(k.update({{"d1", 1.45}}, 0.0, w));
  EXPECT_TRUE(k.update({{"d1", 1.0}}, 0.1, w));
  EXPECT_DOUBLE_EQ(k.open_leaf_angle(w.doors[0]), 1.0);
  const auto leaf = k.apply(w).polygons.at(0).vertices;
  // Hinge (5, 1.2), the slab's end 1.6 m (the leaf) + 0.1 m (leaf_tip_margin_m) along heading
  // pi/2 - 1.0 rad.
  const Vec2 tip = 0.5 * (leaf[1] + leaf[2]);
  EXPECT_NEAR(tip.x(), 5.0 + 1.7 * std::cos(M_PI / 2 - 1.0), 1e-9);
  EXPECT_NEAR(tip.y(), 1.2 + 1.7 * std::sin(M_PI / 2 - 1.0), 1e-9);
  EXPECT_FALSE(k.update({{"d1", 1.1}}, 0.2, w));
  EXPECT_THROW(DoorKnowledge({0.35, 0.6, 120.0, 0.2, 0.0}), std::invalid_argument);
  EXPECT_THROW(DoorKnowledge({0.35, 0.6, 120.0, 0.2, 0.05, -1.0}), std::invalid_argument);
  EXPECT_THROW(DoorKnowledge({0.35, 0.6, 120.0, 0.2, 0.05, 0.1, -0.1}), std::invalid_argument);
}

TEST(GoalTrackerReplan, DetourKeepsTheGoalAndNoRouteBlocksItWithTheReason) {
  const WorldMap w = two_doors();
  GoalTracker tracker(OccupancyGrid(w, 0.1, 0.35));
  ASSERT_EQ(tracker.set_goal("g", 8.0, 2.0, 0.2, 0.0).changes.size(), 1u);
  ASSERT_EQ(tracker.update({2.0, 2.0, 0.0}, 0.1).current->state, GoalState::Active);
  EXPECT_EQ(tracker.target()->id, "g");

  DoorKnowledge k;
  k.update({{"d1", 0.0}}, 0.2, w);
  const OccupancyGrid one_closed(k.apply(w), 0.1, 0.35);
  tracker.set_grid(one_closed, describe_closed_doors(k.closed()));
  GoalReport r = tracker.replan(CostToGoField(one_closed, Vec2(8.0, 2.0)), 0.2);
  EXPECT_TRUE(r.changes.empty());
  EXPECT_TRUE(tracker.active());
  EXPECT_GT(tracker.field()->cost_at(Vec2(2.0, 2.0)), 12.0f);  // the detour through d2

  k.update({{"d2", 0.0}}, 0.3, w);
  const OccupancyGrid both_closed(k.apply(w), 0.1, 0.35);
  tracker.set_grid(both_closed, describe_closed_doors(k.closed()));
  r = tracker.replan(CostToGoField(both_closed, Vec2(8.0, 2.0)), 0.3);
  ASSERT_EQ(r.changes.size(), 1u);
  EXPECT_EQ(r.changes[0].state, GoalState::Blocked);
  EXPECT_EQ(r.changes[0].reason, "no route to goal (8.00, 2.00): doors d1, d2 closed");
  EXPECT_FALSE(tracker.active());
  EXPECT_TRUE(tracker.replan(CostToGoField(both_closed, Vec2(8.0, 2.0)), 0.4).changes.empty());
  EXPECT_THROW(tracker.set_grid(OccupancyGrid(w, 0.2, 0.35)), std::invalid_argument);

  // A new goal on the grid with both doors closed: blocked at activation, with the doors named.
  ASSERT_EQ(tracker.set_goal("g2", 8.0, 2.0, 0.2, 0.5).changes.size(), 1u);
  r = tracker.update({2.0, 2.0, 0.0}, 0.6);
  ASSERT_EQ(r.changes.size(), 1u);
  EXPECT_EQ(r.changes[0].reason, "no route to goal (8.00, 2.00): doors d1, d2 closed");
}

}  // namespace
}  // namespace autonomy::behavior
