#include "simulator/radio/delivery.hpp"
#include "simulator/radio/message_relay.hpp"

#include <gtest/gtest.h>

#include <string>

namespace autonomy::sim::radio {
namespace {

LinkQuality hop(double margin_db) {
  LinkQuality l;
  l.margin_db = margin_db;
  l.connected = margin_db >= 0.0;
  return l;
}

double loss_rate(const DeliveryParameters& p, const std::vector<LinkQuality>& hops, int samples,
                 uint64_t seed) {
  std::mt19937_64 rng(seed);
  int lost = 0;
  for (int i = 0; i < samples; ++i) lost += decide(p, hops, 0.0, rng).delivered() ? 0 : 1;
  return static_cast<double>(lost) / samples;
}

TEST(Delivery, LossCurveByHand) {
  const DeliveryParameters p;  // good at 10 dB, exponent 2
  EXPECT_EQ(hop_loss_probability(p, 25.0), 0.0);
  EXPECT_EQ(hop_loss_probability(p, 10.0), 0.0);
  EXPECT_DOUBLE_EQ(hop_loss_probability(p, 5.0), 0.25);
  EXPECT_DOUBLE_EQ(hop_loss_probability(p, 8.0), 0.04);
  EXPECT_EQ(hop_loss_probability(p, 0.0), 1.0);
  EXPECT_EQ(hop_loss_probability(p, -3.0), 1.0);
  DeliveryParameters linear = p;
  linear.loss_exponent = 1.0;
  EXPECT_DOUBLE_EQ(hop_loss_probability(linear, 5.0), 0.5);
}

TEST(Delivery, DelayGrowsAsTheMarginShrinks) {
  const DeliveryParameters p;
  EXPECT_DOUBLE_EQ(hop_delay_s(p, 30.0), p.per_hop_delay_s);
  EXPECT_DOUBLE_EQ(hop_delay_s(p, 5.0), p.per_hop_delay_s + 0.5 * p.weak_link_delay_s);
  EXPECT_LT(hop_delay_s(p, 8.0), hop_delay_s(p, 2.0));
}

TEST(Delivery, StrongRouteNeverLosesAndDelayIsExact) {
  const DeliveryParameters p;
  std::mt19937_64 rng(1);
  for (int i = 0; i < 10000; ++i) {
    const DeliveryDecision d = decide(p, {hop(20.0), hop(15.0)}, 3.0, rng);
    ASSERT_TRUE(d.delivered());
    ASSERT_DOUBLE_EQ(d.deliver_at_s, 3.0 + p.base_delay_s + 2 * p.per_hop_delay_s);
  }
}

TEST(Delivery, LossRateFollowsTheCurve) {
  const DeliveryParameters p;
  // 20000 samples: the binomial standard deviation is at most 0.0035; allow 5 of them.
  EXPECT_NEAR(loss_rate(p, {hop(5.0)}, 20000, 11), 0.25, 0.0175);
  EXPECT_NEAR(loss_rate(p, {hop(8.0)}, 20000, 12), 0.04, 0.0175);
  EXPECT_NEAR(loss_rate(p, {hop(2.0)}, 20000, 13), 0.64, 0.0175);
  // Two hops at 5 dB: delivered with 0.75^2.
  EXPECT_NEAR(loss_rate(p, {hop(5.0), hop(5.0)}, 20000, 14), 1.0 - 0.5625, 0.0175);
  EXPECT_EQ(loss_rate(p, {hop(0.0)}, 1000, 15), 1.0);
}

TEST(Delivery, NothingCrossesADisconnectedLinkAndNoRandomnessIsUsed) {
  const DeliveryParameters p;
  std::mt19937_64 rng(5);
  const std::mt19937_64 before = rng;
  for (int i = 0; i < 1000; ++i) {
    const DeliveryDecision d = decide(p, {hop(30.0), hop(-0.5)}, 0.0, rng);
    ASSERT_EQ(d.outcome, DeliveryOutcome::kNoRoute);
  }
  EXPECT_EQ(decide(p, {}, 0.0, rng).outcome, DeliveryOutcome::kNoRoute);
  EXPECT_EQ(rng, before);
}

TEST(Delivery, SameSeedSameDecisions) {
  DeliveryParameters p;
  p.jitter_s = 0.005;
  std::mt19937_64 a(42), b(42);
  for (int i = 0; i < 1000; ++i) {
    const DeliveryDecision x = decide(p, {hop(4.0), hop(7.0)}, i * 0.1, a);
    const DeliveryDecision y = decide(p, {hop(4.0), hop(7.0)}, i * 0.1, b);
    ASSERT_EQ(x.outcome, y.outcome);
    ASSERT_EQ(x.deliver_at_s, y.deliver_at_s);
    ASSERT_EQ(x.lost_at_hop, y.lost_at_hop);
  }
}

TEST(Delivery, LostAtTheWeakHop) {
  const DeliveryParameters p;
  std::mt19937_64 rng(8);
  for (int i = 0; i < 200; ++i) {
    const DeliveryDecision d = decide(p, {hop(30.0), hop(0.0), hop(30.0)}, 0.0, rng);
    ASSERT_EQ(d.outcome, DeliveryOutcome::kLost);
    ASSERT_EQ(d.lost_at_hop, 1u);
  }
}

TEST(MessageRelay, ReleasesByDeliveryTimeThenOfferOrder) {
  MessageRelay<std::string> relay;
  relay.push(0.3, "c");
  relay.push(0.1, "a1");
  relay.push(0.2, "b");
  relay.push(0.1, "a2");
  EXPECT_EQ(relay.pending(), 4u);
  EXPECT_EQ(relay.next_due_s(), 0.1);
  EXPECT_TRUE(relay.take_due(0.05).empty());
  auto first = relay.take_due(0.15);
  ASSERT_EQ(first.size(), 2u);
  EXPECT_EQ(first[0].payload, "a1");
  EXPECT_EQ(first[1].payload, "a2");
  auto rest = relay.take_due(1.0);
  ASSERT_EQ(rest.size(), 2u);
  EXPECT_EQ(rest[0].payload, "b");
  EXPECT_EQ(rest[0].deliver_at_s, 0.2);
  EXPECT_EQ(rest[1].payload, "c");
  EXPECT_FALSE(relay.next_due_s().has_value());
}

TEST(MessageRelay, OffersOnlyDeliveredMessages) {
  const DeliveryParameters p;
  std::mt19937_64 rng(2);
  MessageRelay<int> relay;
  EXPECT_FALSE(relay.offer(decide(p, {hop(-1.0)}, 0.0, rng), 1));
  EXPECT_TRUE(relay.offer(decide(p, {hop(30.0)}, 1.0, rng), 2));
  EXPECT_EQ(relay.pending(), 1u);
  EXPECT_TRUE(relay.take_due(1.0).empty());  // still travelling
  auto due = relay.take_due(1.0 + p.base_delay_s + p.per_hop_delay_s);
  ASSERT_EQ(due.size(), 1u);
  EXPECT_EQ(due[0].payload, 2);
}

}  // namespace
}  // namespace autonomy::sim::radio
