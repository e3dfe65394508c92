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
  void publish();
  std::chrono::milliseconds period() const { return period_; }

 private:
  dds::Topic<msg::Heartbeat> topic_;
  dds::Writer<msg::Heartbeat> writer_;
  msg::Heartbeat beat_;
  std::chrono::milliseconds period_;
  std::chrono::steady_clock::time_point started_;
};

// This machine's host name, or "unknown".
std::string host_name();

}  // namespace autonomy::service
