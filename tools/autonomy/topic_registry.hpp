#pragma once
// Topic name -> what the tool can do with that topic, without knowing its type at compile time.
// Built from the catalogue (common/dds/topics.hpp, for_each_topic), so a topic added there shows
// up in every command without a change here (its message type needs a Fields table in
// tools/json/fields.hpp, which the compiler asks for).
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "common/dds/participant.hpp"
#include "common/dds/qos.hpp"
#include "common/dds/reader.hpp"
#include "tools/json/msg_json.hpp"

namespace autonomy::tools {

// One received sample: its JSON and what DDS said about it.
struct ReceivedSample {
  json::Json json;    // every field; for samples without data only the key fields
  json::Json key;     // the key fields (which instance)
  bool valid = true;  // false: the sample only reports an instance state change
  dds::InstanceState instance_state = dds::InstanceState::Alive;
  dds_time_t source_timestamp = 0;
};

class AnyReader {
 public:
  virtual ~AnyReader() = default;
  // Takes every available sample. with_json=false skips the JSON conversion (for rates).
  virtual std::vector<ReceivedSample> take(bool with_json) = 0;
  virtual dds_entity_t data_condition() const = 0;
  virtual dds_entity_t handle() const = 0;
};

class AnyWriter {
 public:
  virtual ~AnyWriter() = default;
  // Throws json::JsonError when j does not fit the type, dds::DdsError when the write fails.
  virtual void write(const json::Json& j) = 0;
  virtual dds_entity_t handle() const = 0;
  virtual uint32_t matched_readers() const = 0;
};

struct TopicEntry {
  std::string name;          // "autonomy/nav/goal"
  std::string type_name;     // the DDS type name, "autonomy::NavGoal"
  std::string message_name;  // the JSON/C++ name, "NavGoal"
  std::vector<std::string> fields;
  std::vector<std::string> key_fields;
  dds::QosClass qos;
  // Checks j against the type and returns it complete (omitted fields with their defaults);
  // throws json::JsonError naming the field.
  std::function<json::Json(const json::Json&)> normalize;
  std::function<std::unique_ptr<AnyReader>(const dds::Participant&, const dds_qos_t*)> make_reader;
  std::function<std::unique_ptr<AnyWriter>(const dds::Participant&, const dds_qos_t*)> make_writer;
};

class TopicRegistry {
 public:
  // Every topic of the catalogue, sorted by name.
  static TopicRegistry catalogue();

  const TopicEntry* find(std::string_view name) const;
  const std::vector<TopicEntry>& entries() const { return entries_; }
  // "a, b, c": for help texts.
  std::string names() const;
  std::vector<std::string> name_list() const;

 private:
  std::vector<TopicEntry> entries_;
};

}  // namespace autonomy::tools
