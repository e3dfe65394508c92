#pragma once
// A typed writer: C++ values in, generated C samples on the wire.
#include "common/dds/topic.hpp"

#include <chrono>
#include <thread>

namespace autonomy::dds {

template <typename T>
class Writer {
 public:
  using C = typename DdsType<T>::C;

  // qos defaults to the topic's class; tools pass another class to mirror a foreign writer.
  Writer(const Participant& participant, const Topic<T>& topic)
      : Writer(participant, topic, topic.spec().qos) {}
  Writer(const Participant& participant, const Topic<T>& topic, QosClass qos)
      : Writer(participant, topic, make_qos(qos).get()) {}
  // An explicit QoS, for tools (e.g. a class's QoS with autodispose turned off).
  Writer(const Participant& participant, const Topic<T>& topic, const dds_qos_t* qos)
      : entity_(check(dds_create_writer(participant.handle(), topic.handle(), qos, nullptr),
                      std::string("dds_create_writer of ") + topic.spec().name)) {}

  void write(const T& value) const {
    C sample{};
    Arena arena;
    DdsType<T>::to_c(value, sample, arena);
    check(dds_write(entity_.handle(), &sample), "dds_write");
  }

  // Disposes the instance whose key fields value carries: readers see it NOT_ALIVE_DISPOSED.
  void dispose(const T& key) const {
    C sample{};
    Arena arena;
    DdsType<T>::to_c(key, sample, arena);
    check(dds_dispose(entity_.handle(), &sample), "dds_dispose");
  }

  uint32_t matched_readers() const {
    dds_publication_matched_status_t st{};
    check(dds_get_publication_matched_status(entity_.handle(), &st), "dds_get_publication_matched_status");
    return st.current_count;
  }

  // Discovery is asynchronous: a volatile sample written before a reader is matched is lost.
  // Returns false when fewer than count readers matched within timeout.
  bool wait_for_readers(uint32_t count, std::chrono::milliseconds timeout) const {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (matched_readers() < count) {
      if (std::chrono::steady_clock::now() >= deadline) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return true;
  }

  dds_entity_t handle() const { return entity_.handle(); }

 private:
  Entity entity_;
};

}  // namespace autonomy::dds
