#include "tools/autonomy/processes.hpp"

namespace autonomy::tools {

std::string ProcessView::state() const {
  switch (instance_state) {
    case dds::InstanceState::Disposed:
      return "stopped";
    case dds::InstanceState::NoWriters:
      return "lost";
    case dds::InstanceState::Alive:
      break;
  }
  return has_data ? msg::to_string(last.state) : "unknown";
}

bool ProcessView::ready() const {
  return has_data && instance_state == dds::InstanceState::Alive && last.state == msg::ServiceState::Ready;
}

void ProcessTable::update(const std::vector<dds::Sample<msg::Heartbeat>>& samples) {
  for (const auto& s : samples) {
    auto& row = rows_[{s.value.service, s.value.instance}];
    row.instance_state = s.instance_state;  // the instance's state when the samples were taken
    if (!s.valid) {
      if (!row.has_data) row.last = s.value;  // keys only
      continue;
    }
    if (!row.has_data || s.source_timestamp >= row.source_timestamp) {
      row.last = s.value;
      row.source_timestamp = s.source_timestamp;
      row.has_data = true;
    }
  }
}

const ProcessView* ProcessTable::find(const std::string& service, const std::string& instance) const {
  const auto it = rows_.find({service, instance});
  return it == rows_.end() ? nullptr : &it->second;
}

}  // namespace autonomy::tools
