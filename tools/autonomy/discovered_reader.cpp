#include "tools/autonomy/discovered_reader.hpp"

#include <iostream>

#include "common/dds/error.hpp"
#include "tools/autonomy/discovery.hpp"
#include "tools/recording/raw_topic.hpp"
#include "tools/xtypes/cdr_encode.hpp"

namespace autonomy::tools {

DiscoveredReader::DiscoveredReader(const dds::Participant& participant, const xtypes::DiscoveredTopic& topic,
                                   const dds_qos_t* qos, xtypes::WalkOptions options)
    : topic_(topic), reader_(participant.handle(), topic, qos), options_(options) {}

std::vector<ReceivedSample> DiscoveredReader::take(bool with_json) {
  std::vector<ReceivedSample> out;
  for (auto& s : reader_.take()) {
    ReceivedSample r;
    r.valid = s.valid;
    r.source_timestamp = s.source_timestamp;
    r.instance_state = s.instance_state == DDS_IST_ALIVE                ? dds::InstanceState::Alive
                       : s.instance_state == DDS_IST_NOT_ALIVE_DISPOSED ? dds::InstanceState::Disposed
                                                                        : dds::InstanceState::NoWriters;
    if (s.valid && with_json) {
      try {
        r.json = xtypes::cdr_to_json(*topic_.type, s.cdr, options_);
      } catch (const xtypes::CdrError& e) {
        std::cerr << "autonomy: a sample of " << topic_.name << " does not fit its type " << topic_.type_name << ": "
                  << e.what() << "\n";
        continue;
      }
      json::Json key = json::Json::object();
      for (const auto& m : topic_.type->members)
        if (m.key && r.json.contains(m.name)) key[m.name] = r.json[m.name];
      keys_[s.instance] = key;
    }
    // A sample without data carries no fields here: the key of an instance seen before is known.
    if (auto it = keys_.find(s.instance); it != keys_.end()) r.key = it->second;
    if (!r.valid && r.instance_state != dds::InstanceState::Alive && !with_json) keys_.erase(s.instance);
    out.push_back(std::move(r));
  }
  return out;
}

std::optional<xtypes::DiscoveredTopic> find_discovered_topic(const dds::Participant& participant,
                                                             const std::string& topic, const Interrupt& interrupt,
                                                             std::chrono::nanoseconds wait) {
  xtypes::TopicTypeFinder finder(participant.handle());
  const auto deadline = std::chrono::steady_clock::now() + wait;
  // A type object can take a round trip to the other process: give it at least 5 s.
  const dds_duration_t lookup_timeout = std::max<dds_duration_t>(DDS_SECS(5), wait.count());
  for (;;) {
    if (auto found = finder.find(topic, lookup_timeout)) return found;
    const auto left = deadline - std::chrono::steady_clock::now();
    if (left <= std::chrono::nanoseconds::zero()) return std::nullopt;
    if (!sleep_for(interrupt, participant, std::min<std::chrono::nanoseconds>(left, std::chrono::milliseconds(20))))
      return std::nullopt;
  }
}

DiscoveredWriter::DiscoveredWriter(const dds::Participant& participant, const xtypes::DiscoveredTopic& topic,
                                   const dds_qos_t* qos)
    : topic_(topic),
      topic_entity_(dds::check(dds_create_topic(participant.handle(), topic_.descriptor.get(), topic_.name.c_str(),
                                                nullptr, nullptr),
                               "dds_create_topic " + topic_.name)),
      writer_(dds::check(dds_create_writer(participant.handle(), topic_entity_.handle(), qos, nullptr),
                         "dds_create_writer " + topic_.name)) {}

void DiscoveredWriter::write(const json::Json& j) {
  std::string cdr;
  try {
    cdr = xtypes::json_to_cdr(*topic_.type, j).cdr;
  } catch (const xtypes::CdrError& e) {
    throw json::JsonError(topic_.type_name + "." + e.what());
  }
  // No public way to write serialized bytes in Cyclone 0.10: decode them into the C layout of
  // the descriptor Cyclone built from the type objects, and write that.
  const recording::DecodedSample sample(topic_.descriptor.get(), cdr);
  dds::check(dds_write(writer_.handle(), sample.get()), "dds_write " + topic_.name);
}

uint32_t DiscoveredWriter::matched_readers() const {
  dds_publication_matched_status_t st{};
  dds::check(dds_get_publication_matched_status(writer_.handle(), &st), "dds_get_publication_matched_status");
  return st.current_count;
}

OpenedDiscoveredTopic open_discovered_topic(const dds::Participant& participant, const std::string& topic,
                                            const Interrupt& interrupt, std::chrono::nanoseconds wait,
                                            const xtypes::WalkOptions& options, std::string* why) {
  const auto found = find_discovered_topic(participant, topic, interrupt, wait);
  if (!found) return {};
  Discovery discovery(participant);
  // Processes started together are discovered together; give the other writers a moment.
  sleep_for(interrupt, participant, std::chrono::milliseconds(100));
  const auto writers = discovery.writers_of(topic);
  const dds::Qos qos = mirror_writers_qos(dds::QosClass::Event, writers);
  if (why)
    *why = "type " + found->type_name + " from discovery; " + std::to_string(writers.size()) +
           " writer(s); reader QoS: " + EndpointQos::of(qos.get(), false).str();
  OpenedDiscoveredTopic opened;
  opened.type = found->type;
  opened.type_name = found->type_name;
  opened.reader = std::make_unique<DiscoveredReader>(participant, *found, qos.get(), options);
  return opened;
}

std::vector<std::string> discovered_topic_names(const dds::Participant& participant) {
  return xtypes::TopicTypeFinder(participant.handle()).topic_names();
}

}  // namespace autonomy::tools
