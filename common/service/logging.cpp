#include "common/service/logging.hpp"

#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <filesystem>
#include <memory>
#include <stdexcept>

namespace autonomy::service {

std::string setup_logging(const ServiceOptions& o) {
  std::error_code ec;
  std::filesystem::create_directories(o.log_dir, ec);
  if (ec) throw std::runtime_error("cannot create log folder " + o.log_dir + ": " + ec.message());
  const std::string path = o.log_dir + "/" + o.service + "-" + o.instance + ".log";

  auto console = std::make_shared<spdlog::sinks::stderr_color_sink_mt>();
  auto file = std::make_shared<spdlog::sinks::basic_file_sink_mt>(path, /*truncate=*/false);
  auto logger = std::make_shared<spdlog::logger>(o.service + "/" + o.instance, spdlog::sinks_init_list{console, file});
  logger->set_pattern("%Y-%m-%dT%H:%M:%S.%e %^%-5l%$ [%n] %v");
  logger->set_level(spdlog::level::from_str(o.log_level));
  logger->flush_on(spdlog::level::info);
  spdlog::set_default_logger(logger);
  return path;
}

}  // namespace autonomy::service
