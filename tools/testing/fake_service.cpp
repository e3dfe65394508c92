// fake_service: a stand-in process for trying the `autonomy` tool and launch scripts by hand.
// It runs the common service skeleton (heartbeat, signals), turns ready after --ready-after
// seconds, and keeps one GoalStatus instance (robot "fake-<instance>") alive, which it disposes
// when it stops cleanly.
#include <memory>

#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"
#include "common/service/service.hpp"

namespace {

struct Node {
  Node(autonomy::service::Service& service, double ready_after_s)
      : topic(service.participant(), autonomy::dds::topics::goal_status), writer(service.participant(), topic) {
    status.robot_id = "fake-" + service.options().instance;
    status.goal_id = "idle";
    status.state = autonomy::msg::GoalState::Active;
    writer.write(status);
    const auto start = std::chrono::steady_clock::now();
    service.loop().every(std::chrono::milliseconds(100), [this, &service, start, ready_after_s] {
      if (std::chrono::steady_clock::now() - start >= std::chrono::duration<double>(ready_after_s)) service.set_ready();
    });
  }
  autonomy::dds::Topic<autonomy::msg::GoalStatus> topic;
  autonomy::dds::Writer<autonomy::msg::GoalStatus> writer;
  autonomy::msg::GoalStatus status;
};

}  // namespace

int main(int argc, char** argv) {
  double ready_after_s = 0.0;
  return autonomy::service::run_service(
      argc, argv, "fake", "A stand-in service for trying the autonomy tool", autonomy::service::InstanceFlag::Instance,
      [&](CLI::App& app) {
        app.add_option("--ready-after", ready_after_s, "Seconds before the heartbeat says ready")
            ->capture_default_str();
      },
      [&](autonomy::service::Service& service) { return std::make_unique<Node>(service, ready_after_s); });
}
