// autonomy node list: our processes, from their heartbeats, and the silent ones a watcher
// (`autonomy node watch`, run by deploy/launch.sh) still remembers.
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "common/dds/topics.hpp"
#include "tools/autonomy/commands.hpp"
#include "tools/autonomy/processes.hpp"
#include "tools/autonomy/text.hpp"

namespace autonomy::tools {

namespace {

struct Options {
  int domain = 0;
  double wait_s = 1.5;
  bool json = false;
  bool all = false;
};

struct Listed {
  const ProcessView* row = nullptr;
  std::string state;  // starting, ready, stopping; stale; stopped (with -a)
  bool from_watcher = false;
  double age_s = 0.0;  // since its last heartbeat, by its source timestamp
};

// Takes every sample for `wait` (or until Ctrl-C): a heartbeat reader deep enough that two
// processes of one name both show, and the watcher's silent processes.
bool listen(const Interrupt& interrupt, const dds::Participant& participant, std::chrono::nanoseconds wait,
            const dds::Reader<msg::Heartbeat>& beats, const dds::Reader<msg::Heartbeat>& silent,
            const dds::Reader<msg::SimulatorStatus>& sim_status, ProcessTable& heard, ProcessTable& remembered,
            std::optional<msg::SimulatorStatus>& status) {
  dds::WaitSet ws(participant);
  ws.attach(beats.data_condition(), 1);
  ws.attach(silent.data_condition(), 2);
  ws.attach(interrupt.condition(), 3);
  ws.attach(sim_status.data_condition(), 4);
  const auto deadline = std::chrono::steady_clock::now() + wait;
  for (;;) {
    heard.update(beats.take());
    remembered.update(silent.take());
    for (auto& st : sim_status.take())
      if (st.valid) status = std::move(st.value);
    if (interrupt.requested()) return false;
    const auto left = deadline - std::chrono::steady_clock::now();
    if (left <= std::chrono::nanoseconds::zero()) return true;
    ws.wait(left);
  }
}

int run(const Options& o, Context& ctx) {
  dds::Participant participant(o.domain);
  Interrupt interrupt(ctx.signals, participant);
  dds::Topic<msg::Heartbeat> topic(participant, dds::topics::heartbeat);
  dds::Reader<msg::Heartbeat> reader(participant, topic, every_process_qos().get());
  dds::Topic<msg::Heartbeat> silent_topic(participant, silent_heartbeat);
  dds::Reader<msg::Heartbeat> silent_reader(participant, silent_topic);

  // The simulator's status says which lockstep participants it dropped (not waited for now).
  dds::Topic<msg::SimulatorStatus> status_topic(participant, dds::topics::sim_status);
  dds::Reader<msg::SimulatorStatus> status_reader(participant, status_topic);

  ProcessTable heard, remembered;
  std::optional<msg::SimulatorStatus> sim_status;
  if (!listen(interrupt, participant, seconds(o.wait_s), reader, silent_reader, status_reader, heard, remembered,
              sim_status))
    return kExitInterrupted;
  // name -> the tick it was dropped at (the latest drop of the status's list; -1 when not listed).
  std::map<std::string, int64_t> lockstep_dropped;
  if (sim_status) {
    for (const auto& name : sim_status->lockstep_dropped) lockstep_dropped[name] = -1;
    for (const auto& c : sim_status->lockstep_changes)
      if (c.dropped && lockstep_dropped.count(c.participant)) lockstep_dropped[c.participant] = c.tick;
  }
  const dds_time_t now = dds_time();
  auto age_of = [now](const ProcessView& r) { return static_cast<double>(now - r.source_timestamp) / 1e9; };

  std::map<ProcessKey, Listed> listed;
  for (const auto& [key, row] : heard.rows()) {
    Listed l{&row, msg::to_string(row.last.state), false, age_of(row)};
    if (row.instance_state == dds::InstanceState::Disposed) {
      if (!o.all) continue;
      l.state = "stopped";
    } else if (row.instance_state == dds::InstanceState::NoWriters ||
               now - row.source_timestamp > silent_after_ns(row.last.period_ms)) {
      l.state = "stale";
    }
    listed[key] = l;
  }
  // A watcher's silent process: unless this listing heard it speak since (it resumed).
  for (const auto& [key, row] : remembered.rows()) {
    if (row.instance_state != dds::InstanceState::Alive) continue;  // heard again, stopped or gone
    const auto it = listed.find(key);
    if (it != listed.end() && it->second.row->source_timestamp > row.source_timestamp) continue;
    listed[key] = Listed{&row, "stale", true, age_of(row)};
  }

  std::map<std::string, int> per_name;
  std::map<uint64_t, int> per_world;  // worlds the listed processes follow (0: none yet)
  for (const auto& [key, l] : listed) {
    if (l.state != "stopped") ++per_name[key.name()];
    if (l.state != "stopped" && l.row->last.world_id != 0) ++per_world[l.row->last.world_id];
  }
  // A second process of one name is the usual sign of a second set on the domain: every row of
  // such a name is flagged, not only the newer one.
  auto duplicate = [&](const ProcessKey& key, const Listed& l) {
    return l.state != "stopped" && per_name[key.name()] > 1;
  };

  if (o.json) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const auto& [key, l] : listed) {
      const auto& b = l.row->last;
      out.push_back({{"service", b.service},
                     {"instance", b.instance},
                     {"host", b.host},
                     {"pid", b.pid},
                     {"state", l.state},
                     {"last_state", msg::to_string(b.state)},
                     {"age_s", l.age_s},
                     {"uptime_s", b.uptime_s},
                     {"period_ms", b.period_ms},
                     {"from_watcher", l.from_watcher},
                     {"duplicate", duplicate(key, l)},
                     {"lockstep_dropped", lockstep_dropped.count(key.name()) > 0},
                     {"world_id", b.world_id},
                     {"clock_samples_ignored", b.clock_samples_ignored},
                     {"detail", b.detail}});
    }
    print_line(out.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
    return kExitOk;
  }

