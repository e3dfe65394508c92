#include "common/service/service.hpp"

namespace autonomy::service {

Service::Service(ServiceOptions options)
    : options_(std::move(options)),
      participant_(static_cast<dds_domainid_t>(options_.domain)),
      loop_(participant_),
      heartbeat_(participant_, options_.service, options_.instance,
                 std::chrono::milliseconds(static_cast<int64_t>(options_.heartbeat_period_s * 1000.0))) {
  signals_.on_shutdown([this](int sig) {
    spdlog::info("signal {} received, stopping", sig);
    loop_.stop();
  });
  heartbeat_.publish();
  loop_.every(heartbeat_.period(), [this] { heartbeat_.publish(); });
}

void Service::fail(const std::string& reason) {
  spdlog::error("giving up: {}", reason);
  exit_code_ = 1;
  loop_.stop();
}

void Service::run() {
  loop_.run();
  heartbeat_.set_state(msg::ServiceState::Stopping);
}

}  // namespace autonomy::service
