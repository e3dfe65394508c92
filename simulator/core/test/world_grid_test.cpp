// The robot grid (uniform_grid.hpp) must not change what the world does: the same crowd stepped
// with the grid and with the all-pairs reference gives the same poses, contacts, spawn answers
// and range scans, bit for bit.
#include "simulator/core/test/world_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace autonomy::sim::test {
namespace {

// 60 x 40 m with some walls and 150 robots of mixed sizes packed close enough to keep meeting.
WorldSpec grid_test_crowd() {
  WorldSpec spec;
  spec.name = "crowd";
  spec.width = 60.0;
  spec.height = 40.0;
  spec.obstacles = {{20.0, 10.0, 22.0, 30.0}, {40.0, 5.0, 41.0, 20.0}, {5.0, 33.0, 30.0, 34.0}};
  spec.command_timeout_s = 100.0;
  spec.seed = 7;
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> x(1.0, 59.0), y(1.0, 39.0), r(0.2, 0.6);
  int placed = 0;
  for (int k = 0; placed < 150 && k < 5000; ++k) {
    RobotSpec s = robot_spec("g" + std::to_string(placed), Kinematics::Holonomic, x(rng), y(rng));
    s.radius = r(rng);
    s.max_speed = 2.0;
    s.sensors.range.rays = 16;
    s.sensors.range.max_range_m = 6.0;
    s.sensors.range.noise_stddev_m = 0.02;
    bool clear = true;
    for (const auto& o : spec.robots_at_start)
      clear = clear && std::hypot(o.start.x - s.start.x, o.start.y - s.start.y) > o.radius + s.radius + 0.05;
    for (const auto& rect : spec.obstacles) clear = clear && !geometry::circle_overlaps(rect, s.start.position(), s.radius);
    if (!clear) continue;
    spec.robots_at_start.push_back(s);
    ++placed;
  }
  return spec;
}

TEST(WorldGrid, SameMotionContactsAndScansAsAllPairs) {
  const WorldSpec spec = grid_test_crowd();
  ASSERT_EQ(spec.robots_at_start.size(), 150u);
  World with_grid(spec);
  World reference(spec);
  reference.use_all_pairs_reference(true);
  int contacts = 0;
  for (int tick = 0; tick < 150; ++tick) {
    for (World* w : {&with_grid, &reference}) {
      for (const RobotStatus& r : w->robots()) {
        const double phase = 0.07 * tick + static_cast<double>(r.id.size() * 37 + r.id.back()) * 0.61;
        ASSERT_TRUE(w->submit(command(r.id, 1.8 * std::cos(phase), 1.8 * std::sin(phase), 0.3)).accepted);
      }
      w->step(0.1);
    }
    const auto a = with_grid.robots();
    const auto b = reference.robots();
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
      ASSERT_EQ(a[i].pose.x, b[i].pose.x) << a[i].id << " tick " << tick;
      ASSERT_EQ(a[i].pose.y, b[i].pose.y) << a[i].id << " tick " << tick;
      ASSERT_EQ(a[i].in_collision, b[i].in_collision) << a[i].id << " tick " << tick;
      contacts += a[i].in_collision ? 1 : 0;
      if (tick % 10 == 0) {
        const auto sa = with_grid.sense(a[i].id);
        const auto sb = reference.sense(b[i].id);
        ASSERT_TRUE(sa && sb);
        ASSERT_EQ(sa->ranges, sb->ranges) << a[i].id << " tick " << tick;
      }
    }
  }
  EXPECT_GT(contacts, 100);  // the crowd did meet walls and each other

  // Spawning onto a crowd names the same robot (the smallest id overlapped) either way.
  const auto first = with_grid.robots().front();
  const SpawnResult sa = with_grid.spawn("newcomer", geometry::Pose2{first.pose.x, first.pose.y, 0.0});
  const SpawnResult sb = reference.spawn("newcomer", geometry::Pose2{first.pose.x, first.pose.y, 0.0});
  EXPECT_FALSE(sa.accepted);
  EXPECT_EQ(sa.reason, sb.reason);
  // A removed robot is no obstacle any more.
  ASSERT_TRUE(with_grid.remove(first.id));
  EXPECT_TRUE(with_grid.spawn("newcomer", geometry::Pose2{first.pose.x, first.pose.y, 0.0}).accepted);
}

}  // namespace
}  // namespace autonomy::sim::test
