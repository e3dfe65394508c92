#include "tools/xtypes/discovered_topic.hpp"

#include <dds/ddsi/ddsi_serdata.h>

#include <algorithm>
#include <cstring>

#include "common/dds/error.hpp"
#include "tools/xtypes/type_lookup.hpp"

// Debian's Cyclone 0.10.2 is built with type discovery (the library exports this and answers
// type lookups) but installs no dds/features.h, so dds.h leaves out the declaration behind
// DDS_HAS_TYPE_DISCOVERY. The same declaration as in dds.h:
#ifndef DDS_HAS_TYPE_DISCOVERY
extern "C" DDS_EXPORT dds_return_t dds_builtintopic_get_endpoint_type_info(dds_builtintopic_endpoint_t* builtintopic_endpoint,
                                                                         const dds_typeinfo_t** type_info);
#endif

namespace autonomy::xtypes {

namespace {

// A read loan on a built-in topic reader, given back however the reading ends.
class BuiltinLoan {
 public:
  explicit BuiltinLoan(dds_entity_t reader) : reader_(reader), buffers_(kMax, nullptr), infos_(kMax) {
    n_ = dds::check(dds_read_mask(reader, buffers_.data(), infos_.data(), kMax, kMax,
                                  DDS_ANY_SAMPLE_STATE | DDS_ANY_VIEW_STATE | DDS_ALIVE_INSTANCE_STATE),
                    "dds_read_mask(built-in topic)");
  }
  ~BuiltinLoan() {
    if (n_ > 0) dds_return_loan(reader_, buffers_.data(), n_);
  }
  BuiltinLoan(const BuiltinLoan&) = delete;
  BuiltinLoan& operator=(const BuiltinLoan&) = delete;
  int size() const { return n_; }
  const dds_builtintopic_endpoint_t* at(int i) const {
    return infos_[i].valid_data ? static_cast<const dds_builtintopic_endpoint_t*>(buffers_[i]) : nullptr;
  }

