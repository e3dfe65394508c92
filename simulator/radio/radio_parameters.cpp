#include "simulator/radio/radio_parameters.hpp"

#include <cmath>

namespace autonomy::sim::radio {

namespace {
constexpr double kSpeedOfLightMps = 299792458.0;
}

double free_space_loss_db(double distance_m, double frequency_hz) {
  return 20.0 * std::log10(4.0 * M_PI * distance_m * frequency_hz / kSpeedOfLightMps);
}

std::optional<std::string> problem(const RadioParameters& p) {
  const auto finite = [](double v) { return std::isfinite(v); };
  if (!finite(p.tx_power_dbm)) return "tx_power_dbm must be finite";
  if (!finite(p.frequency_hz) || p.frequency_hz <= 0.0) return "frequency_hz must be positive";
  if (!finite(p.reference_distance_m) || p.reference_distance_m <= 0.0) {
    return "reference_distance_m must be positive";
  }
  if (!finite(p.reference_loss_db)) return "reference_loss_db must be finite";
  if (!finite(p.path_loss_exponent) || p.path_loss_exponent <= 0.0) {
    return "path_loss_exponent must be positive";
  }
  if (!finite(p.p1238_power_loss_coefficient) || p.p1238_power_loss_coefficient <= 0.0) {
    return "p1238_power_loss_coefficient must be positive";
  }
  if (!finite(p.p1238_floor_penetration_db) || p.p1238_floor_penetration_db < 0.0) {
    return "p1238_floor_penetration_db must be >= 0";
  }
  if (!finite(p.receiver_sensitivity_dbm)) return "receiver_sensitivity_dbm must be finite";
  if (!finite(p.wall_loss_db) || p.wall_loss_db < 0.0) return "wall_loss_db must be >= 0";
  if (!finite(p.inside_loss_db_per_m) || p.inside_loss_db_per_m < 0.0) {
    return "inside_loss_db_per_m must be >= 0";
  }
  const DeliveryParameters& d = p.delivery;
  if (!finite(d.good_margin_db) || d.good_margin_db <= 0.0) {
    return "delivery.good_margin_db must be positive";
  }
  if (!finite(d.loss_exponent) || d.loss_exponent <= 0.0) {
    return "delivery.loss_exponent must be positive";
  }
  for (const auto& [value, name] :
       {std::pair{d.base_delay_s, "delivery.base_delay_s"},
        std::pair{d.per_hop_delay_s, "delivery.per_hop_delay_s"},
        std::pair{d.weak_link_delay_s, "delivery.weak_link_delay_s"},
        std::pair{d.jitter_s, "delivery.jitter_s"}}) {
    if (!finite(value) || value < 0.0) return std::string(name) + " must be >= 0";
  }
  return std::nullopt;
}

}  // namespace autonomy::sim::radio
