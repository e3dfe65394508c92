#pragma once
// Holds accepted team messages until their delivery time. Pure: time is passed in; the caller
// (the simulator's DDS node) forwards what take_due() returns.
//
// Order: by delivery time; messages due at the same time come out in the order they were
// offered. Payload is whatever the caller relays (a sample, an id, ...); it must be movable.
#include "simulator/radio/delivery.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace autonomy::sim::radio {

template <typename Payload>
class MessageRelay {
 public:
  struct Due {
    double deliver_at_s;
    Payload payload;
  };

  // Queues `payload` when `decision` delivers it; returns whether it was queued.
  bool offer(const DeliveryDecision& decision, Payload payload) {
    if (!decision.delivered()) return false;
    push(decision.deliver_at_s, std::move(payload));
    return true;
  }

  void push(double deliver_at_s, Payload payload) {
    heap_.push_back({deliver_at_s, next_seq_++, std::move(payload)});
    std::push_heap(heap_.begin(), heap_.end(), Later{});
  }

  // Removes and returns every message due at or before now_s, earliest first.
  std::vector<Due> take_due(double now_s) {
    std::vector<Due> out;
    while (!heap_.empty() && heap_.front().at <= now_s) {
      std::pop_heap(heap_.begin(), heap_.end(), Later{});
      out.push_back({heap_.back().at, std::move(heap_.back().payload)});
      heap_.pop_back();
    }
    return out;
  }

  std::optional<double> next_due_s() const {
    if (heap_.empty()) return std::nullopt;
    return heap_.front().at;
  }
  size_t pending() const { return heap_.size(); }
  void clear() { heap_.clear(); }

 private:
  struct Entry {
    double at;
    uint64_t seq;
    Payload payload;
  };
  struct Later {  // max-heap comparator that puts the earliest (time, seq) at the front
    bool operator()(const Entry& a, const Entry& b) const {
      return a.at > b.at || (a.at == b.at && a.seq > b.seq);
    }
  };
  std::vector<Entry> heap_;
  uint64_t next_seq_ = 0;
};

}  // namespace autonomy::sim::radio
