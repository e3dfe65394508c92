#pragma once
// Our processes as their heartbeats (autonomy/heartbeat) describe them: one row per
// (service, instance), folded from the samples a heartbeat reader returns.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "common/dds/reader.hpp"
#include "common/msg/system.hpp"

namespace autonomy::tools {

struct ProcessView {
  msg::Heartbeat last;  // the newest heartbeat with data (key fields only if none came)
  bool has_data = false;
  dds::InstanceState instance_state = dds::InstanceState::Alive;
  dds_time_t source_timestamp = 0;

  // "ready", "starting", "stopping"; "stopped" when disposed (a clean exit); "lost" when its
  // writer is gone without disposing (killed, or lease expired).
  std::string state() const;
  bool ready() const;
  std::string name() const { return last.service + "/" + last.instance; }
};

class ProcessTable {
 public:
  void update(const std::vector<dds::Sample<msg::Heartbeat>>& samples);
  const std::map<std::pair<std::string, std::string>, ProcessView>& rows() const { return rows_; }
  const ProcessView* find(const std::string& service, const std::string& instance) const;

 private:
  std::map<std::pair<std::string, std::string>, ProcessView> rows_;  // sorted by service, instance
};

}  // namespace autonomy::tools
