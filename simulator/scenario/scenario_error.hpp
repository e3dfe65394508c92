#pragma once
// A problem in a scenario file, located like a compiler diagnostic so editors can jump to it.
#include "common/config/file_error.hpp"

namespace autonomy::sim {

using ScenarioError = configfile::FileError;

}  // namespace autonomy::sim
