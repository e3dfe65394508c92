#pragma once
// The process's heartbeat on autonomy/heartbeat: who it is, where, and its lifecycle state.
#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"

#include <chrono>
#include <string>
#include <vector>

namespace autonomy::service {

class HeartbeatPublisher {
 public:
  HeartbeatPublisher(const dds::Participant& participant, std::string service, std::string instance,
                     std::chrono::milliseconds period);
  // Disposes this process's instance: a clean stop. The writer does not dispose by itself, so
  // a killed process's instance goes NOT_ALIVE_NO_WRITERS when its lease expires ("lost" in
  // `autonomy node list -a`) instead of looking like a clean stop.
  ~HeartbeatPublisher();
  HeartbeatPublisher(const HeartbeatPublisher&) = delete;
  HeartbeatPublisher& operator=(const HeartbeatPublisher&) = delete;

  // Publishes at once when the state changes, so readiness is seen without waiting a period.
  void set_state(msg::ServiceState state);
  // What this process offers beyond its service ("courier"); published at once when it changes.
  void set_capabilities(std::vector<std::string> capabilities);
  // The world this process joined; published at once when it changes.
  void set_world(uint64_t world_id);
  // Counted at once, published with the next periodic beat (ignored samples may come in floods).
  void set_clock_samples_ignored(uint64_t n) { beat_.clock_samples_ignored = n; }
  // What this process runs (the simulator's scenario); published at once when it changes.
  void set_detail(std::string detail);
  void publish();
  std::chrono::milliseconds period() const { return period_; }

 private:
  dds::Topic<msg::Heartbeat> topic_;
  dds::Writer<msg::Heartbeat> writer_;
  msg::Heartbeat beat_;
  std::chrono::milliseconds period_;
  std::chrono::steady_clock::time_point started_;
};

// The host this process reports: $AUTONOMY_HOST when set (a host of deploy/hosts.sh), else the
// machine's hostname, or "unknown".
std::string host_name();

}  // namespace autonomy::service
