#pragma once
// Any topic by name, without its type compiled into the command: the catalogue's topics with the
// type information idlc compiled in (xtypes::compiled_topic), any other topic with the type its
// writers (or readers) announced in discovery. Either way one type tree: samples are read as
// JSON by the generic CDR walker (xtypes::JsonReader) and written from JSON by its inverse
// (xtypes::json_to_cdr), so echo, hz and pub treat every topic alike.
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "tools/autonomy/common.hpp"
#include "tools/xtypes/discovered_topic.hpp"

namespace autonomy::tools {

class TopicWriter {
 public:
  TopicWriter(const dds::Participant& participant, const xtypes::DiscoveredTopic& topic, const dds_qos_t* qos);
  // cdr: a sample as xtypes::json_to_cdr makes it. Throws std::runtime_error when Cyclone does
  // not take the bytes for the type, dds::DdsError when the write fails.
  void write(const std::string& cdr);
  dds_entity_t handle() const { return writer_.handle(); }
  uint32_t matched_readers() const;

 private:
  xtypes::DiscoveredTopic topic_;
  dds::Entity topic_entity_, writer_;
};

// Waits up to wait for an endpoint of topic (another process's) and resolves its type; nullopt
// when none was discovered in time. Throws xtypes::TypeLookupError when the type cannot be had.
std::optional<xtypes::DiscoveredTopic> find_discovered_topic(const dds::Participant& participant,
                                                             const std::string& topic, const Interrupt& interrupt,
                                                             std::chrono::nanoseconds wait);

// The catalogue's topic of that name with its compiled type, else find_discovered_topic.
std::optional<xtypes::DiscoveredTopic> find_any_topic(const dds::Participant& participant, const std::string& topic,
                                                      const Interrupt& interrupt, std::chrono::nanoseconds wait);

// Topic names other processes have endpoints of now (for "did you mean").
std::vector<std::string> discovered_topic_names(const dds::Participant& participant);

// "{@key robot_id, goal_id, x}": a struct's members, for error messages.
std::string member_list(const xtypes::Type& type);

}  // namespace autonomy::tools
