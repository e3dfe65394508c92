// autonomy node info NAME: one of our processes (from its heartbeat, as `node list` finds it) and
// what it does on the domain: host, pid, program, state, and the topics it writes and reads, from
// discovery (the endpoints of its DDS participant, the one that writes its heartbeat, and any other
// participant of the same pid on the same host).
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <set>

#include "common/dds/error.hpp"
#include "common/dds/topics.hpp"
#include "tools/autonomy/commands.hpp"
#include "tools/autonomy/discovery.hpp"
#include "tools/autonomy/processes.hpp"
#include "tools/autonomy/suggest.hpp"
#include "tools/autonomy/text.hpp"

namespace autonomy::tools {

namespace {

struct NodeInfoOptions {
  int domain = 0;
  std::string name;
  double wait_s = 1.5;
};

// The participant that wrote a heartbeat (its writer as this reader matched it); "" if unknown.
std::string heartbeat_participant(dds_entity_t reader, dds_instance_handle_t writer) {
  dds_builtintopic_endpoint_t* ep = dds_get_matched_publication_data(reader, writer);
  if (!ep) return "";
  const std::string key = to_string(ep->participant_key);
  dds_builtintopic_free_endpoint(ep);
  return key;
}

// "autonomy/nav/goal_status  autonomy::GoalStatus  reliable transient-local keep-last 1", one line
// per topic and QoS (a process with two writers of one topic and QoS shows "(2 endpoints)").
std::vector<std::string> endpoint_lines(const std::vector<Endpoint>& endpoints) {
  std::map<std::string, int> lines;
  for (const auto& e : endpoints) ++lines[e.topic + "  " + e.type + "  " + e.qos.str()];
  std::vector<std::string> out;
  for (const auto& [line, n] : lines)
    out.push_back(n > 1 ? line + "  (" + std::to_string(n) + " endpoints)" : line);
  return out;
}

int run_node_info(const NodeInfoOptions& o, Context& ctx) {
  const auto slash = o.name.find('/');
  const std::string service = o.name.substr(0, slash);
  const std::string instance = slash == std::string::npos ? "main" : o.name.substr(slash + 1);
  if (service.empty() || instance.empty()) {
    std::cerr << "autonomy node info: \"" << o.name << "\" is not SERVICE/INSTANCE (or SERVICE for SERVICE/main)\n";
    return kExitUsage;
  }
  const std::string name = service + "/" + instance;

  dds::Participant participant(o.domain);
  Interrupt interrupt(ctx.signals, participant);
  Discovery discovery(participant);
  dds::Topic<msg::Heartbeat> topic(participant, dds::topics::heartbeat);
  dds::Reader<msg::Heartbeat> beats(participant, topic, every_process_qos().get());

  // Heartbeats are state (the last one arrives on matching): listen until the process is heard
  // and a moment more for the endpoints discovered with it, or --wait when it is not.
  ProcessTable table;
  dds::WaitSet waitset(participant);
  waitset.attach(beats.data_condition(), 1);
  waitset.attach(interrupt.condition(), 2);
  auto deadline = std::chrono::steady_clock::now() + seconds(o.wait_s);
  bool heard = false;
  for (;;) {
    table.update(beats.take());
    if (interrupt.requested()) return kExitInterrupted;
    if (!heard) {
      for (const auto& [key, row] : table.rows())
        if (key.name() == name && row.instance_state != dds::InstanceState::Disposed) heard = true;
      if (heard)
        deadline = std::min(deadline, std::chrono::steady_clock::now() + std::chrono::milliseconds(300));
    }
    const auto left = deadline - std::chrono::steady_clock::now();
    if (left <= std::chrono::nanoseconds::zero()) break;
    waitset.wait(left);
  }

  std::vector<const ProcessView*> rows;
  std::set<std::string> names;
  for (const auto& [key, row] : table.rows()) {
    if (row.instance_state == dds::InstanceState::Disposed) continue;  // stopped cleanly
    names.insert(key.name());
    if (key.name() == name) rows.push_back(&row);
  }
  if (rows.empty()) {
    const auto hint = did_you_mean(name, {names.begin(), names.end()});
    std::cerr << "autonomy node info: no process named \"" << name << "\" on domain " << o.domain
              << (hint.empty() ? "" : "; " + hint);
    if (names.empty())
      std::cerr << "; no autonomy processes seen in " << o.wait_s << " s: " << where_we_looked(o.domain);
    else
      std::cerr << " (`autonomy node list` shows the " << names.size() << " names heard)";
    std::cerr << "\n";
    return kExitUsage;
  }

  const auto processes = participant_processes(participant);
  const auto endpoints = discovery.endpoints();
  const dds_time_t now = dds_time();
  for (const auto* row : rows) {
    const auto& b = row->last;
    // Its participants: the heartbeat's, and every other one of the same pid on the same host.
    std::set<std::string> participants;
    const std::string own = heartbeat_participant(beats.handle(), row->writer);
    ParticipantProcess dds_process;
    if (!own.empty()) {
      participants.insert(own);
      if (const auto it = processes.find(own); it != processes.end()) dds_process = it->second;
    }
    if (dds_process.pid != "?")
      for (const auto& [key, p] : processes)
        if (p.pid == dds_process.pid && p.host == dds_process.host) participants.insert(key);
    std::vector<Endpoint> writes, reads;
    for (const auto& e : endpoints)
      if (participants.count(to_string(e.participant))) (e.writer ? writes : reads).push_back(e);

    std::string state = row->state();
    if (row->instance_state == dds::InstanceState::Alive && now - row->source_timestamp > silent_after_ns(b.period_ms))
      state = "stale (last heard as " + state + ")";
    char age[64];
    std::snprintf(age, sizeof(age), "%.1f s ago", static_cast<double>(now - row->source_timestamp) / 1e9);
    print_line("node: " + name);
    print_line("  host: " + b.host);
    print_line("  pid: " + std::to_string(b.pid));
    print_line("  program: " + dds_process.program);
    print_line("  state: " + state + ", heard " + age + ", up " + std::to_string(static_cast<int64_t>(b.uptime_s)) + " s");
    if (!b.capabilities.empty()) {
      std::string caps;
      for (const auto& c : b.capabilities) caps += (caps.empty() ? "" : ", ") + c;
      print_line("  capabilities: " + caps);
    }
    if (!b.detail.empty()) print_line("  detail: " + b.detail);
    std::string keys;
    for (const auto& k : participants) keys += (keys.empty() ? "" : ", ") + k;
    print_line("  dds participant: " + (keys.empty() ? std::string("not discovered") : keys));
    for (const auto* list : {&writes, &reads}) {
      const auto lines = endpoint_lines(*list);
      print_line(std::string(list == &writes ? "  writes" : "  reads") + " (" + std::to_string(lines.size()) +
                 " topics):");
      for (const auto& l : lines) print_line("    " + l);
    }
  }
  if (rows.size() > 1)
    std::cerr << "autonomy node info: " << rows.size() << " processes are named " << name << "\n";
  return kExitOk;
}

}  // namespace

Command add_node_info(CLI::App& node) {
  auto o = std::make_shared<NodeInfoOptions>();
  auto* cmd = node.add_subcommand(
      "info",
      "One of our processes, found by its heartbeat as `node list` finds it: host, pid, program, state, and the "
      "topics it writes and reads with their type and QoS (from discovery: the endpoints of its DDS participant). "
      "Two processes of one name are both shown, and warned about.");
  add_domain_option(cmd, o->domain);
  cmd->add_option("name", o->name, "SERVICE/INSTANCE, e.g. behavior/r1 (SERVICE alone means SERVICE/main)")
      ->required();
  cmd->add_option("--wait", o->wait_s, "Seconds to listen for the process's heartbeat")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->footer(
      "Exit codes: 0 printed; 1 DDS error; 2 no process of that name (with the nearest names heard) or bad "
      "arguments; 130 Ctrl-C.");
  return {cmd, [o](Context& ctx) { return run_node_info(*o, ctx); }};
}

}  // namespace autonomy::tools