 private:
  static constexpr size_t kMax = 16384;
  dds_entity_t reader_;
  std::vector<void*> buffers_;
  std::vector<dds_sample_info_t> infos_;
  int n_ = 0;
};

// Whether the serialized form of a key field of this type can vary in size (a string, a
// sequence or a union in it). Of a struct used as a key: its key members, or all of them when
// none is marked.
bool discovered_topic_key_varies(const Type& type) {
  switch (type.kind) {
    case Kind::String:
    case Kind::Sequence:
    case Kind::Union:
      return true;
    case Kind::Array:
      return type.element && discovered_topic_key_varies(*type.element);
    case Kind::Struct: {
      const bool any_marked =
          std::any_of(type.members.begin(), type.members.end(), [](const Member& m) { return m.key; });
      return std::any_of(type.members.begin(), type.members.end(), [&](const Member& m) {
        return (m.key || !any_marked) && m.type && discovered_topic_key_varies(*m.type);
      });
    }
    default:
      return false;
  }
}

// Cyclone 0.10.2's dds_create_topic_descriptor sets DDS_TOPIC_FIXED_KEY(_XCDR2) ("the serialized
// key fits in 16 bytes") for a key with a string in it (eclipse-cyclonedds/cyclonedds#1637 and
// #2185; not on Cyclone master). Cyclone then serializes such a key into a 16-byte buffer inside
// the sample and, when it does not fit, realloc()s that buffer: "realloc(): invalid pointer" on
// the first sample of a string-keyed topic. The descriptor's fields are const: a copy with the
// flags cleared, which owns the one Cyclone built (its keys and ops are shared).
std::shared_ptr<dds_topic_descriptor_t> discovered_topic_fix_key_flags(dds_topic_descriptor_t* built, const Type& type) {
  std::shared_ptr<dds_topic_descriptor_t> owner(built, [](dds_topic_descriptor_t* d) { dds_delete_topic_descriptor(d); });
  const bool key_varies =
      std::any_of(type.members.begin(), type.members.end(),
                  [](const Member& m) { return m.key && m.type && discovered_topic_key_varies(*m.type); });
  constexpr uint32_t kFixedKeyFlags = DDS_TOPIC_FIXED_KEY | DDS_TOPIC_FIXED_KEY_XCDR2;
  if (!key_varies || (built->m_flagset & kFixedKeyFlags) == 0) return owner;
  auto* copy = new dds_topic_descriptor_t{built->m_size,        built->m_align,   built->m_flagset & ~kFixedKeyFlags,
                                          built->m_nkeys,       built->m_typename, built->m_keys,
                                          built->m_nops,        built->m_ops,      built->m_meta,
                                          built->type_information, built->type_mapping,
                                          built->restrict_data_representation};
  return std::shared_ptr<dds_topic_descriptor_t>(copy, [owner](dds_topic_descriptor_t* d) mutable {
    delete d;
    owner.reset();
  });
}

}  // namespace

DiscoveredTopic compiled_topic(dds_entity_t participant, const std::string& name, const dds_topic_descriptor_t* descriptor) {
  DiscoveredTopic t;
  t.name = name;
  t.type_name = descriptor->m_typename;
  // Cyclone's descriptor built from type objects mishandles string keys (see above): the
  // compiled one is used for reading and writing, the type objects only for the tree.
  t.descriptor = std::shared_ptr<dds_topic_descriptor_t>(const_cast<dds_topic_descriptor_t*>(descriptor),
                                                         [](dds_topic_descriptor_t*) {});
  // Creating the topic registers its type in the domain's type library (local: no lookup waits).
  const dds::Entity topic(
      dds::check(dds_create_topic(participant, descriptor, name.c_str(), nullptr, nullptr), "dds_create_topic " + name));
  t.type = TypeLookup(participant, DDS_SECS(1)).resolve_entity(topic.handle());
  return t;
}

TopicTypeFinder::TopicTypeFinder(dds_entity_t participant)
    : participant_(participant),
      publications_(dds::check(dds_create_reader(participant, DDS_BUILTIN_TOPIC_DCPSPUBLICATION, nullptr, nullptr),
                               "dds_create_reader(DCPSPublication)")),
      subscriptions_(dds::check(dds_create_reader(participant, DDS_BUILTIN_TOPIC_DCPSSUBSCRIPTION, nullptr, nullptr),
                                "dds_create_reader(DCPSSubscription)")) {
  dds::check(dds_get_guid(participant, &own_), "dds_get_guid");
}

std::optional<DiscoveredTopic> TopicTypeFinder::find(const std::string& topic, dds_duration_t timeout) const {
  bool seen_without_type_info = false;
  for (dds_entity_t reader : {publications_.handle(), subscriptions_.handle()}) {
    BuiltinLoan loan(reader);
    for (int i = 0; i < loan.size(); ++i) {
      const auto* ep = loan.at(i);
      if (!ep || !ep->topic_name || topic != ep->topic_name) continue;
      if (std::memcmp(&ep->participant_key, &own_, sizeof(own_)) == 0) continue;
      const dds_typeinfo_t* info = nullptr;
      if (dds_builtintopic_get_endpoint_type_info(const_cast<dds_builtintopic_endpoint_t*>(ep), &info) !=
              DDS_RETCODE_OK ||
          !info) {
        seen_without_type_info = true;
        continue;
      }
      DiscoveredTopic t;
      t.name = topic;
      t.type_name = ep->type_name ? ep->type_name : "";
      TypeLookup lookup(participant_, timeout);
      t.type = lookup.resolve(info);
      dds_topic_descriptor_t* descriptor = nullptr;
      const dds_return_t rc = dds_create_topic_descriptor(DDS_FIND_SCOPE_GLOBAL, participant_, info, timeout, &descriptor);
      if (rc != DDS_RETCODE_OK)
        throw TypeLookupError(std::string("dds_create_topic_descriptor: ") + dds_strretcode(rc));
      t.descriptor = discovered_topic_fix_key_flags(descriptor, *t.type);
      return t;
    }
  }
  if (seen_without_type_info)
    throw TypeLookupError("the endpoints of \"" + topic + "\" announce no type information (a DDS without XTypes?)");
  return std::nullopt;
}

std::vector<std::string> TopicTypeFinder::topic_names() const {
  std::vector<std::string> names;
  for (dds_entity_t reader : {publications_.handle(), subscriptions_.handle()}) {
    BuiltinLoan loan(reader);
    for (int i = 0; i < loan.size(); ++i)
      if (const auto* ep = loan.at(i); ep && ep->topic_name && std::memcmp(&ep->participant_key, &own_, sizeof(own_)) != 0)
        names.emplace_back(ep->topic_name);
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

CdrReader::CdrReader(dds_entity_t participant, const DiscoveredTopic& topic, const dds_qos_t* qos)
    : descriptor_(topic.descriptor),
      topic_(dds::check(dds_create_topic(participant, descriptor_.get(), topic.name.c_str(), nullptr, nullptr),
                        "dds_create_topic " + topic.name)),
      reader_(dds::check(dds_create_reader(participant, topic_.handle(), qos, nullptr), "dds_create_reader " + topic.name)),
      condition_(dds::check(dds_create_readcondition(reader_.handle(), DDS_ANY_STATE),
                            "dds_create_readcondition " + topic.name)) {}

std::vector<CdrSample> CdrReader::take() {
  std::vector<CdrSample> out;
  constexpr uint32_t kBatch = 64;
  for (;;) {
    ddsi_serdata* data[kBatch] = {};
    dds_sample_info_t info[kBatch];
    const dds_return_t n = dds::check(dds_takecdr(reader_.handle(), data, kBatch, info, DDS_ANY_STATE), "dds_takecdr");
    for (int i = 0; i < n; ++i) {
      CdrSample s;
      s.valid = info[i].valid_data;
      s.instance_state = info[i].instance_state;
      s.instance = info[i].instance_handle;
      s.source_timestamp = info[i].source_timestamp;
      if (s.valid) {
        s.cdr.resize(ddsi_serdata_size(data[i]));
        ddsi_serdata_to_ser(data[i], 0, s.cdr.size(), s.cdr.data());
      }
      ddsi_serdata_unref(data[i]);
      out.push_back(std::move(s));
    }
    if (static_cast<uint32_t>(n) < kBatch) return out;
  }
}

}  // namespace autonomy::xtypes
