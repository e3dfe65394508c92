#include "simulator/radio/delivery.hpp"

#include <cmath>

namespace autonomy::sim::radio {

namespace {
// How far below a good link the margin is: 0 at good_margin_db and above, 1 at 0 dB.
double weakness(const DeliveryParameters& p, double margin_db) {
  if (margin_db >= p.good_margin_db) return 0.0;
  if (margin_db <= 0.0) return 1.0;
  return 1.0 - margin_db / p.good_margin_db;
}
}  // namespace

double hop_loss_probability(const DeliveryParameters& p, double margin_db) {
  if (margin_db <= 0.0) return 1.0;
  return std::pow(weakness(p, margin_db), p.loss_exponent);
}

double hop_delay_s(const DeliveryParameters& p, double margin_db) {
  return p.per_hop_delay_s + p.weak_link_delay_s * weakness(p, margin_db);
}

DeliveryDecision decide(const DeliveryParameters& p, const std::vector<LinkQuality>& hops,
                        double sent_at_s, std::mt19937_64& rng) {
  DeliveryDecision d;
  if (hops.empty()) return d;
  for (const LinkQuality& hop : hops) {
    if (!hop.connected) return d;
  }
  double delay = p.base_delay_s;
  for (size_t k = 0; k < hops.size(); ++k) {
    const double loss = hop_loss_probability(p, hops[k].margin_db);
    if (uniform01(rng) < loss) {
      d.outcome = DeliveryOutcome::kLost;
      d.lost_at_hop = k;
      return d;
    }
    delay += hop_delay_s(p, hops[k].margin_db);
  }
  if (p.jitter_s > 0.0) delay += p.jitter_s * uniform01(rng);
  d.outcome = DeliveryOutcome::kDelivered;
  d.deliver_at_s = sent_at_s + delay;
  return d;
}

}  // namespace autonomy::sim::radio
