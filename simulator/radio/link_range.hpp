#pragma once
// How far the radio model can carry a link at all. Every obstacle loss is >= 0 (attenuators,
// rasters and moving walls refuse negative losses), so a link's margin is at most what distance
// alone leaves of the link budget:
//
//   margin_db <= tx_power_dbm - receiver_sensitivity_dbm - distance_loss_db(d)
//
// and distance_loss_db grows with d in both distance models (n > 0, N > 0). The range R solves
// distance_loss_db(R) = tx_power_dbm - receiver_sensitivity_dbm (the link budget B):
//
//   log-distance:  R = d0 * 10^((B - PL(d0)) / (10 n))
//   ITU-R P.1238:  R = 10^((B - 20 log10(f_MHz) - Lf + 28) / N)
//
// A pair farther apart than R is "no link" whatever lies between them, so the simulator never
// computes it. Defaults (20 dBm, -90 dBm, PL(d0) = 40.05 dB, n = 3): B = 110 dB,
// R = 10^(69.95 / 30) = 214.6 m. The returned range is widened by a relative 1e-9 so that the
// rounding of pow and log10 cannot put a connected pair just outside it.
#include "simulator/radio/radio_parameters.hpp"

#include <optional>

namespace autonomy::sim::radio {

// R as above; nothing when not even two radios at the reference distance can connect.
// `params` must pass problem() (RadioModel checks it).
std::optional<double> max_link_range_m(const RadioParameters& params);

}  // namespace autonomy::sim::radio
