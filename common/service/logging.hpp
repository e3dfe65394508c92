#pragma once
// spdlog to the console (stderr) and to <log_dir>/<service>-<instance>.log, installed as the
// default logger so that spdlog::info() anywhere in the process lands in both.
#include "common/service/options.hpp"

#include <string>

namespace autonomy::service {

// Returns the log file's path. Throws std::runtime_error when the folder cannot be created.
std::string setup_logging(const ServiceOptions& options);

}  // namespace autonomy::service
