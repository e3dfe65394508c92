#pragma once
// Loading scenario files (protobuf text format, schema idl/scenario.proto) at the edge: syntax
// and meaning are both checked here, every problem is reported with its file position, and only
// plain structs go inward. Cores never see protobuf types.
#include "simulator/core/world_spec.hpp"
#include "simulator/office/office_spec.hpp"
#include "simulator/scenario/scenario_content.hpp"
#include "simulator/scenario/scenario_error.hpp"
#include "simulator/scenario/simulation_settings.hpp"
#include "simulator/spacecraft/spacecraft_spec.hpp"

#include <optional>
#include <string>
#include <vector>

namespace autonomy::sim {

struct Scenario {
  WorldSpec world;  // world.name is the scenario name; world.seed == simulation.seed
  SimulationSettings simulation;
  std::vector<RoomSpec> rooms;
  std::vector<PlaceSpec> places;
  std::vector<WaypointSpec> waypoints;
  std::vector<WaypointSpec> parking;  // Scenario.parking: where a fleet's idle couriers wait
  RadioSettings radio;
  // The office (people, objects, loading stations) when the file declares any, checked: its
  // places are the file's rooms (kind room, at the centre of their bounds) and places.
  std::optional<office::OfficeSpec> office;
  // The spacecraft (Scenario.spacecraft) when the file declares one, checked.
  std::optional<spacecraft::SpacecraftSpec> spacecraft;
};

struct [[nodiscard]] ScenarioLoadResult {
  std::optional<Scenario> scenario;  // set exactly when errors is empty
  // A syntax error stops parsing, so it comes alone; otherwise every semantic problem found,
  // ordered by position.
  std::vector<ScenarioError> errors;

  bool ok() const { return errors.empty(); }
  std::string error_text() const;  // one error per line, for logs and stderr
};

// `source_name` names the text in errors (a path, or kBuiltinScenarioSource). Map files are
// read relative to the directory of `source_name` (the working directory when it has none).
ScenarioLoadResult load_scenario_text(const std::string& text, const std::string& source_name);

// Reads `path` and loads it; `path` as given is the source name in errors.
ScenarioLoadResult load_scenario_file(const std::string& path);

}  // namespace autonomy::sim
