#pragma once
// A topic's samples as JSON: taken as CDR (CdrReader) and printed by the walker with the
// topic's type, the same for the project's topics (compiled_topic) and any other process's
// (TopicTypeFinder). A sample that only reports an instance's end carries no data: it gets the
// key fields of that instance's last valid sample, remembered here.
#include <dds/dds.h>

#include <map>
#include <string>
#include <vector>

#include "tools/xtypes/cdr_json.hpp"
#include "tools/xtypes/discovered_topic.hpp"

namespace autonomy::xtypes {

struct JsonSample {
  Json json;          // every member (null when not walked: with_json false, or `error`)
  Json key;           // the key members of the instance ({} when not known)
  bool valid = true;  // false: the sample only reports an instance state change
  dds_instance_state_t instance_state = DDS_IST_ALIVE;
  dds_time_t source_timestamp = 0;
  std::string error;  // the bytes did not fit the type (CdrError's text)
};

class JsonReader {
 public:
  JsonReader(dds_entity_t participant, const DiscoveredTopic& topic, const dds_qos_t* qos, WalkOptions options = {});
  // Every sample available now. with_json false skips the walk (for rates).
  std::vector<JsonSample> take(bool with_json = true);
  dds_entity_t handle() const { return reader_.handle(); }
  dds_entity_t data_condition() const { return reader_.data_condition(); }
  const DiscoveredTopic& topic() const { return topic_; }

 private:
  DiscoveredTopic topic_;
  CdrReader reader_;
  WalkOptions options_;
  std::map<dds_instance_handle_t, Json> keys_;  // of each live instance seen
};

}  // namespace autonomy::xtypes
