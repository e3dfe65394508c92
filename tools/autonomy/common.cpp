#include "tools/autonomy/common.hpp"

#include <cmath>
#include <iostream>

namespace autonomy::tools {

void add_domain_option(CLI::App* cmd, int& domain) {
  cmd->add_option("--domain", domain, "DDS domain id (0-232)")
      ->envname("AUTONOMY_DOMAIN")
      ->check(CLI::Range(0, 232))
      ->capture_default_str();
}

Interrupt::Interrupt(service::ShutdownSignals& signals, const dds::Participant& participant)
    : signals_(signals), guard_(participant) {
  signals_.on_shutdown([this](int) { guard_.trigger(); });
}

Interrupt::~Interrupt() {
  // on_shutdown holds the signal thread's lock: once it returns, the callback no longer runs.
  signals_.on_shutdown(nullptr);
}

bool sleep_for(const Interrupt& interrupt, const dds::Participant& participant, std::chrono::nanoseconds d) {
  dds::WaitSet ws(participant);
  ws.attach(interrupt.condition(), 1);
  const auto deadline = std::chrono::steady_clock::now() + d;
  while (!interrupt.requested()) {
    const auto left = deadline - std::chrono::steady_clock::now();
    if (left <= std::chrono::nanoseconds::zero()) return true;
    ws.wait(left);
  }
  return false;
}

std::chrono::nanoseconds seconds(double s) {
  if (!(s > 0)) return std::chrono::nanoseconds::zero();
  if (s > 1e9) s = 1e9;
  return std::chrono::nanoseconds(static_cast<int64_t>(std::llround(s * 1e9)));
}

EndpointQos EndpointQos::of(const dds_qos_t* qos, bool writer) {
  EndpointQos q;
  q.reliable = writer;  // DDS defaults when a QoS is absent: writers reliable, readers best effort
  dds_reliability_kind_t rel;
  dds_duration_t blocking;
  if (qos && dds_qget_reliability(qos, &rel, &blocking)) q.reliable = rel == DDS_RELIABILITY_RELIABLE;
  dds_durability_kind_t dur;
  if (qos && dds_qget_durability(qos, &dur)) q.durability = dur;
  dds_history_kind_t hist;
  int32_t depth;
  if (qos && dds_qget_history(qos, &hist, &depth)) {
    q.history = hist;
    q.depth = depth;
  }
  return q;
}

const char* to_string(dds_durability_kind_t d) {
  switch (d) {
    case DDS_DURABILITY_VOLATILE:
      return "volatile";
    case DDS_DURABILITY_TRANSIENT_LOCAL:
      return "transient-local";
    case DDS_DURABILITY_TRANSIENT:
      return "transient";
    case DDS_DURABILITY_PERSISTENT:
      return "persistent";
  }
  return "?";
}

std::string EndpointQos::str() const {
  std::string s = reliable ? "reliable " : "best-effort ";
  s += to_string(durability);
  s += history == DDS_HISTORY_KEEP_ALL ? " keep-all" : " keep-last " + std::to_string(depth);
  return s;
}

void print_line(const std::string& line) { std::cout << line << std::endl; }

}  // namespace autonomy::tools
