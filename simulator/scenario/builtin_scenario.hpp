#pragma once
// The demo world the simulator runs when no --config is given: deploy/scenarios/demo.pbtxt,
// embedded at build time so the binary needs no files installed beside it.
#include <string_view>

namespace autonomy::sim {

// Source name to pass to load_scenario_text, so errors read "builtin:demo.pbtxt:12:3: ...".
inline constexpr std::string_view kBuiltinScenarioSource = "builtin:demo.pbtxt";

// The text of deploy/scenarios/demo.pbtxt as it was at build time.
std::string_view builtin_default_scenario();

}  // namespace autonomy::sim
