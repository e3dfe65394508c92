#pragma once
// What a scenario declares besides the World itself: named rooms, places and waypoints, and the
// radio settings. Plain structs, checked by the loader; the node and the services read them.
#include "common/geometry/geometry.hpp"

#include <optional>
#include <string>
#include <vector>

namespace autonomy::sim {

struct RoomSpec {
  std::string name;  // unique, e.g. "A-120"
  std::string kind;  // "office", "hallway", ... (may be empty)
  std::optional<geometry::Rect> bounds;
};

// A named spot in a room (a desk, a table). Extension point: simulator/office attaches people
// and objects to places by name (Scenario fields 12..19 of idl/scenario.proto).
struct PlaceSpec {
  std::string name;
  std::string room;  // a RoomSpec name
  geometry::Vec2 position;
};

struct WaypointSpec {
  std::string name;
  geometry::Vec2 position;
};

struct AttenuatingAreaSpec {
  std::string name;
  std::vector<geometry::Vec2> vertices;  // a simple polygon
  double loss_db_per_m = 0.0;
  double entry_loss_db = 0.0;
};

// The radio numbers as written in the file. Absent values stay empty so the radio model's own
// defaults (simulator/radio/radio_parameters.hpp) apply; the node maps this onto
// radio::RadioParameters and builds the model with the world's obstacles and `areas`.
struct RadioSettings {
  enum class DistanceModel { LogDistance, ItuP1238 };
  std::optional<double> tx_power_dbm;
  std::optional<double> frequency_hz;
  DistanceModel distance_model = DistanceModel::LogDistance;
  std::optional<double> reference_distance_m;
  std::optional<double> reference_loss_db;
  std::optional<double> path_loss_exponent;
  std::optional<double> p1238_power_loss_coefficient;
  std::optional<double> p1238_floor_penetration_db;
  std::optional<double> receiver_sensitivity_dbm;
  std::optional<double> wall_loss_db;
  std::optional<double> inside_loss_db_per_m;
  std::optional<double> good_margin_db;
  std::optional<double> loss_exponent;
  std::optional<double> base_delay_s;
  std::optional<double> per_hop_delay_s;
  std::optional<double> weak_link_delay_s;
  std::optional<double> jitter_s;
  std::vector<AttenuatingAreaSpec> areas;
};

}  // namespace autonomy::sim
