#pragma once
// Any topic on the domain, by name, without its type compiled in: its type from the type
// information another process's endpoint announced in discovery (DCPSPublication, then
// DCPSSubscription), and a reader that takes its samples as CDR for the walker (cdr_json.hpp).
#include <dds/dds.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/dds/entity.hpp"
#include "tools/xtypes/type_tree.hpp"

namespace autonomy::xtypes {

struct DiscoveredTopic {
  std::string name;       // "DDSPerfRDataKS"
  std::string type_name;  // "KeyedSeq"
  TypePtr type;
  // What dds_create_topic needs for this type (built by Cyclone from the type objects).
  std::shared_ptr<dds_topic_descriptor_t> descriptor;
};

// A topic whose type this process has compiled in (an idlc descriptor, with the type
// information idlc generated): its type as Cyclone's type library holds it once the topic is
// created, the same tree a foreign type gets, so one walker prints both. descriptor is not
// owned (idlc's are static). Throws TypeLookupError, dds::DdsError.
DiscoveredTopic compiled_topic(dds_entity_t participant, const std::string& name, const dds_topic_descriptor_t* descriptor);

class TopicTypeFinder {
 public:
  explicit TopicTypeFinder(dds_entity_t participant);

  // The topic if an endpoint of another participant with that name is known now (with type
  // information), else nullopt. Asks the endpoint's process for type objects it does not have,
  // waiting up to timeout. Throws TypeLookupError when the type cannot be had.
  std::optional<DiscoveredTopic> find(const std::string& topic, dds_duration_t timeout) const;
  // Every topic name other participants have endpoints of now, sorted, once each.
  std::vector<std::string> topic_names() const;

 private:
  dds_entity_t participant_;
  dds_guid_t own_{};
  dds::Entity publications_, subscriptions_;
};

// One taken sample: the bytes as on the wire (encapsulation header included), or for a sample
// without data (an instance disposed or without writers) only its state.
struct CdrSample {
  std::string cdr;
  bool valid = true;
  dds_instance_state_t instance_state = DDS_IST_ALIVE;
  dds_instance_handle_t instance = 0;
  dds_time_t source_timestamp = 0;
};

class CdrReader {
 public:
  CdrReader(dds_entity_t participant, const DiscoveredTopic& topic, const dds_qos_t* qos);
  std::vector<CdrSample> take();
  dds_entity_t handle() const { return reader_.handle(); }
  dds_entity_t data_condition() const { return condition_.handle(); }

 private:
  std::shared_ptr<dds_topic_descriptor_t> descriptor_;  // the topic refers to it while it lives
  dds::Entity topic_, reader_, condition_;
};

}  // namespace autonomy::xtypes
