#pragma once
// A typed topic on a participant, named by a TopicSpec from the catalogue (common/dds/topics.hpp).
#include "common/dds/entity.hpp"
#include "common/dds/error.hpp"
#include "common/dds/participant.hpp"
#include "common/dds/qos.hpp"
#include "common/dds/type_traits.hpp"

namespace autonomy::dds {

template <typename T>
struct TopicSpec {
  const char* name;
  QosClass qos;
  using Value = T;
};

template <typename T>
class Topic {
 public:
  Topic(const Participant& participant, const TopicSpec<T>& spec)
      : spec_(spec),
        entity_(check(dds_create_topic(participant.handle(), DdsType<T>::descriptor(), spec.name,
                                       nullptr, nullptr),
                      std::string("dds_create_topic ") + spec.name)) {}

  dds_entity_t handle() const { return entity_.handle(); }
  const TopicSpec<T>& spec() const { return spec_; }

 private:
  TopicSpec<T> spec_;
  Entity entity_;
};

}  // namespace autonomy::dds
