#pragma once
// Catalogue topics handled as serialized samples (CDR with its 4-byte encapsulation header, as on
// the wire): the recorder takes them without decoding (dds_takecdr) and the player writes them
// back. Cyclone 0.10 has no public way to build a writer's serdata from bytes, so the player
// decodes a recorded sample into the generated C type with Cyclone's own CDR stream code (after
// checking it with dds_stream_normalize_data) and writes that: what goes on the wire is the same.
#include <dds/dds.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/dds/entity.hpp"
#include "common/dds/participant.hpp"
#include "common/dds/qos.hpp"

namespace autonomy::recording {

struct RecordableTopic {
  std::string name;       // "autonomy/nav/goal"
  std::string type_name;  // "autonomy::NavGoal"
  const dds_topic_descriptor_t* descriptor = nullptr;
  dds::QosClass qos = dds::QosClass::Event;
};

// Every topic of the catalogue (common/dds/topics.hpp), sorted by name.
const std::vector<RecordableTopic>& recordable_topics();
const RecordableTopic* find_recordable(const std::string& name);

struct RawSample {
  std::string cdr;                 // encapsulation header + payload
  int64_t source_timestamp = 0;    // ns since the epoch, the writer's clock
  int64_t reception_time = 0;      // ns since the epoch, when this process took it
};

class RawReader {
 public:
  // A reader of the topic's class reliability and durability (transient-local state written
  // before it started arrives at once), keeping every sample until taken.
  RawReader(const dds::Participant& participant, const RecordableTopic& topic);
  // Appends the valid samples available now (instance state changes without data are skipped).
  void take(std::vector<RawSample>& out);
  dds_entity_t data_condition() const { return condition_.handle(); }
  const RecordableTopic& topic() const { return topic_; }
  dds_entity_t topic_handle() const { return topic_entity_.handle(); }  // for its type (xtypes)
  uint32_t matched_writers() const;

 private:
  RecordableTopic topic_;
  dds::Entity topic_entity_, reader_, condition_;
};

// A C sample decoded from CDR, freed with its contents.
class DecodedSample {
 public:
  // Throws std::runtime_error when the bytes are not a valid sample of the type.
  DecodedSample(const dds_topic_descriptor_t* descriptor, const std::string& cdr);
  ~DecodedSample();
  DecodedSample(const DecodedSample&) = delete;
  DecodedSample& operator=(const DecodedSample&) = delete;
  const void* get() const { return sample_; }

 private:
  const dds_topic_descriptor_t* descriptor_;
  void* sample_ = nullptr;
};

class RawWriter {
 public:
  RawWriter(const dds::Participant& participant, const RecordableTopic& topic, const dds_qos_t* qos);
  void write(const std::string& cdr);  // throws std::runtime_error / dds::DdsError
  uint32_t matched_readers() const;
  dds_entity_t topic_handle() const { return topic_entity_.handle(); }

 private:
  RecordableTopic topic_;
  dds::Entity topic_entity_, writer_;
};

// QoS as MCAP channel metadata: qos_class, reliability, durability, history, depth.
std::map<std::string, std::string> qos_metadata(const dds_qos_t* qos, dds::QosClass cls);
// Back from metadata; throws std::runtime_error naming a missing or unknown value.
dds::Qos qos_from_metadata(const std::map<std::string, std::string>& metadata);

}  // namespace autonomy::recording
