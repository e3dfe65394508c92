#include "simulator/radio/radio_model.hpp"
#include "simulator/radio/test/hand_parameters.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace autonomy::sim::radio {
namespace {

using geometry::Rect;
using geometry::Vec2;

using test::hand_parameters;

TEST(FreeSpace, ReferenceLossIsFriisAtOneMetreAnd2400MHz) {
  // 20 log10(4 pi * 1 m * 2.4e9 Hz / 299792458 m/s) = 20 log10(100.6066) = 40.0520
  EXPECT_NEAR(free_space_loss_db(1.0, 2.4e9), 40.0520, 1e-4);
  EXPECT_NEAR(RadioParameters{}.reference_loss_db, free_space_loss_db(1.0, 2.4e9), 0.01);
  // Doubling distance adds 6.02 dB in free space.
  EXPECT_NEAR(free_space_loss_db(2.0, 2.4e9) - free_space_loss_db(1.0, 2.4e9), 6.0206, 1e-4);
}

TEST(RadioModel, LogDistanceByHand) {
  const RadioModel model(hand_parameters(), {});
  // d = 10 m, n = 3: 40.05 + 30 log10(10) = 70.05 dB; 20 dBm - 70.05 = -50.05 dBm.
  const LinkQuality l = model.link({0, 0}, {6, 8});
  EXPECT_DOUBLE_EQ(l.distance_m, 10.0);
  EXPECT_NEAR(l.distance_loss_db, 70.05, 1e-9);
  EXPECT_EQ(l.obstacle_loss_db, 0.0);
  EXPECT_NEAR(l.path_loss_db, 70.05, 1e-9);
  EXPECT_NEAR(l.signal_dbm, -50.05, 1e-9);
  EXPECT_NEAR(l.margin_db, 39.95, 1e-9);
  EXPECT_TRUE(l.connected);
  // d = 100 m: 40.05 + 60 = 100.05 dB; d = 200 m: 40.05 + 30 log10(200) = 109.0809 dB.
  EXPECT_NEAR(model.link({0, 0}, {100, 0}).path_loss_db, 100.05, 1e-9);
  EXPECT_NEAR(model.link({0, 0}, {200, 0}).path_loss_db, 109.0809, 1e-4);
}

TEST(RadioModel, DistanceBelowReferenceClampsToIt) {
  const RadioModel model(hand_parameters(), {});
  EXPECT_NEAR(model.link({0, 0}, {0.5, 0}).path_loss_db, 40.05, 1e-12);
  EXPECT_NEAR(model.link({3, 3}, {3, 3}).path_loss_db, 40.05, 1e-12);
}

TEST(RadioModel, ItuP1238ByHand) {
  RadioParameters p = hand_parameters();
  p.distance_model = DistanceModel::kItuP1238;
  p.p1238_power_loss_coefficient = 30.0;
  const RadioModel model(p, {});
  // 20 log10(2400) + 30 log10(10) + 0 - 28 = 67.6042 + 30 - 28 = 69.6042 dB.
  EXPECT_NEAR(model.distance_loss_db(10.0), 69.6042, 1e-4);
  EXPECT_NEAR(model.distance_loss_db(0.2), model.distance_loss_db(1.0), 1e-12);
}

TEST(RadioModel, BuildingBetweenTheRobotsByHand) {
  // A 10 x 10 m building halfway along a 30 m path: 2 walls and 10 m inside.
  const RadioParameters p = hand_parameters();
  const RadioModel model(p, obstacles_from_rects({{10, 0, 20, 10}}, p));
  const LinkQuality l = model.link({0, 5}, {30, 5});
  const double distance = 40.05 + 30.0 * std::log10(30.0);  // 84.3636
  EXPECT_NEAR(l.distance_loss_db, distance, 1e-9);
  EXPECT_NEAR(l.obstacle_loss_db, 2 * 12.0 + 10 * 0.5, 1e-9);
  EXPECT_EQ(l.crossings, 2);
  EXPECT_NEAR(l.inside_m, 10.0, 1e-9);
  EXPECT_NEAR(l.signal_dbm, 20.0 - distance - 29.0, 1e-9);  // -93.36 dBm
  EXPECT_NEAR(l.margin_db, -3.3636, 1e-4);
  EXPECT_FALSE(l.connected);
  // The same pair beside the building (path along y = 12) is only distance.
  EXPECT_EQ(model.link({0, 12}, {30, 12}).obstacle_loss_db, 0.0);
}

TEST(RadioModel, DeclaredAreaAddsItsLoss) {
  const RadioParameters p = hand_parameters();
  std::vector<Attenuator> a;
  a.push_back(Attenuator::area(Shape::polygon({{10, -5}, {20, -5}, {20, 5}, {10, 5}}), 3.0, 0.4,
                               "parked cars"));
  const RadioModel model(p, std::move(a));
  const LinkQuality l = model.link({0, 0}, {40, 0});
  EXPECT_NEAR(l.obstacle_loss_db, 3.0 + 0.4 * 10.0, 1e-9);
}

TEST(RadioModel, SensitivityThresholdIsInclusive) {
  RadioParameters p = hand_parameters();
  p.receiver_sensitivity_dbm = -50.05;  // exactly the signal at 10 m
  const RadioModel at_edge(p, {});
  const LinkQuality l = at_edge.link({0, 0}, {10, 0});
  EXPECT_NEAR(l.margin_db, 0.0, 1e-9);
  p.receiver_sensitivity_dbm = -50.0;
  EXPECT_FALSE(RadioModel(p, {}).link({0, 0}, {10, 0}).connected);
  p.receiver_sensitivity_dbm = -50.1;
  EXPECT_TRUE(RadioModel(p, {}).link({0, 0}, {10, 0}).connected);
}

TEST(RadioModel, ConnectedMeansNonNegativeMargin) {
  const RadioModel model(hand_parameters(), {});
  // Free-space range with the defaults: 69.95 = 30 log10(d) -> d = 214.7 m.
  EXPECT_TRUE(model.link({0, 0}, {214.0, 0}).connected);
  EXPECT_FALSE(model.link({0, 0}, {216.0, 0}).connected);
}

// A random built-up square kilometre: rectangles, rotated rectangles and a few U-shapes.
std::vector<Attenuator> random_city(const RadioParameters& p, int count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> pos(0.0, 1000.0);
  std::uniform_real_distribution<double> size(8.0, 40.0);
  std::uniform_real_distribution<double> angle(0.0, M_PI);
  std::vector<Attenuator> out;
  for (int i = 0; i < count; ++i) {
    const double x = pos(rng), y = pos(rng), w = size(rng), h = size(rng);
    if (i % 3 == 0) {
      out.push_back(Attenuator::obstacle(Shape::rect({x, y, x + w, y + h}), p));
    } else if (i % 3 == 1) {
      const double th = angle(rng);
      const Vec2 u(std::cos(th), std::sin(th)), v(-std::sin(th), std::cos(th)), o(x, y);
      out.push_back(Attenuator::obstacle(
          Shape::polygon({o, o + w * u, o + w * u + h * v, o + h * v}), p));
    } else {
      out.push_back(Attenuator::area(
          Shape::polygon({{x, y}, {x + 3 * w, y}, {x + 3 * w, y + h}, {x + 2 * w, y + h},
                          {x + 2 * w, y + h / 2}, {x + w, y + h / 2}, {x + w, y + h}, {x, y + h}}),
          2.0, 0.3));
    }
  }
  return out;
}

TEST(RadioModel, IndexFindsWhatTheExhaustiveCheckFinds) {
  const RadioParameters p = hand_parameters();
  for (double cell : {0.0, 7.0, 50.0, 400.0}) {
    const RadioModel model(p, random_city(p, 300, 11), cell);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> pos(-50.0, 1050.0);
    std::uniform_int_distribution<int> grid(0, 20);
    for (int i = 0; i < 3000; ++i) {
      Vec2 a(pos(rng), pos(rng)), b(pos(rng), pos(rng));
      if (i % 3 == 0) {  // on the index's cell lines and along axes
        a = Vec2(grid(rng) * 50.0, grid(rng) * 50.0);
        b = i % 2 ? Vec2(a.x(), grid(rng) * 50.0) : Vec2(grid(rng) * 50.0, grid(rng) * 50.0);
      }
      const ObstacleLoss fast = model.obstacle_loss(a, b);
      const ObstacleLoss slow = model.obstacle_loss_exhaustive(a, b);
      ASSERT_NEAR(fast.loss_db, slow.loss_db, 1e-9) << "cell " << cell << " " << a.transpose()
                                                    << " -> " << b.transpose();
      ASSERT_EQ(fast.crossings, slow.crossings);
      ASSERT_NEAR(fast.inside_m, slow.inside_m, 1e-9);
    }
  }
}

TEST(RadioModel, LinksAreExactlySymmetric) {
  const RadioParameters p = hand_parameters();
  const RadioModel model(p, random_city(p, 200, 5));
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> pos(0.0, 1000.0);
  for (int i = 0; i < 500; ++i) {
    const Vec2 a(pos(rng), pos(rng)), b(pos(rng), pos(rng));
    const LinkQuality ab = model.link(a, b);
    const LinkQuality ba = model.link(b, a);
    ASSERT_EQ(ab.signal_dbm, ba.signal_dbm);
    ASSERT_EQ(ab.obstacle_loss_db, ba.obstacle_loss_db);
    ASSERT_EQ(ab.crossings, ba.crossings);
  }
}

TEST(RadioModel, TableHoldsEveryPairOnce) {
  const RadioParameters p = hand_parameters();
  const RadioModel model(p, random_city(p, 100, 2));
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> pos(0.0, 1000.0);
  std::vector<Vec2> robots;
  for (int i = 0; i < 12; ++i) robots.emplace_back(pos(rng), pos(rng));
  LinkTable table = model.table(robots);
  ASSERT_EQ(table.size(), 12u);
  EXPECT_EQ(table.pair_count(), 66u);
  for (size_t i = 0; i < robots.size(); ++i) {
    EXPECT_FALSE(table.connected(i, i));
    for (size_t j = i + 1; j < robots.size(); ++j) {
      EXPECT_EQ(&table.at(i, j), &table.at(j, i));
      EXPECT_EQ(table.at(i, j).signal_dbm, model.link(robots[i], robots[j]).signal_dbm);
    }
  }
  // Reuse with fewer robots.
  robots.resize(3);
  model.update(robots, table);
  EXPECT_EQ(table.size(), 3u);
  EXPECT_EQ(table.pair_count(), 3u);
  model.update({}, table);
  EXPECT_EQ(table.pair_count(), 0u);
}

TEST(RadioModel, RejectsUnusableParameters) {
  RadioParameters p;
  p.path_loss_exponent = 0.0;
  EXPECT_TRUE(problem(p).has_value());
  EXPECT_THROW(RadioModel(p, {}), std::invalid_argument);
  p = RadioParameters{};
  p.delivery.good_margin_db = 0.0;
  EXPECT_THROW(RadioModel(p, {}), std::invalid_argument);
  EXPECT_FALSE(problem(RadioParameters{}).has_value());
}

}  // namespace
}  // namespace autonomy::sim::radio
