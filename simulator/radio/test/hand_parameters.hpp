#pragma once
// The radio numbers the tests' hand computations use: the defaults, spelled out.
#include "simulator/radio/radio_parameters.hpp"

namespace autonomy::sim::radio::test {

inline RadioParameters hand_parameters() {
  RadioParameters p;
  p.tx_power_dbm = 20.0;
  p.reference_distance_m = 1.0;
  p.reference_loss_db = 40.05;
  p.path_loss_exponent = 3.0;
  p.receiver_sensitivity_dbm = -90.0;
  p.wall_loss_db = 12.0;
  p.inside_loss_db_per_m = 0.5;
  return p;
}

}  // namespace autonomy::sim::radio::test
