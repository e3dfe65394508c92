// autonomy node list: our processes, from their heartbeats.
#include <cstdio>
#include <iostream>
#include <memory>

#include "common/dds/topics.hpp"
#include "tools/autonomy/commands.hpp"
#include "tools/autonomy/processes.hpp"
#include "tools/json/msg_json.hpp"

namespace autonomy::tools {

namespace {

struct Options {
  int domain = 0;
  double wait_s = 1.5;
  bool json = false;
  bool all = false;
};

int run(const Options& o, Context& ctx) {
  dds::Participant participant(o.domain);
  Interrupt interrupt(ctx.signals, participant);
  // Heartbeats are of the state class: the last one of every live process arrives at once.
  dds::Topic<msg::Heartbeat> topic(participant, dds::topics::heartbeat);
  dds::Reader<msg::Heartbeat> reader(participant, topic);
  if (!sleep_for(interrupt, participant, seconds(o.wait_s))) return kExitInterrupted;

  ProcessTable table;
  table.update(reader.read());
  const dds_time_t now = dds_time();

  std::vector<const ProcessView*> shown;
  for (const auto& [key, row] : table.rows()) {
    if (row.instance_state == dds::InstanceState::Disposed || !row.has_data) continue;  // stopped cleanly
    if (row.instance_state == dds::InstanceState::NoWriters && !o.all) continue;
    shown.push_back(&row);
  }
  auto age_of = [now](const ProcessView& r) { return static_cast<double>(now - r.source_timestamp) / 1e9; };

  if (o.json) {
    json::Json out = json::Json::array();
    for (const auto* r : shown) {
      out.push_back({{"service", r->last.service},
                     {"instance", r->last.instance},
                     {"host", r->last.host},
                     {"pid", r->last.pid},
                     {"state", r->state()},
                     {"age_s", age_of(*r)},
                     {"uptime_s", r->last.uptime_s},
                     {"period_ms", r->last.period_ms}});
    }
    print_line(out.dump(-1, ' ', false, json::Json::error_handler_t::replace));
    return kExitOk;
  }

  size_t sw = 7, iw = 8, hw = 4;
  for (const auto* r : shown) {
    sw = std::max(sw, r->last.service.size());
    iw = std::max(iw, r->last.instance.size());
    hw = std::max(hw, r->last.host.size());
  }
  char line[1024];
  std::snprintf(line, sizeof(line), "%-*s  %-*s  %-*s  %8s  %-8s  %7s", int(sw), "SERVICE", int(iw), "INSTANCE",
                int(hw), "HOST", "PID", "STATE", "AGE");
  print_line(line);
  for (const auto* r : shown) {
    std::snprintf(line, sizeof(line), "%-*s  %-*s  %-*s  %8d  %-8s  %6.1fs", int(sw), r->last.service.c_str(), int(iw),
                  r->last.instance.c_str(), int(hw), r->last.host.c_str(), r->last.pid, r->state().c_str(), age_of(*r));
    print_line(line);
  }
  if (shown.empty()) std::cerr << "no autonomy processes seen on domain " << o.domain << "\n";
  return kExitOk;
}

}  // namespace

Command add_node_list(CLI::App& node) {
  auto o = std::make_shared<Options>();
  auto* cmd = node.add_subcommand(
      "list",
      "List our processes from their heartbeats (autonomy/heartbeat): service, instance, host, pid, state "
      "(starting, ready, stopping; lost with -a) and age, the seconds since the last heartbeat (by its source "
      "timestamp). Cleanly stopped processes are not listed.");
  add_domain_option(cmd, o->domain);
  cmd->add_option("--wait", o->wait_s, "Seconds to listen before printing")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_flag("--json", o->json,
                "Print one JSON array of {service, instance, host, pid, state, age_s, uptime_s, period_ms}");
  cmd->add_flag("-a,--all", o->all, "Also processes whose heartbeat writer is gone without stopping (\"lost\")");
  cmd->footer("Exit codes: 0 listed (also when none); 1 DDS error; 2 bad arguments; 130 Ctrl-C.");
  return {cmd, [o](Context& ctx) { return run(*o, ctx); }};
}

}  // namespace autonomy::tools
