#pragma once
// A reader (and a writer) for a topic that is not in the catalogue: its type from the type
// information its writers (or readers) announced in discovery, its samples printed by the
// generic CDR walker (tools/xtypes) and written from JSON by its inverse. The same AnyReader and
// AnyWriter interfaces as the catalogue's, so echo, hz and pub treat both alike.
#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "tools/autonomy/common.hpp"
#include "tools/autonomy/topic_registry.hpp"
#include "tools/xtypes/cdr_json.hpp"
#include "tools/xtypes/discovered_topic.hpp"

namespace autonomy::tools {

class DiscoveredReader : public AnyReader {
 public:
  DiscoveredReader(const dds::Participant& participant, const xtypes::DiscoveredTopic& topic, const dds_qos_t* qos,
                   xtypes::WalkOptions options);
  std::vector<ReceivedSample> take(bool with_json) override;
  dds_entity_t data_condition() const override { return reader_.data_condition(); }
  dds_entity_t handle() const override { return reader_.handle(); }

 private:
  xtypes::DiscoveredTopic topic_;
  xtypes::CdrReader reader_;
  xtypes::WalkOptions options_;
  std::map<dds_instance_handle_t, json::Json> keys_;  // key fields of each instance seen, for disposals
};

class DiscoveredWriter : public AnyWriter {
 public:
  DiscoveredWriter(const dds::Participant& participant, const xtypes::DiscoveredTopic& topic, const dds_qos_t* qos);
  // Throws json::JsonError when j does not fit the type.
  void write(const json::Json& j) override;
  dds_entity_t handle() const override { return writer_.handle(); }
  uint32_t matched_readers() const override;

 private:
  xtypes::DiscoveredTopic topic_;
  dds::Entity topic_entity_, writer_;
};

struct OpenedDiscoveredTopic {
  std::unique_ptr<AnyReader> reader;  // null: no endpoint of that name was discovered in time
  xtypes::TypePtr type;
  std::string type_name;
};

// Waits up to wait for an endpoint of topic (another process's) and resolves its type; nullopt
// when none was discovered in time. Throws xtypes::TypeLookupError when the type cannot be had.
std::optional<xtypes::DiscoveredTopic> find_discovered_topic(const dds::Participant& participant,
                                                             const std::string& topic, const Interrupt& interrupt,
                                                             std::chrono::nanoseconds wait);

// Waits up to wait for an endpoint of topic (another process's), resolves its type (asking
// that process for it if need be) and opens a reader whose QoS mirrors the writers'.
// Throws xtypes::TypeLookupError when the type cannot be had.
OpenedDiscoveredTopic open_discovered_topic(const dds::Participant& participant, const std::string& topic,
                                            const Interrupt& interrupt, std::chrono::nanoseconds wait,
                                            const xtypes::WalkOptions& options, std::string* why);

// Topic names other processes have endpoints of now (for "did you mean").
std::vector<std::string> discovered_topic_names(const dds::Participant& participant);

}  // namespace autonomy::tools
