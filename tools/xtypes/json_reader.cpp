#include "tools/xtypes/json_reader.hpp"

namespace autonomy::xtypes {

JsonReader::JsonReader(dds_entity_t participant, const DiscoveredTopic& topic, const dds_qos_t* qos, WalkOptions options)
    : topic_(topic), reader_(participant, topic, qos), options_(options) {}

std::vector<JsonSample> JsonReader::take(bool with_json) {
  std::vector<JsonSample> out;
  for (auto& s : reader_.take()) {
    JsonSample r;
    r.valid = s.valid;
    r.instance_state = s.instance_state;
    r.source_timestamp = s.source_timestamp;
    if (s.valid && with_json) {
      try {
        r.json = cdr_to_json(*topic_.type, s.cdr, options_);
        keys_[s.instance] = key_of(*topic_.type, r.json);
      } catch (const CdrError& e) {
        r.error = e.what();
      }
    }
    const auto known = keys_.find(s.instance);
    r.key = known != keys_.end() ? known->second : Json::object();
    // An instance that ended is forgotten (a new sample of it is remembered again).
    if (!s.valid && s.instance_state != DDS_IST_ALIVE && known != keys_.end()) keys_.erase(known);
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace autonomy::xtypes
