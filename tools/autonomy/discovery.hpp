#pragma once
// Who writes and reads which topic on the domain, from the DDS built-in topics DCPSPublication
// and DCPSSubscription. This sees every DDS process of the domain, not only ours.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/dds/entity.hpp"
#include "common/dds/participant.hpp"
#include "tools/autonomy/common.hpp"
#include "tools/xtypes/json_reader.hpp"

namespace autonomy::tools {

struct Endpoint {
  bool writer = false;
  std::string topic;
  std::string type;
  dds_guid_t guid{};
  dds_guid_t participant{};
  EndpointQos qos;
};

std::string to_string(const dds_guid_t& guid);

// A participant's process, from the properties Cyclone puts in every participant's discovery
// data (__ProcessName, __Pid, __Hostname); "?" for what a participant does not say (another
// DDS implementation).
struct ParticipantProcess {
  std::string program = "?", pid = "?", host = "?";
  // "ddsperf (pid 9379 on vm)"
  std::string str() const { return program + " (pid " + pid + " on " + host + ")"; }
};

// Every participant discovered so far, by to_string(its GUID).
std::map<std::string, ParticipantProcess> participant_processes(const dds::Participant& participant);

class Discovery {
 public:
  explicit Discovery(const dds::Participant& participant);

  // Every endpoint currently alive on the domain, except this process's own participant's.
  std::vector<Endpoint> endpoints() const;
  std::vector<Endpoint> writers_of(const std::string& topic) const;

  // Triggers when DCPSPublication has samples: attach it to a waitset to wait for writers.
  dds_entity_t publications() const { return publications_.handle(); }

 private:
  void collect(dds_entity_t reader, bool writer, std::vector<Endpoint>& out) const;

  dds_guid_t own_{};
  dds::Entity publications_;
  dds::Entity subscriptions_;
};

// A reader QoS that matches the topic's discovered writers, so that late-joining state shows:
// transient-local when every writer is (at least) transient-local, reliable when every writer is
// reliable; the weaker choice when they differ, so that every writer matches. Without writers,
// the catalogue's class. History is keep-last, deep enough for a tool that prints or counts.
dds::Qos mirror_writers_qos(dds::QosClass without_writers, const std::vector<Endpoint>& writers);

// Waits up to wait for writers of topic to be discovered (a little longer once the first one is
// seen, for others discovered in the same moment); returns them, empty if none or interrupted.
std::vector<Endpoint> wait_for_writers(const Discovery& discovery, const std::string& topic, const Interrupt& interrupt,
                                       const dds::Participant& participant, std::chrono::nanoseconds wait);

// A reader of any topic (the catalogue's or another process's) with mirror_writers_qos, its
// samples walked as JSON; waits up to wait for writers and describes its choice in *why.
std::unique_ptr<xtypes::JsonReader> open_mirroring_reader(const dds::Participant& participant,
                                                          const xtypes::DiscoveredTopic& topic,
                                                          dds::QosClass without_writers, const Interrupt& interrupt,
                                                          std::chrono::nanoseconds wait,
                                                          const xtypes::WalkOptions& options, std::string* why);

}  // namespace autonomy::tools
