// Our distance models against ns-3's. The constants below came from ns-3 3.37 (Debian 12
// libns3-dev 3.37-2), printed by simulator/radio/reference/ns3_reference.cpp built with the
// command in simulator/radio/reference/README.md:
//   LogDistancePropagationLossModel: Exponent 3 and 2, ReferenceDistance 1 m, ReferenceLoss 40.05.
//   ItuR1238PropagationLossModel: Frequency 2.4e9, both nodes in one building (office N = 30,
//   residential N = 28), same floor; and office one floor apart (3 m up: ns-3 uses the 3-D
//   distance sqrt(d^2 + 9) and Lf = 15 dB).
#include "simulator/radio/radio_model.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace autonomy::sim::radio {
namespace {

struct Row {
  double distance_m;
  double ns3_loss_db;
};

constexpr Row kLogDistanceN3[] = {
    {0.5, 40.050000},   {1.0, 40.050000},  {2.0, 49.080900},   {5.0, 61.019100},
    {10.0, 70.050000},  {20.0, 79.080900}, {35.0, 86.372041},  {50.0, 91.019100},
    {100.0, 100.050000}, {200.0, 109.080900}, {500.0, 121.019100}};
constexpr Row kLogDistanceN2[] = {
    {0.5, 40.050000},  {1.0, 40.050000},  {2.0, 46.070600},  {5.0, 54.029400},
    {10.0, 60.050000}, {20.0, 66.070600}, {35.0, 70.931361}, {50.0, 74.029400},
    {100.0, 80.050000}, {200.0, 86.070600}, {500.0, 94.029400}};
constexpr Row kP1238Office[] = {
    {1.0, 39.604225},  {2.0, 48.635125},  {5.0, 60.573325},   {10.0, 69.604225},
    {20.0, 78.635125}, {35.0, 85.926266}, {50.0, 90.573325},  {100.0, 99.604225},
    {200.0, 108.635125}, {500.0, 120.573325}};
constexpr Row kP1238Residential[] = {
    {1.0, 39.604225},  {2.0, 48.033065},  {5.0, 59.175385},   {10.0, 67.604225},
    {20.0, 76.033065}, {35.0, 82.838130}, {50.0, 87.175385},  {100.0, 95.604225},
    {200.0, 104.033065}, {500.0, 115.175385}};
// Horizontal distance d; the nodes are also 3 m apart vertically (one floor).
constexpr Row kP1238OfficeOneFloorApart[] = {
    {1.0, 69.604225},  {2.0, 71.313375},  {5.0, 77.576409},   {10.0, 85.165622},
    {20.0, 93.780074}, {35.0, 100.973952}, {50.0, 105.596735}, {100.0, 114.610085},
    {200.0, 123.636590}, {500.0, 135.573559}};

constexpr double kTxPowerDbm = 20.0;

template <size_t N>
void expect_matches(const RadioModel& model, const Row (&rows)[N], double vertical_m,
                    double tolerance_db) {
  for (const Row& r : rows) {
    const double d = std::hypot(r.distance_m, vertical_m);
    const LinkQuality l = model.link({0.0, 0.0}, {d, 0.0});
    EXPECT_NEAR(l.path_loss_db, r.ns3_loss_db, tolerance_db) << "d = " << r.distance_m;
    EXPECT_NEAR(l.signal_dbm, kTxPowerDbm - r.ns3_loss_db, tolerance_db) << "d = " << r.distance_m;
  }
}

RadioParameters log_distance(double exponent) {
  RadioParameters p;
  p.tx_power_dbm = kTxPowerDbm;
  p.reference_distance_m = 1.0;
  p.reference_loss_db = 40.05;
  p.path_loss_exponent = exponent;
  return p;
}

RadioParameters p1238(double coefficient, double floor_db) {
  RadioParameters p;
  p.tx_power_dbm = kTxPowerDbm;
  p.frequency_hz = 2.4e9;
  p.distance_model = DistanceModel::kItuP1238;
  p.p1238_power_loss_coefficient = coefficient;
  p.p1238_floor_penetration_db = floor_db;
  return p;
}

TEST(Ns3Reference, LogDistanceMatchesWithinOneHundredthOfADecibel) {
  expect_matches(RadioModel(log_distance(3.0), {}), kLogDistanceN3, 0.0, 0.01);
  expect_matches(RadioModel(log_distance(2.0), {}), kLogDistanceN2, 0.0, 0.01);
}

TEST(Ns3Reference, ItuP1238MatchesWithinOneHundredthOfADecibel) {
  expect_matches(RadioModel(p1238(30.0, 0.0), {}), kP1238Office, 0.0, 0.01);
  expect_matches(RadioModel(p1238(28.0, 0.0), {}), kP1238Residential, 0.0, 0.01);
  expect_matches(RadioModel(p1238(30.0, 15.0), {}), kP1238OfficeOneFloorApart, 3.0, 0.01);
}

TEST(Ns3Reference, DefaultsAreTheLogDistanceRunWithExponentThree) {
  // Our defaults are the ns-3 run's parameters: the n = 3 column is what a scenario gets.
  expect_matches(RadioModel(RadioParameters{}, {}), kLogDistanceN3, 0.0, 0.01);
}

}  // namespace
}  // namespace autonomy::sim::radio
