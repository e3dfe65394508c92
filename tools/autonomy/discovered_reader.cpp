#include "tools/autonomy/discovered_reader.hpp"

#include "common/dds/error.hpp"
#include "tools/recording/raw_topic.hpp"

namespace autonomy::tools {

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

std::optional<xtypes::DiscoveredTopic> find_any_topic(const dds::Participant& participant, const std::string& topic,
                                                      const Interrupt& interrupt, std::chrono::nanoseconds wait) {
  if (const auto* ours = recording::find_recordable(topic))
    return xtypes::compiled_topic(participant.handle(), ours->name, ours->descriptor);
  return find_discovered_topic(participant, topic, interrupt, wait);
}

TopicWriter::TopicWriter(const dds::Participant& participant, const xtypes::DiscoveredTopic& topic, const dds_qos_t* qos)
    : topic_(topic),
      topic_entity_(dds::check(dds_create_topic(participant.handle(), topic_.descriptor.get(), topic_.name.c_str(),
                                                nullptr, nullptr),
                               "dds_create_topic " + topic_.name)),
      writer_(dds::check(dds_create_writer(participant.handle(), topic_entity_.handle(), qos, nullptr),
                         "dds_create_writer " + topic_.name)) {}

void TopicWriter::write(const std::string& cdr) {
  // No public way to write serialized bytes in Cyclone 0.10: decode them into the C layout of
  // the topic's descriptor (idlc's, or the one Cyclone built from the type objects), and write that.
  const recording::DecodedSample sample(topic_.descriptor.get(), cdr);
  dds::check(dds_write(writer_.handle(), sample.get()), "dds_write " + topic_.name);
}

uint32_t TopicWriter::matched_readers() const {
  dds_publication_matched_status_t st{};
  dds::check(dds_get_publication_matched_status(writer_.handle(), &st), "dds_get_publication_matched_status");
  return st.current_count;
}

std::vector<std::string> discovered_topic_names(const dds::Participant& participant) {
  return xtypes::TopicTypeFinder(participant.handle()).topic_names();
}

std::string member_list(const xtypes::Type& type) {
  std::string members;
  for (const auto& m : type.members) members += std::string(members.empty() ? "" : ", ") + (m.key ? "@key " : "") + m.name;
  return "{" + members + "}";
}

}  // namespace autonomy::tools