  size_t sw = 7, iw = 8, hw = 4;
  for (const auto& [key, l] : listed) {
    sw = std::max(sw, key.service.size());
    iw = std::max(iw, key.instance.size());
    hw = std::max(hw, key.host.size());
  }
  char line[1024];
  std::snprintf(line, sizeof(line), "%-*s  %-*s  %-*s  %8s  %-8s  %7s", int(sw), "SERVICE", int(iw), "INSTANCE",
                int(hw), "HOST", "PID", "STATE", "AGE");
  print_line(line);
  for (const auto& [key, l] : listed) {
    std::string note;
    if (l.state == "stale") note = std::string("  last heard ") + (l.from_watcher ? "by a watcher, " : "") + "as " +
                                   msg::to_string(l.row->last.state);
    if (duplicate(key, l)) note += "  DUPLICATE";
    if (const auto d = lockstep_dropped.find(key.name()); d != lockstep_dropped.end())
      note += "  dropped from lockstep" + (d->second >= 0 ? " at tick " + std::to_string(d->second) : std::string());
    if (per_world.size() > 1 && l.row->last.world_id != 0) note += "  world " + std::to_string(l.row->last.world_id);
    if (l.row->last.clock_samples_ignored > 0)
      note += "  ignored " + std::to_string(l.row->last.clock_samples_ignored) + " clock samples";
    std::snprintf(line, sizeof(line), "%-*s  %-*s  %-*s  %8d  %-8s  %6.1fs%s", int(sw), key.service.c_str(), int(iw),
                  key.instance.c_str(), int(hw), key.host.c_str(), key.pid, l.state.c_str(), l.age_s, note.c_str());
    print_line(line);
  }
  for (const auto& [name, n] : per_name) {
    if (n > 1) std::cerr << "autonomy node list: " << n << " processes are named " << name << "\n";
  }
  if (per_world.size() > 1)
    std::cerr << "autonomy node list: processes follow " << per_world.size() << " worlds on domain " << o.domain
              << " (one world per domain: a second simulator or a forged clock)\n";
  if (listed.empty())
    std::cerr << "no autonomy processes seen on domain " << o.domain << ": " << where_we_looked(o.domain) << "\n";
  return kExitOk;
}

}  // namespace

Command add_node_list(CLI::App& node) {
  auto o = std::make_shared<Options>();
  auto* cmd = node.add_subcommand(
      "list",
      "List our processes from their heartbeats (autonomy/heartbeat), one row per process (two processes with one "
      "name are two rows, and a warning): service, instance, host, pid, state and age, the seconds since its last "
      "heartbeat (by its source timestamp). State is the heartbeat's (starting, ready, stopping), or stale when "
      "the process has not been heard for 3 heartbeat periods (at least 1 s) or its DDS lease expired: hung, "
      "stopped (SIGSTOP), killed or cut off. A process that went silent before this command started is listed "
      "when a watcher remembers it (autonomy/heartbeat/silent: deploy/launch.sh runs `autonomy node watch`). "
      "Cleanly stopped processes are not listed. A lockstep participant the simulator dropped (it did not "
      "acknowledge a tick within the ack timeout; autonomy/sim/status) is noted \"dropped from lockstep at tick T\" "
      "until it is back.");
  add_domain_option(cmd, o->domain);
  cmd->add_option("--wait", o->wait_s, "Seconds to listen before printing")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_flag("--json", o->json,
                "Print one JSON array of {service, instance, host, pid, state, last_state, age_s, uptime_s, "
                "period_ms, from_watcher, duplicate, lockstep_dropped, world_id, clock_samples_ignored, detail}");
  cmd->add_flag("-a,--all", o->all, "Also processes that stopped cleanly while this command listened (\"stopped\")");
  cmd->footer("Exit codes: 0 listed (also when none); 1 DDS error; 2 bad arguments; 130 Ctrl-C.");
  return {cmd, [o](Context& ctx) { return run(*o, ctx); }};
}

}  // namespace autonomy::tools
