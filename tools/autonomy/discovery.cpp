#include "tools/autonomy/discovery.hpp"

#include <cstdio>
#include <cstring>

#include "common/dds/error.hpp"

namespace autonomy::tools {

std::string to_string(const dds_guid_t& guid) {
  std::string s;
  char hex[3];
  for (size_t i = 0; i < sizeof(guid.v); ++i) {
    std::snprintf(hex, sizeof(hex), "%02x", guid.v[i]);
    s += hex;
    if (i % 4 == 3 && i + 1 < sizeof(guid.v)) s += ':';
  }
  return s;
}

std::map<std::string, ParticipantProcess> participant_processes(const dds::Participant& participant) {
  std::map<std::string, ParticipantProcess> out;
  const dds::Entity reader(
      dds::check(dds_create_reader(participant.handle(), DDS_BUILTIN_TOPIC_DCPSPARTICIPANT, nullptr, nullptr),
                 "dds_create_reader(DCPSParticipant)"));
  // A new built-in reader holds every participant discovered before it was made.
  constexpr size_t kMax = 4096;
  std::vector<void*> buffers(kMax, nullptr);
  std::vector<dds_sample_info_t> infos(kMax);
  const dds_return_t n = dds::check(dds_read_mask(reader.handle(), buffers.data(), infos.data(), kMax, kMax,
                                                  DDS_ANY_SAMPLE_STATE | DDS_ANY_VIEW_STATE | DDS_ALIVE_INSTANCE_STATE),
                                    "dds_read_mask(DCPSParticipant)");
  for (dds_return_t i = 0; i < n; ++i) {
    if (!infos[i].valid_data) continue;
    const auto* p = static_cast<const dds_builtintopic_participant_t*>(buffers[i]);
    auto property = [p](const char* name) {
      char* value = nullptr;
      std::string s = p->qos && dds_qget_prop(p->qos, name, &value) && value ? value : "?";
      dds_free(value);
      return s;
    };
    out[to_string(p->key)] = ParticipantProcess{property("__ProcessName"), property("__Pid"), property("__Hostname")};
  }
  if (n > 0) dds_return_loan(reader.handle(), buffers.data(), n);
  return out;
}

Discovery::Discovery(const dds::Participant& participant)
    : publications_(
          dds::check(dds_create_reader(participant.handle(), DDS_BUILTIN_TOPIC_DCPSPUBLICATION, nullptr, nullptr),
                     "dds_create_reader(DCPSPublication)")),
      subscriptions_(
          dds::check(dds_create_reader(participant.handle(), DDS_BUILTIN_TOPIC_DCPSSUBSCRIPTION, nullptr, nullptr),
                     "dds_create_reader(DCPSSubscription)")) {
  dds::check(dds_get_guid(participant.handle(), &own_), "dds_get_guid");
}

void Discovery::collect(dds_entity_t reader, bool writer, std::vector<Endpoint>& out) const {
  // read, not take: the built-in reader keeps one sample per endpoint, so reading again later
  // gives the domain's current endpoints. A single large loan covers any realistic domain.
  constexpr size_t kMax = 16384;
  std::vector<void*> buffers(kMax, nullptr);
  std::vector<dds_sample_info_t> infos(kMax);
  const dds_return_t n = dds::check(dds_read_mask(reader, buffers.data(), infos.data(), kMax, kMax,
                                                  DDS_ANY_SAMPLE_STATE | DDS_ANY_VIEW_STATE | DDS_ALIVE_INSTANCE_STATE),
                                    "dds_read_mask(built-in topic)");
  for (dds_return_t i = 0; i < n; ++i) {
    if (!infos[i].valid_data) continue;
    const auto* ep = static_cast<const dds_builtintopic_endpoint_t*>(buffers[i]);
    if (std::memcmp(&ep->participant_key, &own_, sizeof(own_)) == 0) continue;
    Endpoint e;
    e.writer = writer;
    e.topic = ep->topic_name ? ep->topic_name : "";
    e.type = ep->type_name ? ep->type_name : "";
    e.guid = ep->key;
    e.participant = ep->participant_key;
    e.qos = EndpointQos::of(ep->qos, writer);
    out.push_back(std::move(e));
  }
  if (n > 0) dds::check(dds_return_loan(reader, buffers.data(), n), "dds_return_loan");
}

std::vector<Endpoint> Discovery::endpoints() const {
  std::vector<Endpoint> out;
  collect(publications_.handle(), true, out);
  collect(subscriptions_.handle(), false, out);
  return out;
}

std::vector<Endpoint> Discovery::writers_of(const std::string& topic) const {
  std::vector<Endpoint> all;
  collect(publications_.handle(), true, all);
  std::vector<Endpoint> out;
  for (auto& e : all)
    if (e.topic == topic) out.push_back(std::move(e));
  return out;
}

}  // namespace autonomy::tools

