#pragma once
// Whether a team message sent over a route of links arrives, and when: the simulator's stand-in
// for a lossy, slow wireless network (the kernel has no netem, so delay is applied here).
// The curves are in DeliveryParameters (radio_parameters.hpp).
//
// Deterministic: all randomness comes from the std::mt19937_64 passed in, turned into uniform
// numbers by the bits (not std::uniform_real_distribution, whose output differs between standard
// libraries). decide() draws exactly one number per hop it tries (it stops at the first lost hop)
// and one more for jitter when jitter_s > 0 and the message is delivered.
#include "simulator/radio/radio_model.hpp"
#include "simulator/radio/radio_parameters.hpp"

#include <cstddef>
#include <random>
#include <vector>

namespace autonomy::sim::radio {

// Probability that one hop with this margin loses a message: 1 below 0 dB (disconnected) and at
// 0 dB, falling to 0 at good_margin_db and above.
double hop_loss_probability(const DeliveryParameters& p, double margin_db);
// Delay one hop adds: per_hop_delay_s plus the weak-link term below good_margin_db.
double hop_delay_s(const DeliveryParameters& p, double margin_db);

enum class DeliveryOutcome {
  kDelivered,
  kNoRoute,  // empty route, or a hop that is not connected: nothing is sent, nothing drawn
  kLost,     // a hop lost it (see lost_at_hop)
};

struct DeliveryDecision {
  DeliveryOutcome outcome = DeliveryOutcome::kNoRoute;
  double deliver_at_s = 0.0;  // when delivered: sent_at_s + delay
  size_t lost_at_hop = 0;     // when lost: index of the hop that lost it
  bool delivered() const { return outcome == DeliveryOutcome::kDelivered; }
};

// A message sent at sent_at_s along `hops` (route_links of a Connectivity::route).
[[nodiscard]] DeliveryDecision decide(const DeliveryParameters& p,
                                      const std::vector<LinkQuality>& hops, double sent_at_s,
                                      std::mt19937_64& rng);

// Uniform in [0, 1) from the top 53 bits of one draw.
inline double uniform01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

}  // namespace autonomy::sim::radio
