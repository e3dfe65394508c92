#pragma once
// Loading mission files (protobuf text format, schema idl/mission.proto) at the edge: syntax and
// meaning are both checked here, every problem is reported with its file position, and only a
// plain MissionSpec goes inward. The executor never sees protobuf types.
//
// Checked: duplicate or empty names (states, plan sets, layers, teammates), the initial state and
// every transition target exist, gains and distances are >= 0 / > 0 as documented in the proto,
// each trigger has its parameters (a timeout's seconds, a contact trigger's known teammate, an
// area's shape), at_goal only in go_to states, plan sets start from "obstacles" and name defined
// layers, blend gains only for BLENDED and one per layer, stop states have no transitions.
#include "common/config/file_error.hpp"
#include "services/behavior/core/mission/mission_spec.hpp"

#include <optional>
#include <string>
#include <vector>

namespace autonomy::behavior {

// A problem in a mission file, located like a compiler diagnostic.
using MissionError = configfile::FileError;

struct [[nodiscard]] MissionLoadResult {
  std::optional<MissionSpec> mission;  // set exactly when errors is empty
  // A syntax error stops parsing, so it comes alone; otherwise every semantic problem found,
  // ordered by position.
  std::vector<MissionError> errors;

  bool ok() const { return errors.empty(); }
  std::string error_text() const;  // one error per line
};

MissionLoadResult load_mission_text(const std::string& text, const std::string& source_name);
// Reads `path` and loads it; `path` as given is the source name in errors.
MissionLoadResult load_mission_file(const std::string& path);

}  // namespace autonomy::behavior
