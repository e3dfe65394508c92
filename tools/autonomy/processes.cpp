#include "tools/autonomy/processes.hpp"

#include <algorithm>

namespace autonomy::tools {

dds::Qos every_process_qos() {
  dds::Qos qos = dds::make_qos(dds::topics::heartbeat.qos);
  dds_qset_history(qos.get(), DDS_HISTORY_KEEP_LAST, 16);
  return qos;
}

int64_t silent_after_ns(uint32_t period_ms) {
  return std::max<int64_t>(3 * static_cast<int64_t>(period_ms) * 1'000'000, 1'000'000'000);
}

ProcessKey key_of(const msg::Heartbeat& beat) { return {beat.service, beat.instance, beat.host, beat.pid}; }

std::string ProcessView::state() const {
  switch (instance_state) {
    case dds::InstanceState::Disposed:
      return "stopped";
    case dds::InstanceState::NoWriters:
      return "lost";
    case dds::InstanceState::Alive:
      break;
  }
  return msg::to_string(last.state);
}

bool ProcessView::ready() const {
  return instance_state == dds::InstanceState::Alive && last.state == msg::ServiceState::Ready;
}

void ProcessTable::update(const std::vector<dds::Sample<msg::Heartbeat>>& samples, int64_t received_at_ns) {
  for (const auto& s : samples) {
    if (s.valid) {
      const ProcessKey key = key_of(s.value);
      auto [it, fresh] = rows_.try_emplace(key);
      ProcessView& row = it->second;
      if (fresh || s.source_timestamp >= row.source_timestamp) {
        row.last = s.value;
        row.source_timestamp = s.source_timestamp;
        row.heard_at_ns = received_at_ns;
      }
      row.writer = s.publication_handle;
      by_writer_[s.publication_handle] = key;
      // A sample of a disposed instance that another process of the name wrote later is still
      // this process's word: only a sample without data says that this one stopped.
      row.instance_state = s.instance_state == dds::InstanceState::NoWriters ? dds::InstanceState::NoWriters
                                                                              : dds::InstanceState::Alive;
      continue;
    }
    // A state change without data: key fields only. Disposed is the word of one writer (a
    // process that stopped cleanly); no writers concerns every process of the name.
    if (s.instance_state == dds::InstanceState::Disposed) {
      const auto w = by_writer_.find(s.publication_handle);
      if (w == by_writer_.end()) continue;  // a process this table never heard
      const auto it = rows_.find(w->second);
      if (it != rows_.end()) it->second.instance_state = dds::InstanceState::Disposed;
    } else if (s.instance_state == dds::InstanceState::NoWriters) {
      for (auto& [key, row] : rows_) {
        if (key.service == s.value.service && key.instance == s.value.instance &&
            row.instance_state == dds::InstanceState::Alive)
          row.instance_state = dds::InstanceState::NoWriters;
      }
    }
  }
}

const ProcessView* ProcessTable::find(const std::string& service, const std::string& instance) const {
  const ProcessView* best = nullptr;
  for (auto it = rows_.lower_bound({service, instance, "", INT32_MIN});
       it != rows_.end() && it->first.service == service && it->first.instance == instance; ++it) {
    const ProcessView& row = it->second;
    const bool alive = row.instance_state == dds::InstanceState::Alive;
    const bool best_alive = best && best->instance_state == dds::InstanceState::Alive;
    if (!best || (alive && !best_alive) || (alive == best_alive && row.source_timestamp > best->source_timestamp))
      best = &row;
  }
  return best;
}

void ProcessTable::forget(const ProcessKey& key) {
  const auto it = rows_.find(key);
  if (it == rows_.end()) return;
  by_writer_.erase(it->second.writer);
  rows_.erase(it);
}

}  // namespace autonomy::tools
