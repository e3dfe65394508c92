#pragma once
// What every `autonomy` command shares: the context main hands it, the --domain option, exit
// codes, Ctrl-C as a DDS guard condition, and QoS descriptions.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <functional>
#include <string>

#include "common/dds/participant.hpp"
#include "common/dds/qos.hpp"
#include "common/dds/waitset.hpp"
#include "common/service/shutdown.hpp"

namespace autonomy::tools {

// Exit codes of every command (also in `autonomy --help`).
enum ExitCode : int {
  kExitOk = 0,
  kExitFailed = 1,        // timeout, nothing seen, not acknowledged, DDS error
  kExitUsage = 2,         // bad arguments, unknown topic, JSON that does not fit the type
  kExitInterrupted = 130  // Ctrl-C before a command with a goal (pub, node wait) reached it
};

struct Context {
  service::ShutdownSignals& signals;
};

// A leaf subcommand and what runs when it was the one given.
struct Command {
  CLI::App* app = nullptr;
  std::function<int(Context&)> run;
};

// --domain, env AUTONOMY_DOMAIN, 0..232.
void add_domain_option(CLI::App* cmd, int& domain);

// SIGINT/SIGTERM trigger a guard condition for the lifetime of this object, so a command waits
// on its DDS conditions and on Ctrl-C in the same waitset.
class Interrupt {
 public:
  Interrupt(service::ShutdownSignals& signals, const dds::Participant& participant);
  ~Interrupt();
  Interrupt(const Interrupt&) = delete;
  Interrupt& operator=(const Interrupt&) = delete;

  bool requested() const { return guard_.triggered(); }
  dds_entity_t condition() const { return guard_.handle(); }

 private:
  service::ShutdownSignals& signals_;
  dds::GuardCondition guard_;
};

// Sleeps for d unless interrupted; returns false when interrupted.
bool sleep_for(const Interrupt& interrupt, const dds::Participant& participant, std::chrono::nanoseconds d);

std::chrono::nanoseconds seconds(double s);

// When a requester sends its request again. Matching is not symmetric: our reply reader can see
// the service's reply writer before that writer has seen our reader, and a reply written in
// between is lost (under load this happened to a planner rejection that came within
// milliseconds). The planner and the courier answer a repeated request id with the same reply,
// so a requester resends after 1, 2, 4, then every 8 s until its reply comes.
class ResendSchedule {
 public:
  using Clock = std::chrono::steady_clock;
  explicit ResendSchedule(Clock::time_point first_sent) : next_(first_sent + interval_) {}
  bool due(Clock::time_point now) const { return now >= next_; }
  void resent(Clock::time_point now) {
    interval_ = std::min(interval_ * 2, std::chrono::nanoseconds(std::chrono::seconds(8)));
    next_ = now + interval_;
  }
  Clock::time_point next() const { return next_; }

 private:
  std::chrono::nanoseconds interval_ = std::chrono::seconds(1);
  Clock::time_point next_;
};

// The parts of an endpoint's QoS that decide matching and late-joiner delivery.
struct EndpointQos {
  bool reliable = false;
  dds_durability_kind_t durability = DDS_DURABILITY_VOLATILE;
  dds_history_kind_t history = DDS_HISTORY_KEEP_LAST;
  int32_t depth = 1;

  static EndpointQos of(const dds_qos_t* qos, bool writer);
  // "reliable transient-local keep-last 1"
  std::string str() const;
  bool operator<(const EndpointQos& o) const { return str() < o.str(); }
  bool operator==(const EndpointQos& o) const { return str() == o.str(); }
};

const char* to_string(dds_durability_kind_t d);

// stdout line, flushed (tests and pipes read line by line).
void print_line(const std::string& line);

}  // namespace autonomy::tools
