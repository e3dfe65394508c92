#pragma once
// The skeleton every process shares: options, logging, a participant, the event loop, the
// heartbeat and a clean stop on SIGINT/SIGTERM. A service's main is run_service(...) plus a node.
#include "common/service/event_loop.hpp"
#include "common/service/heartbeat.hpp"
#include "common/service/logging.hpp"
#include "common/service/options.hpp"
#include "common/service/shutdown.hpp"

#include <spdlog/spdlog.h>

#include <exception>
#include <memory>

namespace autonomy::service {

class Service {
 public:
  explicit Service(ServiceOptions options);

  const ServiceOptions& options() const { return options_; }
  const dds::Participant& participant() const { return participant_; }
  EventLoop& loop() { return loop_; }

  // Tells launchers and `autonomy node list` that this process serves.
  void set_ready() { heartbeat_.set_state(msg::ServiceState::Ready); }
  // Capabilities announced in the heartbeat (e.g. "courier" on a robot's behavior process).
  void set_capabilities(std::vector<std::string> capabilities) { heartbeat_.set_capabilities(std::move(capabilities)); }
  HeartbeatPublisher& heartbeat() { return heartbeat_; }
  // Runs the loop until a signal or stop(); publishes the stopping heartbeat.
  void run();
  void stop() { loop_.stop(); }
  // Stops because the node cannot do its job; the process then exits with code 1.
  void fail(const std::string& reason);
  int exit_code() const { return exit_code_; }

 private:
  ServiceOptions options_;
  ShutdownSignals signals_;  // first member: blocks the signals before DDS starts its threads
  dds::Participant participant_;
  EventLoop loop_;
  HeartbeatPublisher heartbeat_;
  int exit_code_ = 0;
};

// Parses the shared options plus those add_options registers, then builds the node with
// make_node(service) and runs until SIGINT/SIGTERM. Returns the process exit code: 0 after a
// clean stop, 1 when the node could not start or called fail() (the reason is logged), CLI11's
// code for bad arguments.
template <typename AddOptions, typename MakeNode>
int run_service(int argc, char** argv, const char* service_name, const char* description, InstanceFlag flag,
                AddOptions&& add_options, MakeNode&& make_node) {
  CLI::App app{description, service_name};
  ServiceOptions options;
  options.service = service_name;
  add_service_options(app, options, flag);
  add_options(app);
  CLI11_PARSE(app, argc, argv);
  try {
    const std::string log_file = setup_logging(options);
    Service service(options);
    service.loop().allow_handling_at_arrival();  // this process runs one loop
    spdlog::info("starting on DDS domain {}, log file {}", options.domain, log_file);
    auto node = make_node(service);
    service.run();
    node.reset();
    spdlog::info("stopped");
    return service.exit_code();
  } catch (const std::exception& e) {
    spdlog::critical("cannot run: {}", e.what());
    return 1;
  }
}

}  // namespace autonomy::service
