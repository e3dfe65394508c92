#pragma once
// The command-line options every process shares. Services add their own to the same CLI::App.
#include <CLI/CLI.hpp>

#include <string>

namespace autonomy::service {

struct ServiceOptions {
  std::string service;         // fixed by the program: "simulator", "behavior", ...
  std::string instance;        // --instance, or --robot for per-robot processes
  int domain = 0;              // --domain, env AUTONOMY_DOMAIN
  std::string config_file;     // --config
  std::string log_level = "info";
  std::string log_dir;         // --log-dir, env AUTONOMY_LOG_DIR
  double heartbeat_period_s = 0.5;
};

enum class InstanceFlag {
  Instance,  // --instance NAME, defaulting to "main"
  Robot,     // --robot ID, required: one process per robot
};

// Registers --domain, --config, --log-level, --log-dir, --heartbeat-period and the instance flag.
void add_service_options(CLI::App& app, ServiceOptions& options, InstanceFlag flag);

// Default log folder when neither --log-dir nor AUTONOMY_LOG_DIR is given.
std::string default_log_dir();

}  // namespace autonomy::service
