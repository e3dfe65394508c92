#include "tools/autonomy/topic_registry.hpp"

#include <algorithm>

#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"

namespace autonomy::tools {

namespace {

template <typename T>
class TypedReader final : public AnyReader {
 public:
  TypedReader(const dds::Participant& p, const dds::TopicSpec<T>& spec, const dds_qos_t* qos)
      : topic_(p, spec), reader_(p, topic_, qos) {}

  std::vector<ReceivedSample> take(bool with_json) override {
    std::vector<ReceivedSample> out;
    for (auto& s : reader_.take()) {
      ReceivedSample r;
      if (with_json) {
        r.key = json::key_json(s.value);
        r.json = s.valid ? json::to_json(s.value) : r.key;
      }
      r.valid = s.valid;
      r.instance_state = s.instance_state;
      r.source_timestamp = s.source_timestamp;
      out.push_back(std::move(r));
    }
    return out;
  }
  dds_entity_t data_condition() const override { return reader_.data_condition(); }
  dds_entity_t handle() const override { return reader_.handle(); }

 private:
  dds::Topic<T> topic_;
  dds::Reader<T> reader_;
};

template <typename T>
class TypedWriter final : public AnyWriter {
 public:
  TypedWriter(const dds::Participant& p, const dds::TopicSpec<T>& spec, const dds_qos_t* qos)
      : topic_(p, spec), writer_(p, topic_, qos) {}

  void write(const json::Json& j) override { writer_.write(json::from_json<T>(j)); }
  dds_entity_t handle() const override { return writer_.handle(); }
  uint32_t matched_readers() const override { return writer_.matched_readers(); }

 private:
  dds::Topic<T> topic_;
  dds::Writer<T> writer_;
};

}  // namespace

TopicRegistry TopicRegistry::catalogue() {
  TopicRegistry r;
  dds::topics::for_each_topic([&r](const auto& spec) {
    using T = typename std::decay_t<decltype(spec)>::Value;
    const dds::TopicSpec<T> s = spec;  // the catalogue's specs are constexpr globals; copy anyway
    TopicEntry e;
    e.name = s.name;
    e.type_name = dds::DdsType<T>::type_name();
    e.message_name = json::message_name<T>();
    e.fields = json::field_names<T>();
    e.key_fields = json::key_names<T>();
    e.qos = s.qos;
    e.normalize = [](const json::Json& j) { return json::to_json(json::from_json<T>(j)); };
    e.make_reader = [s](const dds::Participant& p, const dds_qos_t* q) -> std::unique_ptr<AnyReader> {
      return std::make_unique<TypedReader<T>>(p, s, q);
    };
    e.make_writer = [s](const dds::Participant& p, const dds_qos_t* q) -> std::unique_ptr<AnyWriter> {
      return std::make_unique<TypedWriter<T>>(p, s, q);
    };
    r.entries_.push_back(std::move(e));
  });
  std::sort(r.entries_.begin(), r.entries_.end(),
            [](const TopicEntry& a, const TopicEntry& b) { return a.name < b.name; });
  return r;
}

const TopicEntry* TopicRegistry::find(std::string_view name) const {
  for (const auto& e : entries_)
    if (e.name == name) return &e;
  return nullptr;
}

std::string TopicRegistry::names() const {
  std::string out;
  for (const auto& e : entries_) out += (out.empty() ? "" : ", ") + e.name;
  return out;
}

std::vector<std::string> TopicRegistry::name_list() const {
  std::vector<std::string> out;
  for (const auto& e : entries_) out.push_back(e.name);
  return out;
}

}  // namespace autonomy::tools
