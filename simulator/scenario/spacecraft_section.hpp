#pragma once
// The `spacecraft` section of a scenario file (idl/scenario.proto, message Spacecraft): checked
// field by field with file positions, converted to the plain SpacecraftSpec the simulator's
// spacecraft core takes. Kept apart from scenario_loader.cpp, which checks the robot world.
#include "common/config/text_format.hpp"
#include "simulator/scenario/scenario_error.hpp"
#include "simulator/spacecraft/spacecraft_spec.hpp"

#include <optional>
#include <string>
#include <vector>

namespace autonomy::config {
class Spacecraft;
}

namespace autonomy::sim {

// The spec, or nullopt with every problem appended to `errors` (source = `source`).
std::optional<spacecraft::SpacecraftSpec> check_spacecraft_section(
    const config::Spacecraft& file, const configfile::Locator& at, const std::string& source,
    std::vector<ScenarioError>& errors);

}  // namespace autonomy::sim
