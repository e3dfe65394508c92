#pragma once
// Our processes as their heartbeats (autonomy/heartbeat) describe them: one row per process,
// (service, instance, host, pid), folded from the samples a heartbeat reader returns. Two
// processes started under one name are two rows: a duplicate shows instead of hiding behind the
// newer heartbeat.
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "common/dds/qos.hpp"
#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/msg/system.hpp"

namespace autonomy::tools {

// Processes that a watcher (`autonomy node watch`, run by deploy/launch.sh) no longer hears: the
// last heartbeat it had from each, republished as it was (same source timestamp) while the
// process stays silent, disposed when it is heard again, stops or is gone. A process that hangs
// cannot answer a tool that starts after it hung, so `node list` learns of it here. Same type
// and key as the heartbeat: two silent processes of one name are one instance here (the newer).
inline constexpr dds::TopicSpec<msg::Heartbeat> silent_heartbeat{"autonomy/heartbeat/silent", dds::QosClass::State};

// A heartbeat reader's QoS: the state class, but deep enough that several processes of one name
// all show (the class keeps one sample per name, the newest writer's).
dds::Qos every_process_qos();

// How long a process may go unheard before it is called silent ("stale" in `node list`): three
// of its heartbeat periods, at least one second.
int64_t silent_after_ns(uint32_t period_ms);

struct ProcessKey {
  std::string service, instance, host;
  int32_t pid = 0;
  std::string name() const { return service + "/" + instance; }
  bool operator<(const ProcessKey& o) const {
    return std::tie(service, instance, host, pid) < std::tie(o.service, o.instance, o.host, o.pid);
  }
  bool operator==(const ProcessKey& o) const {
    return std::tie(service, instance, host, pid) == std::tie(o.service, o.instance, o.host, o.pid);
  }
};
ProcessKey key_of(const msg::Heartbeat& beat);

struct ProcessView {
  msg::Heartbeat last;  // the newest heartbeat of this process
  // Alive; Disposed once this process stopped cleanly; NoWriters when its name's DDS instance
  // has no writer left (its lease expired: killed, hung or cut off).
  dds::InstanceState instance_state = dds::InstanceState::Alive;
  dds_time_t source_timestamp = 0;  // of `last`, by the process's clock
  int64_t heard_at_ns = 0;          // when `last` arrived, by the caller's clock (update())
  dds_instance_handle_t writer = 0;

  // "ready", "starting", "stopping"; "stopped" when disposed (a clean exit); "lost" when its
  // writer is gone without disposing (killed, or lease expired).
  std::string state() const;
  bool ready() const;
  std::string name() const { return last.service + "/" + last.instance; }
  ProcessKey key() const { return key_of(last); }
};

class ProcessTable {
 public:
  // received_at_ns: the caller's clock when the samples were taken (ProcessView::heard_at_ns).
  void update(const std::vector<dds::Sample<msg::Heartbeat>>& samples, int64_t received_at_ns = 0);
  const std::map<ProcessKey, ProcessView>& rows() const { return rows_; }
  // The process of that name that spoke last (by source timestamp), preferring one whose writer
  // is alive; nullptr if none.
  const ProcessView* find(const std::string& service, const std::string& instance) const;
  void forget(const ProcessKey& key);

 private:
  std::map<ProcessKey, ProcessView> rows_;  // sorted by service, instance, host, pid
  std::map<dds_instance_handle_t, ProcessKey> by_writer_;
};

}  // namespace autonomy::tools
