// Moving walls (door leaves) in the radio model: a closed door between two radios costs one wall,
// the same door open costs nothing, and the leaf counts wherever it is moved to.
#include "simulator/radio/radio_model.hpp"
#include "simulator/radio/test/hand_parameters.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace autonomy::sim::radio {
namespace {

using geometry::Vec2;

using test::hand_parameters;

Vec2 tip_at(const Vec2& hinge, double length, double angle) {
  return hinge + length * Vec2(std::cos(angle), std::sin(angle));
}

TEST(Crosses, OnlyAtPointsInsideBothSegments) {
  EXPECT_TRUE(crosses({0, 0}, {2, 0}, {1, -1}, {1, 1}));
  EXPECT_TRUE(crosses({2, 0}, {0, 0}, {1, 1}, {1, -1}));   // any order
  EXPECT_FALSE(crosses({0, 0}, {2, 0}, {1, 0}, {1, 1}));   // touches the wall's end
  EXPECT_FALSE(crosses({0, 0}, {1, 0}, {1, -1}, {1, 1}));  // ends on the wall
  EXPECT_FALSE(crosses({0, 0}, {2, 0}, {1, 0.5}, {1, 1}));  // passes beside it
  EXPECT_FALSE(crosses({0, 0}, {4, 0}, {1, 0}, {3, 0}));   // runs along it
  EXPECT_FALSE(crosses({0, 0}, {0, 0}, {1, -1}, {1, 1}));  // no path
}

// A door hinged at (5, 4), 1 m wide, closing the doorway x = 5, y in [4, 5]; it opens
// counter-clockwise (angle measured from +y): closed, the leaf points up; open, it points -x.
class DoorBetweenRadios : public ::testing::Test {
 protected:
  const Vec2 hinge{5.0, 4.0};
  RadioParameters p = hand_parameters();
  Vec2 leaf(double opening) const { return tip_at(hinge, 1.0, M_PI / 2 + opening); }
  RadioModel model{p, {}, {}, {MovingWall::door_leaf(hinge, leaf(0.0), 1.0, p, "door A-120")}};
};

TEST_F(DoorBetweenRadios, ClosedDoorIsOneWallAndOpenDoorNone) {
  // Radios 8 m apart through the doorway: distance loss 40.05 + 30 log10(8) = 67.14270 dB.
  const Vec2 a(1.0, 4.5), b(9.0, 4.5);
  const LinkQuality closed = model.link(a, b);
  EXPECT_EQ(closed.crossings, 1);
  EXPECT_NEAR(closed.obstacle_loss_db, 12.0, 1e-12);
  EXPECT_NEAR(closed.signal_dbm, 20.0 - 67.14270 - 12.0, 1e-4);  // -59.1427 dBm

  model.move_wall(0, hinge, leaf(M_PI / 2));  // open: the leaf lies along y = 4, x in [4, 5]
  const LinkQuality open = model.link(a, b);
  EXPECT_EQ(open.crossings, 0);
  EXPECT_EQ(open.obstacle_loss_db, 0.0);
  EXPECT_NEAR(open.signal_dbm, 20.0 - 67.14270, 1e-4);  // -47.1427 dBm
  EXPECT_NEAR(closed.signal_dbm - open.signal_dbm, -12.0, 1e-12);

  // Half open (45 degrees): the leaf from (5, 4) to (4.293, 4.707) still crosses y = 4.5.
  model.move_wall(0, hinge, leaf(M_PI / 4));
  EXPECT_NEAR(model.link(a, b).obstacle_loss_db, 12.0, 1e-12);
  // A path below the open leaf's reach is never affected.
  EXPECT_EQ(model.link({1.0, 3.5}, {9.0, 3.5}).obstacle_loss_db, 0.0);
}

TEST_F(DoorBetweenRadios, OpenLeafCountsWhereItStands) {
  model.move_wall(0, hinge, leaf(M_PI / 2));  // along y = 4, x in [4, 5]
  // A path from the south room crossing the open leaf.
  const LinkQuality l = model.link({4.5, 1.0}, {4.5, 8.0});
  EXPECT_EQ(l.crossings, 1);
  EXPECT_NEAR(l.obstacle_loss_db, 12.0, 1e-12);
}

TEST_F(DoorBetweenRadios, LeavesMustStayInTheirReach) {
  EXPECT_THROW(model.move_wall(0, hinge, {7.0, 4.0}), std::invalid_argument);
  EXPECT_THROW(model.move_wall(1, hinge, leaf(0.0)), std::out_of_range);
  MovingWall w = MovingWall::door_leaf(hinge, {9.0, 9.0}, 1.0, p);
  EXPECT_THROW(RadioModel(p, {}, {}, {w}), std::invalid_argument);
  w = MovingWall::door_leaf(hinge, leaf(0.0), 1.0, p);
  w.loss_db = -1.0;
  EXPECT_THROW(RadioModel(p, {}, {}, {w}), std::invalid_argument);
}

TEST(MovingWalls, IndexedLossEqualsExhaustiveWithBuildingsAndDoors) {
  const RadioParameters p = hand_parameters();
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> pos(0.0, 100.0), ang(0.0, 2 * M_PI);
  std::vector<Attenuator> buildings;
  std::vector<MovingWall> doors;
  for (int i = 0; i < 30; ++i) {
    const double x = pos(rng), y = pos(rng);
    buildings.push_back(Attenuator::obstacle(Shape::rect({x, y, x + 5, y + 4}), p));
    const Vec2 h(pos(rng), pos(rng));
    doors.push_back(MovingWall::door_leaf(h, tip_at(h, 1.2, ang(rng)), 1.2, p));
  }
  RadioModel model(p, buildings, {}, doors);
  for (int round = 0; round < 2; ++round) {
    int crossed = 0;
    for (int i = 0; i < 2000; ++i) {
      const Vec2 a(pos(rng), pos(rng)), b(pos(rng), pos(rng));
      const ObstacleLoss fast = model.obstacle_loss(a, b);
      const ObstacleLoss slow = model.obstacle_loss_exhaustive(a, b);
      ASSERT_EQ(fast.crossings, slow.crossings);
      ASSERT_NEAR(fast.loss_db, slow.loss_db, 1e-9);
      crossed += fast.crossings > 0 ? 1 : 0;
    }
    EXPECT_GT(crossed, 500);
    // Swing every door somewhere else; the index still finds them.
    for (size_t i = 0; i < doors.size(); ++i) model.move_wall(i, doors[i].a, tip_at(doors[i].a, 1.2, ang(rng)));
  }
}

}  // namespace
}  // namespace autonomy::sim::radio
