#include "simulator/radio/link_range.hpp"

#include <cmath>

namespace autonomy::sim::radio {

std::optional<double> max_link_range_m(const RadioParameters& p) {
  constexpr double kRoundingWidening = 1e-9;  // relative
  const double budget_db = p.tx_power_dbm - p.receiver_sensitivity_dbm;
  double range_m = 0.0;
  switch (p.distance_model) {
    case DistanceModel::kItuP1238:
      range_m = std::pow(10.0, (budget_db - 20.0 * std::log10(p.frequency_hz / 1e6) -
                                p.p1238_floor_penetration_db + 28.0) /
                                   p.p1238_power_loss_coefficient);
      break;
    case DistanceModel::kLogDistance:
      range_m = p.reference_distance_m *
                std::pow(10.0, (budget_db - p.reference_loss_db) / (10.0 * p.path_loss_exponent));
      break;
  }
  // Below d0 the loss stays at its d0 value: if that is already beyond the budget, nothing links.
  if (!(range_m * (1.0 + kRoundingWidening) >= p.reference_distance_m)) return std::nullopt;
  return range_m * (1.0 + kRoundingWidening);
}

}  // namespace autonomy::sim::radio
