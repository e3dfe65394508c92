// Prints ns-3's propagation losses at a list of distances, with the parameters our radio model
// uses, so simulator/radio/test/ns3_reference_test.cpp can compare against them. Standalone: not
// part of the CMake build (ns-3 is not a project dependency). See README.md for the command.
//
// Models:
// - ns3::LogDistancePropagationLossModel: PL(d) = PL0 + 10 n log10(d / d0), d <= d0 -> PL0.
//   Run with d0 = 1 m, PL0 = 40.05 dB (free space at 2.4 GHz, 1 m) and n = 2, 3.
// - ns3::ItuR1238PropagationLossModel (buildings module): L = 20 log10(f_MHz) + N log10(d) + Lf - 28
//   with N = 30 (office), 28 (residential), 22 (commercial) and Lf = 0 on the same floor.
//   Run at 2.4 GHz, both nodes on the same floor of one building, and one floor apart (office).
#include <ns3/building.h>
#include <ns3/constant-position-mobility-model.h>
#include <ns3/core-module.h>
#include <ns3/itu-r-1238-propagation-loss-model.h>
#include <ns3/mobility-building-info.h>
#include <ns3/propagation-loss-model.h>

#include <cstdio>
#include <vector>

using namespace ns3;

namespace {

const std::vector<double> kDistances = {0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 35.0, 50.0, 100.0, 200.0, 500.0};
constexpr double kTxPowerDbm = 20.0;

Ptr<MobilityModel> node_at(double x, double y, double z, Ptr<Building> building) {
  Ptr<MobilityModel> mm = CreateObject<ConstantPositionMobilityModel>();
  mm->SetPosition(Vector(x, y, z));
  if (building) {
    Ptr<MobilityBuildingInfo> info = CreateObject<MobilityBuildingInfo>(building);
    mm->AggregateObject(info);
    info->MakeConsistent(mm);
  }
  return mm;
}

void log_distance(double exponent) {
  Ptr<LogDistancePropagationLossModel> model = CreateObject<LogDistancePropagationLossModel>();
  model->SetAttribute("Exponent", DoubleValue(exponent));
  model->SetAttribute("ReferenceDistance", DoubleValue(1.0));
  model->SetAttribute("ReferenceLoss", DoubleValue(40.05));
  std::printf("# LogDistancePropagationLossModel n=%.1f d0=1 PL0=40.05 tx=%.1f dBm\n", exponent,
              kTxPowerDbm);
  for (double d : kDistances) {
    Ptr<MobilityModel> a = node_at(0.0, 5.0, 1.5, nullptr);
    Ptr<MobilityModel> b = node_at(d, 5.0, 1.5, nullptr);
    const double rx = model->CalcRxPower(kTxPowerDbm, a, b);
    std::printf("logdistance n=%.1f d=%.1f loss_db=%.6f rx_dbm=%.6f\n", exponent, d,
                kTxPowerDbm - rx, rx);
  }
}

// Each call gets its own building (ns-3 buildings must not overlap): a strip 10 m wide at y0.
void itu_p1238(Building::BuildingType_t type, const char* name, double z_b, double y0) {
  Ptr<Building> building = CreateObject<Building>();
  building->SetBoundaries(Box(-10.0, 1000.0, y0, y0 + 10.0, 0.0, 30.0));
  building->SetBuildingType(type);
  building->SetNFloors(10);  // 3 m per floor: z = 1.5 is floor 1, z = 4.5 is floor 2
  Ptr<ItuR1238PropagationLossModel> model = CreateObject<ItuR1238PropagationLossModel>();
  model->SetAttribute("Frequency", DoubleValue(2.4e9));
  std::printf("# ItuR1238PropagationLossModel %s f=2.4 GHz, z_a=1.5 z_b=%.1f\n", name, z_b);
  for (double d : kDistances) {
    if (d < 1.0) continue;  // P.1238 is defined for d > 1 m; ns-3 does not clamp
    Ptr<MobilityModel> a = node_at(0.0, y0 + 5.0, 1.5, building);
    Ptr<MobilityModel> b = node_at(d, y0 + 5.0, z_b, building);
    const double loss = model->GetLoss(a, b);
    std::printf("p1238 %s z_b=%.1f d=%.1f loss_db=%.6f\n", name, z_b, d, loss);
  }
}

}  // namespace

int main() {
  log_distance(3.0);
  log_distance(2.0);
  itu_p1238(Building::Office, "office", 1.5, 0.0);
  itu_p1238(Building::Residential, "residential", 1.5, 100.0);
  itu_p1238(Building::Office, "office", 4.5, 200.0);
  return 0;
}
