// Links only where they can matter: the range derived from the model (link_range.hpp), the
// connected links found through a grid with early-stopping walks (near_links.hpp), which must be
// exactly the connected links of the full table, and which samples the simulator writes
// (link_changes.hpp).
#include "simulator/radio/connectivity.hpp"
#include "simulator/radio/link_changes.hpp"
#include "simulator/radio/link_range.hpp"
#include "simulator/radio/near_links.hpp"
#include "simulator/radio/test/hand_parameters.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace autonomy::sim::radio {
namespace {

using geometry::Vec2;
using test::hand_parameters;

TEST(LinkRange, IsWhereDistanceAloneUsesUpTheBudget) {
  const RadioParameters p = hand_parameters();
  const double r = *max_link_range_m(p);
  EXPECT_NEAR(r, std::pow(10.0, 69.95 / 30.0), 1e-6);  // 214.6 m
  const RadioModel free_field(p, {});
  EXPECT_TRUE(free_field.link({0, 0}, {r * (1 - 1e-7), 0}).connected);
  EXPECT_FALSE(free_field.link({0, 0}, {r * (1 + 1e-7), 0}).connected);

  RadioParameters itu = p;
  itu.distance_model = DistanceModel::kItuP1238;
  const double ri = *max_link_range_m(itu);
  const RadioModel itu_field(itu, {});
  EXPECT_TRUE(itu_field.link({0, 0}, {0, ri * (1 - 1e-7)}).connected);
  EXPECT_FALSE(itu_field.link({0, 0}, {0, ri * (1 + 1e-7)}).connected);

  RadioParameters deaf = p;
  deaf.receiver_sensitivity_dbm = -10.0;  // budget 30 dB < the 40.05 dB lost at 1 m
  EXPECT_FALSE(max_link_range_m(deaf).has_value());
}

// Buildings (rectangles and rotated boxes) and areas over 600 x 600 m.
std::vector<Attenuator> near_links_city(const RadioParameters& p, int count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> pos(0.0, 600.0), size(5.0, 30.0), angle(0.0, M_PI);
  std::vector<Attenuator> out;
  for (int i = 0; i < count; ++i) {
    const double x = pos(rng), y = pos(rng), w = size(rng), h = size(rng);
    if (i % 4 == 3) {
      out.push_back(Attenuator::area(Shape::rect({x, y, x + w, y + h}), 3.0, 0.4));
    } else if (i % 4 == 2) {
      const double th = angle(rng);
      const Vec2 u(std::cos(th), std::sin(th)), v(-std::sin(th), std::cos(th)), o(x, y);
      out.push_back(Attenuator::obstacle(Shape::polygon({o, o + w * u, o + w * u + h * v, o + h * v}), p));
    } else {
      out.push_back(Attenuator::obstacle(Shape::rect({x, y, x + w, y + h}), p));
    }
  }
  return out;
}

TEST(NearLinks, HoldExactlyTheConnectedLinksOfTheFullTable) {
  const RadioParameters p = hand_parameters();
  std::vector<MovingWall> walls{MovingWall::door_leaf({300, 300}, {301, 300}, 1.0, p, "door")};
  const RadioModel model(p, near_links_city(p, 250, 3), {}, walls);
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> pos(-20.0, 620.0), near(-15.0, 15.0);
  std::vector<Vec2> robots;
  for (int i = 0; i < 220; ++i) robots.emplace_back(pos(rng), pos(rng));
  for (int i = 0; i < 60; ++i) robots.push_back(robots[i] + Vec2(near(rng), near(rng)));  // close pairs
  const LinkTable full = model.table(robots);
  NearLinkTable sparse;
  sparse.update(model, robots);
  ASSERT_EQ(sparse.size(), robots.size());
  EXPECT_LT(sparse.pairs_in_range(), full.pair_count());
  size_t connected = 0;
  for (size_t i = 0; i < robots.size(); ++i) {
    EXPECT_FALSE(sparse.connected(i, i));
    for (size_t j = i + 1; j < robots.size(); ++j) {
      const LinkQuality& f = full.at(i, j);
      const LinkQuality* s = sparse.find(i, j);
      ASSERT_EQ(f.connected, s != nullptr) << i << "-" << j << " at " << f.distance_m << " m";
      ASSERT_EQ(s, sparse.find(j, i));
      if (s == nullptr) continue;
      ++connected;
      EXPECT_EQ(s->signal_dbm, f.signal_dbm);
      EXPECT_EQ(s->margin_db, f.margin_db);
      EXPECT_EQ(s->obstacle_loss_db, f.obstacle_loss_db);
      EXPECT_EQ(s->crossings, f.crossings);
      EXPECT_EQ(s->inside_m, f.inside_m);
    }
  }
  EXPECT_EQ(connected, sparse.links().size());
  EXPECT_GT(connected, 100u);  // not a trivial city

  const Connectivity a(full), b(sparse);
  EXPECT_EQ(a.components(), b.components());
  for (size_t i = 0; i < robots.size(); i += 7) {
    EXPECT_EQ(a.neighbours(i), b.neighbours(i));
    EXPECT_EQ(a.route(0, i), b.route(0, i));
    if (const auto r = b.route(0, i)) {
      const auto fl = route_links(full, *r);
      const auto sl = route_links(sparse, *r);
      ASSERT_EQ(fl.size(), sl.size());
      for (size_t k = 0; k < fl.size(); ++k) EXPECT_EQ(fl[k].signal_dbm, sl[k].signal_dbm);
    }
  }

  // Reuse with fewer robots, then none.
  robots.resize(2);
  sparse.update(model, robots);
  EXPECT_EQ(sparse.size(), 2u);
  EXPECT_EQ(sparse.connected(0, 1), model.link(robots[0], robots[1]).connected);
  sparse.update(model, {});
  EXPECT_EQ(sparse.size(), 0u);
  EXPECT_TRUE(sparse.links().empty());
}

TEST(LinkChanges, NewChangedLostOnceThenSilent) {
  const RadioModel model(hand_parameters(), {});
  const std::vector<std::string> ids{"a", "b", "c"};
  LinkChangeFilter filter;  // 1 dB
  NearLinkTable table;
  std::vector<Vec2> at{{0, 0}, {100, 0}, {1000, 0}};  // a-b connected, c far away
  const auto exact = [&](size_t i, size_t j) { return model.link(at[i], at[j]); };
  const auto update = [&] {
    table.update(model, at);
    return filter.update(ids, table, exact);
  };
  auto samples = update();
  ASSERT_EQ(samples.size(), 1u);  // c's pairs never connected: no samples at all
  EXPECT_EQ(samples[0].robot_a, "a");
  EXPECT_EQ(samples[0].robot_b, "b");
  EXPECT_TRUE(samples[0].quality.connected);
  EXPECT_FALSE(samples[0].lost);

  at[1] = {101, 0};  // 0.13 dB: below the threshold
  EXPECT_TRUE(update().empty());
  at[1] = {110, 0};  // 1.24 dB since the last sample
  samples = update();
  ASSERT_EQ(samples.size(), 1u);
  EXPECT_NEAR(samples[0].quality.signal_dbm, 20.0 - 40.05 - 30.0 * std::log10(110.0), 1e-9);

  at[1] = {400, 0};  // out of range: lost, once, with its exact signal
  samples = update();
  ASSERT_EQ(samples.size(), 1u);
  EXPECT_TRUE(samples[0].lost);
  EXPECT_FALSE(samples[0].quality.connected);
  EXPECT_NEAR(samples[0].quality.signal_dbm, 20.0 - 40.05 - 30.0 * std::log10(400.0), 1e-9);
  EXPECT_TRUE(update().empty());
  EXPECT_EQ(filter.connected_pairs(), 0u);

  at[1] = {900, 0};  // now b-c connect, and a-b again later
  samples = update();
  ASSERT_EQ(samples.size(), 1u);
  EXPECT_EQ(samples[0].robot_a, "b");
  EXPECT_EQ(samples[0].robot_b, "c");
  at[1] = {50, 0};
  samples = update();
  ASSERT_EQ(samples.size(), 2u);  // a-b connected again, b-c lost; ordered by pair
  EXPECT_EQ(samples[0].robot_b, "b");
  EXPECT_TRUE(samples[0].quality.connected);
  EXPECT_EQ(samples[1].robot_a, "b");
  EXPECT_TRUE(samples[1].lost);

  // A robot leaving the world: its pairs are forgotten without a sample.
  const std::vector<std::string> two{"a", "c"};
  std::vector<Vec2> two_at{{0, 0}, {1000, 0}};
  table.update(model, two_at);
  EXPECT_TRUE(filter.update(two, table, [&](size_t i, size_t j) { return model.link(two_at[i], two_at[j]); }).empty());
  EXPECT_THROW(LinkChangeFilter(-1.0), std::invalid_argument);
}

}  // namespace
}  // namespace autonomy::sim::radio
