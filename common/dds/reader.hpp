#pragma once
// A typed reader: generated C samples in, C++ values (with their sample info) out.
#include "common/dds/topic.hpp"

#include <vector>

namespace autonomy::dds {

enum class InstanceState { Alive, Disposed, NoWriters };

template <typename T>
struct Sample {
  T value;             // for samples without data (valid == false) only the key fields are set
  bool valid = true;   // false: the sample only reports an instance state change
  InstanceState instance_state = InstanceState::Alive;
  dds_time_t source_timestamp = 0;
  dds_instance_handle_t publication_handle = 0;  // which writer sent it
};

template <typename T>
class Reader {
 public:
  using C = typename DdsType<T>::C;

  Reader(const Participant& participant, const Topic<T>& topic)
      : Reader(participant, topic, topic.spec().qos) {}
  Reader(const Participant& participant, const Topic<T>& topic, QosClass qos)
      : Reader(participant, topic, make_qos(qos).get()) {}
  // An explicit QoS, for tools that mirror the QoS of writers they discovered.
  Reader(const Participant& participant, const Topic<T>& topic, const dds_qos_t* qos)
      : entity_(check(dds_create_reader(participant.handle(), topic.handle(), qos, nullptr),
                      std::string("dds_create_reader of ") + topic.spec().name)),
        any_data_(check(dds_create_readcondition(entity_.handle(), DDS_ANY_STATE), "dds_create_readcondition")) {}

  // Removes and returns every available sample. dds_take groups samples by instance (key);
  // within one instance they keep their order.
  std::vector<Sample<T>> take() const { return collect(&dds_take); }

  // Returns every available sample, leaving it in the reader (for state topics).
  std::vector<Sample<T>> read() const { return collect(&dds_read); }

  // Triggers while the reader holds samples: attach it to a WaitSet.
  dds_entity_t data_condition() const { return any_data_.handle(); }
  dds_entity_t handle() const { return entity_.handle(); }

  uint32_t matched_writers() const {
    dds_subscription_matched_status_t st{};
    check(dds_get_subscription_matched_status(entity_.handle(), &st), "dds_get_subscription_matched_status");
    return st.current_count;
  }

 private:
  using Op = dds_return_t (*)(dds_entity_t, void**, dds_sample_info_t*, size_t, uint32_t);

  std::vector<Sample<T>> collect(Op op) const {
    constexpr size_t kBatch = 64;
    std::vector<Sample<T>> out;
    for (;;) {
      void* buffers[kBatch] = {nullptr};  // nullptr asks Cyclone to loan its own samples
      dds_sample_info_t infos[kBatch];
      const dds_return_t n = check(op(any_data_.handle(), buffers, infos, kBatch, kBatch), "dds_take/dds_read");
      if (out.empty()) out.reserve(static_cast<size_t>(n));  // one allocation, not log2(n) regrowths
      for (dds_return_t i = 0; i < n; ++i) {
        Sample<T> s{DdsType<T>::from_c(*static_cast<const C*>(buffers[i]))};
        s.valid = infos[i].valid_data;
        s.instance_state = infos[i].instance_state == DDS_IST_ALIVE         ? InstanceState::Alive
                           : infos[i].instance_state == DDS_IST_NOT_ALIVE_DISPOSED ? InstanceState::Disposed
                                                                              : InstanceState::NoWriters;
        s.source_timestamp = infos[i].source_timestamp;
        s.publication_handle = infos[i].publication_handle;
        out.push_back(std::move(s));
      }
      if (n > 0) check(dds_return_loan(any_data_.handle(), buffers, n), "dds_return_loan");
      if (static_cast<size_t>(n) < kBatch) return out;
    }
  }

  Entity entity_;
  Entity any_data_;  // read condition over every sample state; deleted before the reader
};

}  // namespace autonomy::dds