namespace autonomy::tools {

dds::Qos mirror_writers_qos(dds::QosClass without_writers, const std::vector<Endpoint>& writers) {
  dds::Qos q = dds::make_qos(without_writers);
  if (!writers.empty()) {
    bool reliable = true, durable = true;
    for (const auto& w : writers) {
      reliable = reliable && w.qos.reliable;
      durable = durable && w.qos.durability != DDS_DURABILITY_VOLATILE;
    }
    dds_qset_reliability(q.get(), reliable ? DDS_RELIABILITY_RELIABLE : DDS_RELIABILITY_BEST_EFFORT, DDS_MSECS(100));
    dds_qset_durability(q.get(), durable ? DDS_DURABILITY_TRANSIENT_LOCAL : DDS_DURABILITY_VOLATILE);
  }
  // Keep-last, not keep-all: a slow terminal must not throttle the writers (reliable keep-all
  // readers push back on them).
  dds_qset_history(q.get(), DDS_HISTORY_KEEP_LAST, 1024);
  return q;
}

std::vector<Endpoint> wait_for_writers(const Discovery& discovery, const std::string& topic, const Interrupt& interrupt,
                                       const dds::Participant& participant, std::chrono::nanoseconds wait) {
  const auto deadline = std::chrono::steady_clock::now() + wait;
  for (;;) {
    auto writers = discovery.writers_of(topic);
    if (!writers.empty()) {
      // Processes started together are discovered together; give the others a moment.
      if (!sleep_for(interrupt, participant, std::chrono::milliseconds(100))) return {};
      return discovery.writers_of(topic);
    }
    const auto left = deadline - std::chrono::steady_clock::now();
    if (left <= std::chrono::nanoseconds::zero()) return {};
    if (!sleep_for(interrupt, participant, std::min<std::chrono::nanoseconds>(left, std::chrono::milliseconds(20))))
      return {};
  }
}

std::unique_ptr<xtypes::JsonReader> open_mirroring_reader(const dds::Participant& participant,
                                                          const xtypes::DiscoveredTopic& topic,
                                                          dds::QosClass without_writers, const Interrupt& interrupt,
                                                          std::chrono::nanoseconds wait,
                                                          const xtypes::WalkOptions& options, std::string* why) {
  Discovery discovery(participant);
  const auto writers = wait_for_writers(discovery, topic.name, interrupt, participant, wait);
  const dds::Qos qos = mirror_writers_qos(without_writers, writers);
  if (why) {
    const EndpointQos chosen = EndpointQos::of(qos.get(), false);
    *why = writers.empty() ? "no writer discovered yet; reader QoS of class " + std::string(dds::to_string(without_writers))
                           : std::to_string(writers.size()) + " writer(s) discovered; reader QoS mirrors them";
    *why += ": " + chosen.str();
  }
  return std::make_unique<xtypes::JsonReader>(participant.handle(), topic, qos.get(), options);
}

}  // namespace autonomy::tools
