#pragma once
// What the courier reads from a scenario file (idl/scenario.proto text, through the simulator's
// loader so that errors carry file:line:column): its office knowledge (places, people and their
// hours, objects where they were put, loading stations, the day clock), the floor the executive
// navigates (place positions, rooms, the door of each room), the static map for travel times,
// and the courier robots. Door scripts, random doors and anything else that is the world's truth
// stay unread: the courier learns doors from its robots' sightings.
#include "services/behavior/core/world_map.hpp"
#include "services/courier/core/execution/floor.hpp"
#include "services/courier/core/knowledge/office_knowledge.hpp"

#include <optional>
#include <string>
#include <vector>

namespace autonomy::courier {

struct CourierRobotSpec {
  std::string id;
  int capacity = 1;
  double radius_m = 0.3;
  double max_speed_mps = 0.5;
};

struct CourierOffice {
  OfficeKnowledge knowledge;
  Floor floor;
  behavior::WorldMap map;
  std::vector<CourierRobotSpec> robots;  // the scenario's robots of kind "courier"
  CourierRobotSpec attach_defaults;      // body and limits of a robot attached by id only
};

struct [[nodiscard]] CourierOfficeResult {
  std::optional<CourierOffice> office;
  std::string error;  // the loader's file:line:column messages, or what the office lacks
  bool ok() const { return office.has_value(); }
};

CourierOfficeResult load_courier_office(const std::string& scenario_path);

}  // namespace autonomy::courier
