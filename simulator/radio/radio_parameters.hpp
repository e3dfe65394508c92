#pragma once
// The numbers of the radio model: how strong a transmitter is, how the signal falls off with
// distance, what walls, buildings and declared areas take away, when a receiver still hears it,
// and how message loss and delay grow as a link weakens. Plain data, parsed and checked at the
// edge (scenario files); RadioModel re-checks it with problem() and refuses what it cannot use.
//
// Defaults are for 2.4 GHz 802.11 radios on small ground robots in a built-up area. Sources, so a
// scenario author can tell which numbers are measured and which are judgement:
//
//   tx_power_dbm = 20 dBm      100 mW EIRP, the ETSI EN 300 328 limit for wideband 2.4 GHz data
//                              in Europe; typical 802.11 client radios transmit 15-20 dBm.
//                              It stands for EIRP plus receive antenna gain (0 dBi assumed).
//   frequency_hz = 2.4 GHz     ISM band (802.11 channels 1-13 are 2.412-2.472 GHz).
//   reference_distance_m = 1   the usual d0 for indoor/short-range log-distance models.
//   reference_loss_db = 40.05  free-space (Friis) loss at d0 = 1 m, f = 2.4 GHz:
//                              20 log10(4 pi d0 f / c) = 20 log10(4 pi * 2.4e9 / 299792458)
//                              = 20 log10(100.61) = 40.052 dB (free_space_loss_db(1, 2.4e9)),
//                              rounded to 40.05 as the issue and ns-3 reference runs use.
//   path_loss_exponent = 3.0   ITU-R P.1238 gives a distance power loss coefficient N = 28
//                              (residential) to 30 (office) at 2.4 GHz, i.e. n = N/10 = 2.8-3.0;
//                              Rappaport (Wireless Communications, 2nd ed., Table 4.2) lists
//                              2.7-3.5 for urban areas. 3.0 is also ns-3's LogDistance default.
//   receiver_sensitivity_dbm = -90
//                              typical datasheet sensitivity of 802.11b/g/n radios at the lowest
//                              rates (1 Mb/s DSSS: -95 to -98 dBm; 6 Mb/s OFDM: -88 to -92 dBm).
//                              The standard's minimum for 6 Mb/s OFDM is -82 dBm (IEEE Std
//                              802.11-2016, Table 17-18): use that for a pessimistic team.
//   wall_loss_db = 12 per building boundary crossed
//                              3GPP TR 38.901 (V16, section 7.4.3.1) "low-loss" outdoor-to-indoor
//                              penetration at 2.4 GHz: 5 - 10 log10(0.3*10^(-Lglass/10) +
//                              0.7*10^(-Lconcrete/10)) with Lglass = 2 + 0.2 f = 2.48 dB and
//                              Lconcrete = 5 + 4 f = 14.6 dB (f in GHz): 12.1 dB. Its per-material
//                              figures at 2.4 GHz: wood 5.1 dB, concrete 14.6 dB, IRR glass 23.7 dB;
//                              its "high-loss" building is 23.7 dB. Typical measured 2.4 GHz wall
//                              losses: drywall 2-4 dB, brick 6-12 dB, concrete 10-20 dB.
//   inside_loss_db_per_m = 0.5 3GPP TR 38.901 section 7.4.3.1: indoor loss PL_in = 0.5 d_2D-in dB.
//   P.1238 alternative         ITU-R P.1238 site-general indoor model (see DistanceModel):
//                              N = 30 (office, 2.4 GHz), floor penetration Lf = 0 on one floor
//                              (P.1238 gives 15 + 4 (n - 1) dB for n floors in offices).
//   Delivery curve             see DeliveryParameters.
#include <optional>
#include <string>

namespace autonomy::sim::radio {

// How loss grows with distance (the obstacle and area losses are added to either).
enum class DistanceModel {
  // PL(d) = PL(d0) + 10 n log10(d / d0), d clamped to d0 from below.
  kLogDistance,
  // ITU-R P.1238: L = 20 log10(f_MHz) + N log10(d) + Lf - 28, d in metres clamped to d0 from
  // below (the recommendation is for d > 1 m). Same formula as ns-3's ItuR1238PropagationLossModel.
  kItuP1238,
};

// How message loss and delay follow the margin of each hop (margin = signal - sensitivity).
//   loss probability per hop:  0 at margin >= good_margin_db, else (1 - margin/good)^loss_exponent,
//                              so 1 at margin 0 (the receiver's edge); a disconnected hop
//                              (margin < 0) never carries anything.
//     loss_exponent = 1 is a straight line; 2 (default) keeps loss low until the last few dB,
//     as 802.11 packet error rates do with rate adaptation and retries.
//   delay of a message:        base_delay_s + sum over hops of
//                              (per_hop_delay_s + weak_link_delay_s * (1 - margin/good)) for hops
//                              below good_margin_db (retries and rate fall-back on weak links)
//                              + a uniform draw in [0, jitter_s).
// good_margin_db = 10: the usual 10-20 dB fade margin of 802.11 link planning (typical). The
// delays are typical, not measured: a few ms of medium access and forwarding per hop, tens of ms
// of retries near the edge.
struct DeliveryParameters {
  double good_margin_db = 10.0;
  double loss_exponent = 2.0;
  double base_delay_s = 0.001;
  double per_hop_delay_s = 0.002;
  double weak_link_delay_s = 0.020;
  double jitter_s = 0.0;
};

struct RadioParameters {
  double tx_power_dbm = 20.0;
  double frequency_hz = 2.4e9;
  DistanceModel distance_model = DistanceModel::kLogDistance;
  double reference_distance_m = 1.0;  // d0; shorter distances count as d0 (both models)
  double reference_loss_db = 40.05;   // PL(d0), log-distance only
  double path_loss_exponent = 3.0;    // n, log-distance only
  double p1238_power_loss_coefficient = 30.0;  // N, P.1238 only
  double p1238_floor_penetration_db = 0.0;     // Lf, P.1238 only
  double receiver_sensitivity_dbm = -90.0;
  // Defaults for obstacles (walls, buildings): per boundary crossed and per metre inside.
  // Declared attenuating areas carry their own values (Attenuator::area).
  double wall_loss_db = 12.0;
  double inside_loss_db_per_m = 0.5;
  DeliveryParameters delivery;
};

// Free-space (Friis) path loss in dB at distance_m > 0 and frequency_hz > 0:
// 20 log10(4 pi d f / c).
double free_space_loss_db(double distance_m, double frequency_hz);

// Why `p` cannot be used (first problem found), or nothing. Rejects non-finite numbers,
// non-positive frequency, reference distance or exponents, negative losses, delays, or margins
// that are not positive.
std::optional<std::string> problem(const RadioParameters& p);

}  // namespace autonomy::sim::radio
