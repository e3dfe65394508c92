#include "common/service/heartbeat.hpp"

#include <unistd.h>

#include <cstdlib>

#include <utility>

namespace autonomy::service {

std::string host_name() {
  // A network namespace (deploy/hosts.sh) keeps the machine's hostname: the launcher names the
  // host a process runs on through AUTONOMY_HOST instead.
  if (const char* host = std::getenv("AUTONOMY_HOST"); host != nullptr && host[0] != '\0') return host;
  char name[256] = {0};
  if (gethostname(name, sizeof(name) - 1) != 0) return "unknown";
  return name;
}

namespace {
dds::Qos heartbeat_writer_qos() {
  dds::Qos q = dds::make_qos(dds::topics::heartbeat.qos);
  dds_qset_writer_data_lifecycle(q.get(), false);  // see ~HeartbeatPublisher
  return q;
}
}  // namespace

HeartbeatPublisher::HeartbeatPublisher(const dds::Participant& participant, std::string service,
                                       std::string instance, std::chrono::milliseconds period)
    : topic_(participant, dds::topics::heartbeat),
      writer_(participant, topic_, heartbeat_writer_qos().get()),
      period_(period),
      started_(std::chrono::steady_clock::now()) {
  beat_.service = std::move(service);
  beat_.instance = std::move(instance);
  beat_.host = host_name();
  beat_.pid = static_cast<int32_t>(getpid());
  beat_.period_ms = static_cast<uint32_t>(period.count());
}

HeartbeatPublisher::~HeartbeatPublisher() {
  try {
    writer_.dispose(beat_);
  } catch (...) {  // never throw from a destructor; the instance then ends as "lost"
  }
}

void HeartbeatPublisher::set_state(msg::ServiceState state) {
  if (beat_.state == state) return;
  beat_.state = state;
  publish();
}

void HeartbeatPublisher::set_capabilities(std::vector<std::string> capabilities) {
  if (beat_.capabilities == capabilities) return;
  beat_.capabilities = std::move(capabilities);
  publish();
}

void HeartbeatPublisher::set_world(uint64_t world_id) {
  if (beat_.world_id == world_id) return;
  beat_.world_id = world_id;
  publish();
}

void HeartbeatPublisher::set_detail(std::string detail) {
  if (beat_.detail == detail) return;
  beat_.detail = std::move(detail);
  publish();
}

void HeartbeatPublisher::publish() {
  beat_.uptime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  writer_.write(beat_);
}

}  // namespace autonomy::service
