#include "simulator/dds/world_claim.hpp"

#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/service/heartbeat.hpp"

#include <unistd.h>

#include <random>
#include <thread>

namespace autonomy::sim {

std::string describe(const OtherWorld& w, uint32_t domain) {
  std::string s = "another world runs on DDS domain " + std::to_string(domain) + ": ";
  if (w.host.empty())
    s += "a clock without a simulator heartbeat (a forged clock or a simulator without heartbeat)";
  else
    s += "simulator on host " + w.host + ", pid " + std::to_string(w.pid) + ", scenario " +
         (w.scenario.empty() ? std::string("(built-in)") : w.scenario);
  return s + " (world " + std::to_string(w.world_id) + "); stop it or start this one on another --domain";
}

std::optional<OtherWorld> find_other_world(const dds::Participant& participant, std::chrono::milliseconds window) {
  const dds::Topic<msg::SimClock> clock_topic(participant, dds::topics::clock);
  const dds::Topic<msg::Heartbeat> beat_topic(participant, dds::topics::heartbeat);
  const dds::Reader<msg::SimClock> clocks(participant, clock_topic);
  const dds::Reader<msg::Heartbeat> beats(participant, beat_topic);
  const std::string host = service::host_name();
  const auto pid = static_cast<int32_t>(getpid());
  std::optional<OtherWorld> found;
  std::optional<uint64_t> clock_world;
  // Both topics are state topics (transient-local): a running world's last clock and its
  // simulator's heartbeat arrive as soon as discovery matched, whatever their period.
  const auto until = std::chrono::steady_clock::now() + window;
  while (std::chrono::steady_clock::now() < until) {
    for (const auto& s : clocks.read())
      if (s.valid) clock_world = s.value.world_id;
    for (const auto& s : beats.read()) {
      const msg::Heartbeat& b = s.value;
      if (!s.valid || s.instance_state != dds::InstanceState::Alive || b.service != "simulator") continue;
      if (b.state == msg::ServiceState::Stopping || (b.host == host && b.pid == pid)) continue;
      // A simulator that is still listening itself (world 0) runs no world yet.
      if (b.world_id == 0) continue;
      found = OtherWorld{b.world_id, b.host, b.pid, b.detail};
    }
    if (found) return found;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  // A clock heard without a simulator's heartbeat naming it: still a world on this domain.
  if (clock_world) return OtherWorld{*clock_world, "", 0, ""};
  return std::nullopt;
}

uint64_t new_world_id() {
  std::random_device entropy;
  for (;;) {
    const uint64_t id = (static_cast<uint64_t>(entropy()) << 32) ^ static_cast<uint64_t>(entropy());
    if (id != 0) return id;
  }
}

}  // namespace autonomy::sim
