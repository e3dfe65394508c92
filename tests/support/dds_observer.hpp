#pragma once
// The test's own eyes on a DDS domain: Recorder<T> keeps every sample a reader has taken, and
// eventually() polls a condition until it holds or a deadline passes (never sleep-and-hope).
#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace autonomy::test {

// The QoS of the topic's class, but keep-all: a test must see every sample (e.g. each goal status
// transition), not only the newest per key. Durability and reliability stay those of the class,
// so a state-class reader still gets the writers' current state when it joins late.
inline dds::Qos observer_qos(dds::QosClass c) {
  dds::Qos q = dds::make_qos(c);
  dds_qset_history(q.get(), DDS_HISTORY_KEEP_ALL, 0);
  return q;
}

template <typename T>
class Recorder {
 public:
  Recorder(const dds::Participant& participant, const dds::TopicSpec<T>& spec)
      : topic_(participant, spec), reader_(participant, topic_, observer_qos(spec.qos).get()) {}

  // Takes what arrived since the last poll; returns only those (valid data) samples.
  std::vector<T> poll() {
    std::vector<T> fresh;
    for (auto& s : reader_.take()) {
      if (s.valid) {
        all_.push_back(s.value);
        fresh.push_back(std::move(s.value));
      } else {
        gone_.push_back(s);
      }
    }
    return fresh;
  }
  // Every valid sample taken so far, in take order (per key, in the writer's order).
  const std::vector<T>& all() const { return all_; }
  // Samples that only reported an instance state change (disposed / no writers).
  const std::vector<dds::Sample<T>>& gone() const { return gone_; }
  std::vector<T> matching(const std::function<bool(const T&)>& pred) const {
    std::vector<T> out;
    for (const auto& v : all_)
      if (pred(v)) out.push_back(v);
    return out;
  }
  const dds::Reader<T>& reader() const { return reader_; }

 private:
  dds::Topic<T> topic_;
  dds::Reader<T> reader_;
  std::vector<T> all_;
  std::vector<dds::Sample<T>> gone_;
};

// Generous by design: the machine may run other tests at the same time.
inline constexpr std::chrono::seconds kDeadline{30};

// Polls `condition` every 20 ms until it is true or `timeout` passed; fails with what was awaited.
inline ::testing::AssertionResult eventually(const std::string& what, const std::function<bool()>& condition,
                                             std::chrono::milliseconds timeout = kDeadline) {
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    if (condition()) return ::testing::AssertionSuccess();
    if (std::chrono::steady_clock::now() - start >= timeout)
      return ::testing::AssertionFailure() << "timed out after " << timeout.count() / 1000.0
                                           << " s waiting for: " << what;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

}  // namespace autonomy::test
