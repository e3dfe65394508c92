#include "common/service/options.hpp"

#include <cstdlib>

namespace autonomy::service {

std::string default_log_dir() {
  if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.autonomy/log";
  return "/tmp/autonomy/log";
}

void add_service_options(CLI::App& app, ServiceOptions& o, InstanceFlag flag) {
  if (flag == InstanceFlag::Robot) {
    app.add_option("--robot", o.instance, "Robot id this process drives (one process per robot)")->required();
  } else {
    o.instance = "main";
    app.add_option("--instance", o.instance, "Instance name, to run several copies of this service")
        ->capture_default_str();
  }
  app.add_option("--domain", o.domain, "DDS domain id (0-232)")
      ->envname("AUTONOMY_DOMAIN")
      ->check(CLI::Range(0, 232))
      ->capture_default_str();
  app.add_option("--config", o.config_file, "Configuration file (protobuf text format)")->check(CLI::ExistingFile);
  app.add_option("--log-level", o.log_level, "Log level: trace, debug, info, warn, error")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "critical", "off"}))
      ->capture_default_str();
  o.log_dir = default_log_dir();
  app.add_option("--log-dir", o.log_dir, "Folder for this process's log file")
      ->envname("AUTONOMY_LOG_DIR")
      ->capture_default_str();
  app.add_option("--heartbeat-period", o.heartbeat_period_s, "Seconds between heartbeats")
      ->check(CLI::Range(0.01, 60.0))
      ->capture_default_str();
}

}  // namespace autonomy::service
