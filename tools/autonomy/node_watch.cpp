// autonomy node watch: follow the heartbeats of our processes and say, one line each as it
// happens, when one goes silent, is heard again, is hung (silent for its limit), stops or is
// gone; and when the simulator drops a lockstep participant or takes it back (autonomy/sim/status). deploy/launch.sh runs one per set to notice hung processes. While a process is silent,
// its last heartbeat is republished on autonomy/heartbeat/silent so that `node list` started
// later still shows it (stale) instead of dropping it.
#include <signal.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "common/dds/message_types.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"
#include "common/service/heartbeat.hpp"
#include "tools/autonomy/commands.hpp"
#include "tools/autonomy/liveliness.hpp"
#include "tools/autonomy/lockstep_feed.hpp"
#include "tools/autonomy/processes.hpp"

namespace autonomy::tools {

namespace {

struct WatchOptions {
  int domain = 0;
  std::vector<std::string> targets;
  double hang_after_s = 10.0;
  bool json = false;
  bool relay = true;
  bool lockstep = true;
};

int64_t monotonic_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// A process of this host whose pid no longer runs (or is a zombie: ended, not yet collected).
bool gone_from_this_host(const ProcessKey& key, const std::string& this_host) {
  if (key.host != this_host || key.pid <= 0) return false;
  if (::kill(key.pid, 0) != 0) return errno == ESRCH;
  std::ifstream stat("/proc/" + std::to_string(key.pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
  const auto paren = text.rfind(')');
  if (paren == std::string::npos || paren + 2 >= text.size()) return false;
  return text[paren + 2] == 'Z' || text[paren + 2] == 'X';
}

std::string describe(const LivelinessEvent& e) {
  char detail[256];
  switch (e.kind) {
    case LivelinessEvent::Kind::Heard:
      std::snprintf(detail, sizeof(detail), "heard, state %s", msg::to_string(e.last.state));
      break;
    case LivelinessEvent::Kind::Silent:
      std::snprintf(detail, sizeof(detail), "not heard for %.1f s (last state %s)", e.silent_s,
                    msg::to_string(e.last.state));
      break;
    case LivelinessEvent::Kind::HeardAgain:
      std::snprintf(detail, sizeof(detail), "heard again after %.1f s of silence", e.silent_s);
      break;
    case LivelinessEvent::Kind::Hung:
      std::snprintf(detail, sizeof(detail), "hung: not heard for %.1f s (limit %g s)", e.silent_s, e.limit_s);
      break;
    case LivelinessEvent::Kind::Stopped:
      std::snprintf(detail, sizeof(detail), "stopped cleanly");
      break;
    case LivelinessEvent::Kind::Gone:
      std::snprintf(detail, sizeof(detail), "no longer runs (not heard for %.1f s)", e.silent_s);
      break;
  }
  return std::string(to_string(e.kind)) + " " + e.process.name() + " pid " + std::to_string(e.process.pid) + " on " +
         e.process.host + ": " + detail;
}

nlohmann::ordered_json to_json(const LivelinessEvent& e) {
  return {{"event", to_string(e.kind)},     {"service", e.process.service}, {"instance", e.process.instance},
          {"host", e.process.host},         {"pid", e.process.pid},         {"silent_s", e.silent_s},
          {"limit_s", e.limit_s},           {"last_state", msg::to_string(e.last.state)}};
}

nlohmann::ordered_json to_json(const msg::LockstepChange& c) {
  return {{"event", event_name(c)}, {"participant", c.participant}, {"tick", c.tick},
          {"number", c.number},     {"reason", c.reason}};
}

// The silent processes on autonomy/heartbeat/silent: per name, the newest silent one's last
// heartbeat with its own source timestamp; disposed when none of that name is silent.
class SilentRelay {
 public:
  explicit SilentRelay(const dds::Participant& participant)
      : topic_(participant, silent_heartbeat), writer_(participant, topic_) {}

  void publish(const std::vector<const ProcessView*>& silent) {
    std::map<std::string, const ProcessView*> newest;
    for (const auto* row : silent) {
      auto& slot = newest[row->name()];
      if (!slot || row->source_timestamp > slot->source_timestamp) slot = row;
    }
    for (auto it = relayed_.begin(); it != relayed_.end();) {
      if (newest.count(it->first)) {
        ++it;
        continue;
      }
      writer_.dispose(it->second);
      it = relayed_.erase(it);
    }
    for (const auto& [name, row] : newest) {
      const auto it = relayed_.find(name);
      if (it != relayed_.end() && key_of(it->second) == row->key()) continue;
      using C = dds::DdsType<msg::Heartbeat>::C;
      C sample{};
      dds::Arena arena;
      dds::DdsType<msg::Heartbeat>::to_c(row->last, sample, arena);
      dds::check(dds_write_ts(writer_.handle(), &sample, row->source_timestamp), "dds_write_ts");
      relayed_[name] = row->last;
    }
  }

 private:
  dds::Topic<msg::Heartbeat> topic_;
  dds::Writer<msg::Heartbeat> writer_;
  std::map<std::string, msg::Heartbeat> relayed_;  // name -> the heartbeat published for it
};

int run_watch(const WatchOptions& o, Context& ctx) {
  LivelinessRules rules;
  rules.hang_after_s = o.hang_after_s;
  for (const auto& t : o.targets) {
    const auto eq = t.find('=');
    std::string name = t.substr(0, eq);
    if (name.find('/') == std::string::npos) name += "/main";
    const auto slash = name.find('/');
    if (slash == 0 || slash + 1 == name.size()) {
      std::cerr << "autonomy node watch: \"" << t << "\" is not SERVICE/INSTANCE[=SECONDS]\n";
      return kExitUsage;
    }
    if (eq != std::string::npos) {
      char* end = nullptr;
      const std::string limit = t.substr(eq + 1);
      const double s = std::strtod(limit.c_str(), &end);
      if (limit.empty() || *end != '\0' || !(s >= 0) || s > 1e6) {
        std::cerr << "autonomy node watch: \"" << t << "\": the limit after = must be seconds (0: never hung)\n";
        return kExitUsage;
      }
      rules.hang_after_by_name[name] = s;
    }
    rules.only.push_back(name);
  }
  const std::string this_host = service::host_name();

  dds::Participant participant(o.domain);
  Interrupt interrupt(ctx.signals, participant);
  dds::Topic<msg::Heartbeat> topic(participant, dds::topics::heartbeat);
  dds::Reader<msg::Heartbeat> reader(participant, topic, every_process_qos().get());
  std::unique_ptr<SilentRelay> relay;
  if (o.relay) relay = std::make_unique<SilentRelay>(participant);
  dds::WaitSet waitset(participant);
  waitset.attach(reader.data_condition(), 1);
  waitset.attach(interrupt.condition(), 2);
  std::optional<dds::Topic<msg::SimulatorStatus>> status_topic;
  std::optional<dds::Reader<msg::SimulatorStatus>> status_reader;
  if (o.lockstep) {
    status_topic.emplace(participant, dds::topics::sim_status);
    status_reader.emplace(participant, *status_topic);
    waitset.attach(status_reader->data_condition(), 3);
  }
  LockstepFeed lockstep;

  std::fprintf(stderr, "autonomy node watch: watching %s on domain %d; hung after %g s without a heartbeat%s\n",
               rules.only.empty() ? "every process" : (std::to_string(rules.only.size()) + " processes").c_str(),
               o.domain, o.hang_after_s, rules.hang_after_by_name.empty() ? "" : " (some have their own limit)");

  ProcessTable table;
  LivelinessMonitor monitor(rules);
  const auto is_gone = [&](const ProcessKey& key) { return gone_from_this_host(key, this_host); };
  while (!interrupt.requested()) {
    table.update(reader.take(), monotonic_ns());
    for (const auto& e : monitor.check(table, monotonic_ns(), is_gone)) {
      print_line(o.json ? to_json(e).dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) : describe(e));
    }
    if (status_reader)
      for (const auto& st : status_reader->take()) {
        if (!st.valid) continue;
        uint64_t missed = 0;
        for (const auto& c : lockstep.take(st.value, &missed)) {
          if (missed > 0 && !o.json)
            std::fprintf(stderr, "autonomy node watch: %llu lockstep changes were missed\n",
                         static_cast<unsigned long long>(missed));
          missed = 0;
          print_line(o.json ? to_json(c).dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) : tools::describe(c));
        }
      }
    if (relay) relay->publish(monitor.silent(table));
    waitset.wait(std::chrono::milliseconds(100));
  }
  return kExitOk;
}

}  // namespace

Command add_node_watch(CLI::App& node) {
  auto o = std::make_shared<WatchOptions>();
  auto* cmd = node.add_subcommand(
      "watch",
      "Follow the heartbeats and print one line per change, until Ctrl-C: EVENT SERVICE/INSTANCE pid PID on HOST: "
      "DETAIL, where EVENT is heard (for the first time), silent (not heard for 3 heartbeat periods, at least 1 s, or its DDS lease expired), "
      "heard_again, hung (silent for the limit), stopped (a clean stop) or gone (a process of this host that no "
      "longer runs). Lockstep changes the simulator reports (autonomy/sim/status) are lines too: lockstep_dropped "
      "PARTICIPANT at tick T: REASON (it did not acknowledge a tick within the ack timeout) and lockstep_rejoined "
      "PARTICIPANT at tick T: REASON. While a process is silent its last heartbeat is republished on autonomy/heartbeat/silent, so "
      "that `autonomy node list` shows it as stale. deploy/launch.sh runs one for its set.");
  add_domain_option(cmd, o->domain);
  cmd->add_option("process", o->targets,
                  "SERVICE/INSTANCE to watch (SERVICE alone: SERVICE/main), optionally =SECONDS: its own hang limit "
                  "(0: never hung). None: every process on the domain");
  cmd->add_option("--hang-after", o->hang_after_s, "Seconds without a heartbeat after which a process is hung (0: never)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  cmd->add_flag("--json", o->json,
                "One JSON object per line: {event, service, instance, host, pid, silent_s, limit_s, last_state}; "
                "lockstep changes: {event, participant, tick, number, reason}");
  cmd->add_flag("!--no-relay", o->relay, "Do not republish silent processes on autonomy/heartbeat/silent");
  cmd->add_flag("!--no-lockstep", o->lockstep, "Do not print the simulator's lockstep drops and rejoins");
  cmd->footer("Exit codes: 0 after Ctrl-C or SIGTERM; 1 DDS error; 2 bad arguments.");
  return {cmd, [o](Context& ctx) { return run_watch(*o, ctx); }};
}

}  // namespace autonomy::tools
