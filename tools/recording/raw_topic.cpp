#include "tools/recording/raw_topic.hpp"

#include <dds/ddsi/ddsi_cdrstream.h>
#include <dds/ddsi/ddsi_serdata.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "common/dds/error.hpp"
#include "common/dds/topics.hpp"

namespace autonomy::recording {

namespace {

dds::Entity create_topic(const dds::Participant& p, const RecordableTopic& t) {
  return dds::Entity(dds::check(dds_create_topic(p.handle(), t.descriptor, t.name.c_str(), nullptr, nullptr),
                                "dds_create_topic " + t.name));
}

}  // namespace

const std::vector<RecordableTopic>& recordable_topics() {
  static const std::vector<RecordableTopic> topics = [] {
    std::vector<RecordableTopic> v;
    dds::topics::for_each_topic([&v](const auto& spec) {
      using T = typename std::decay_t<decltype(spec)>::Value;
      std::string type = dds::DdsType<T>::type_name();
      v.push_back({spec.name, type, dds::DdsType<T>::descriptor(), spec.qos});
    });
    std::sort(v.begin(), v.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
    return v;
  }();
  return topics;
}

const RecordableTopic* find_recordable(const std::string& name) {
  for (const auto& t : recordable_topics())
    if (t.name == name) return &t;
  return nullptr;
}

RawReader::RawReader(const dds::Participant& participant, const RecordableTopic& topic)
    : topic_(topic), topic_entity_(create_topic(participant, topic)) {
  auto qos = dds::make_qos(topic.qos);
  dds_qset_history(qos.get(), DDS_HISTORY_KEEP_ALL, 0);  // a recorder drops nothing it received
  reader_ = dds::Entity(dds::check(dds_create_reader(participant.handle(), topic_entity_.handle(), qos.get(), nullptr),
                                   "dds_create_reader " + topic.name));
  condition_ = dds::Entity(dds::check(dds_create_readcondition(reader_.handle(), DDS_ANY_STATE),
                                      "dds_create_readcondition " + topic.name));
}

void RawReader::take(std::vector<RawSample>& out) {
  constexpr uint32_t kBatch = 64;
  for (;;) {
    ddsi_serdata* data[kBatch] = {};
    dds_sample_info_t info[kBatch];
    const dds_return_t n = dds_takecdr(reader_.handle(), data, kBatch, info, DDS_ANY_STATE);
    dds::check(n, "dds_takecdr " + topic_.name);
    const int64_t now = dds_time();
    for (int i = 0; i < n; ++i) {
      if (info[i].valid_data) {
        RawSample s;
        // The serialized form includes the 4-byte encapsulation header, as on the wire.
        s.cdr.resize(ddsi_serdata_size(data[i]));
        ddsi_serdata_to_ser(data[i], 0, s.cdr.size(), s.cdr.data());
        s.source_timestamp = info[i].source_timestamp;
        s.reception_time = now;
        out.push_back(std::move(s));
      }
      ddsi_serdata_unref(data[i]);
    }
    if (static_cast<uint32_t>(n) < kBatch) return;
  }
}

DecodedSample::DecodedSample(const dds_topic_descriptor_t* descriptor, const std::string& cdr)
    : descriptor_(descriptor) {
  if (cdr.size() < 4) throw std::runtime_error("sample of " + std::to_string(cdr.size()) + " bytes: no CDR header");
  const uint16_t id = static_cast<uint16_t>((static_cast<unsigned char>(cdr[0]) << 8) | static_cast<unsigned char>(cdr[1]));
  uint32_t xcdr;
  if (id <= 0x0003)
    xcdr = 1;  // CDR, PL_CDR
  else if (id >= 0x0006 && id <= 0x000b)
    xcdr = 2;  // CDR2, D_CDR2, PL_CDR2
  else
    throw std::runtime_error("unknown CDR encapsulation 0x" + std::to_string(id));
  const bool little = (id & 1u) != 0;
  const bool host_little = DDSRT_ENDIAN == DDSRT_LITTLE_ENDIAN;
  std::string payload = cdr.substr(4);  // normalised in place (byte swapped if needed)
  uint32_t off = 0;
  if (!dds_stream_normalize_data(payload.data(), &off, static_cast<uint32_t>(payload.size()), little != host_little, xcdr,
                                 descriptor->m_ops))
    throw std::runtime_error(std::string("sample is not a valid ") + descriptor->m_typename + " (CDR check failed)");
  sample_ = std::calloc(1, descriptor->m_size);
  if (!sample_) throw std::bad_alloc();
  dds_istream_t is;
  dds_istream_init(&is, static_cast<uint32_t>(payload.size()), payload.data(), xcdr);
  dds_stream_read(&is, static_cast<char*>(sample_), descriptor->m_ops);
  dds_istream_fini(&is);
}

DecodedSample::~DecodedSample() {
  if (sample_) dds_sample_free(sample_, descriptor_, DDS_FREE_ALL);
}

RawWriter::RawWriter(const dds::Participant& participant, const RecordableTopic& topic, const dds_qos_t* qos)
    : topic_(topic), topic_entity_(create_topic(participant, topic)) {
  writer_ = dds::Entity(dds::check(dds_create_writer(participant.handle(), topic_entity_.handle(), qos, nullptr),
                                   "dds_create_writer " + topic.name));
}

void RawWriter::write(const std::string& cdr) {
  DecodedSample sample(topic_.descriptor, cdr);
  dds::check(dds_write(writer_.handle(), sample.get()), "dds_write " + topic_.name);
}

uint32_t RawReader::matched_writers() const {
  dds_subscription_matched_status_t st{};
  dds::check(dds_get_subscription_matched_status(reader_.handle(), &st), "dds_get_subscription_matched_status");
  return st.current_count;
}

uint32_t RawWriter::matched_readers() const {
  dds_publication_matched_status_t st{};
  dds::check(dds_get_publication_matched_status(writer_.handle(), &st), "dds_get_publication_matched_status");
  return st.current_count;
}

std::map<std::string, std::string> qos_metadata(const dds_qos_t* qos, dds::QosClass cls) {
  std::map<std::string, std::string> m;
  m["qos_class"] = dds::to_string(cls);
  dds_reliability_kind_t rel = DDS_RELIABILITY_RELIABLE;
  dds_duration_t blocking;
  if (qos) dds_qget_reliability(qos, &rel, &blocking);
  m["reliability"] = rel == DDS_RELIABILITY_RELIABLE ? "reliable" : "best-effort";
  dds_durability_kind_t dur = DDS_DURABILITY_VOLATILE;
  if (qos) dds_qget_durability(qos, &dur);
  m["durability"] = dur == DDS_DURABILITY_TRANSIENT_LOCAL ? "transient-local"
                    : dur == DDS_DURABILITY_TRANSIENT    ? "transient"
                    : dur == DDS_DURABILITY_PERSISTENT   ? "persistent"
                                                         : "volatile";
  dds_history_kind_t hist = DDS_HISTORY_KEEP_LAST;
  int32_t depth = 1;
  if (qos) dds_qget_history(qos, &hist, &depth);
  m["history"] = hist == DDS_HISTORY_KEEP_ALL ? "keep-all" : "keep-last";
  m["depth"] = std::to_string(hist == DDS_HISTORY_KEEP_ALL ? 0 : depth);
  return m;
}

dds::Qos qos_from_metadata(const std::map<std::string, std::string>& m) {
  auto get = [&](const char* key) -> const std::string& {
    const auto it = m.find(key);
    if (it == m.end()) throw std::runtime_error(std::string("channel metadata has no ") + key);
    return it->second;
  };
  auto bad = [](const char* key, const std::string& v) {
    return std::runtime_error(std::string("channel metadata ") + key + "=\"" + v + "\" is not a known value");
  };
  dds::Qos q(dds_create_qos());
  const auto& rel = get("reliability");
  if (rel == "reliable")
    dds_qset_reliability(q.get(), DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  else if (rel == "best-effort")
    dds_qset_reliability(q.get(), DDS_RELIABILITY_BEST_EFFORT, 0);
  else
    throw bad("reliability", rel);
  const auto& dur = get("durability");
  if (dur == "volatile")
    dds_qset_durability(q.get(), DDS_DURABILITY_VOLATILE);
  else if (dur == "transient-local" || dur == "transient" || dur == "persistent")
    dds_qset_durability(q.get(), DDS_DURABILITY_TRANSIENT_LOCAL);  // Cyclone 0.10 has no durability service
  else
    throw bad("durability", dur);
  const auto& hist = get("history");
  const auto& depth_text = get("depth");
  int depth = 0;
  try {
    depth = std::stoi(depth_text);
  } catch (const std::exception&) {
    throw bad("depth", depth_text);
  }
  if (hist == "keep-all")
    dds_qset_history(q.get(), DDS_HISTORY_KEEP_ALL, 0);
  else if (hist == "keep-last" && depth >= 1)
    dds_qset_history(q.get(), DDS_HISTORY_KEEP_LAST, depth);
  else
    throw bad("history", hist + " " + depth_text);
  return q;
}

}  // namespace autonomy::recording
