// autonomy topic info TOPIC: who writes and reads a topic (any topic on the domain), each
// endpoint with its process (host, pid, program, from the properties Cyclone puts in every
// participant's discovery data) and QoS, and the writer/reader pairs whose QoS cannot match
// called out, with the policy at fault.
#include <algorithm>
#include <iostream>
#include <map>
#include <memory>

#include "common/dds/error.hpp"
#include "tools/autonomy/commands.hpp"
#include "tools/autonomy/discovery.hpp"
#include "tools/autonomy/suggest.hpp"
#include "tools/autonomy/topic_registry.hpp"

namespace autonomy::tools {

namespace {

struct InfoOptions {
  int domain = 0;
  std::string topic;
  double discovery_s = 1.0;
};

// Why a reader with QoS r cannot get a writer's samples with QoS w ("" when they match), for
// the request/offer policies the tools show.
std::string qos_mismatch(const EndpointQos& w, const EndpointQos& r) {
  if (r.reliable && !w.reliable) return "reliability: the reader requests reliable, the writer offers best-effort";
  if (r.durability > w.durability)
    return std::string("durability: the reader requests ") + to_string(r.durability) + ", the writer offers " +
           to_string(w.durability);
  return "";
}

int run_topic_info(const InfoOptions& o, Context& ctx) {
  dds::Participant participant(o.domain);
  Interrupt interrupt(ctx.signals, participant);
  Discovery discovery(participant);
  if (!sleep_for(interrupt, participant, seconds(o.discovery_s))) return kExitOk;
  std::vector<Endpoint> writers, readers;
  std::vector<std::string> names;
  for (auto& e : discovery.endpoints()) {
    names.push_back(e.topic);
    if (e.topic == o.topic) (e.writer ? writers : readers).push_back(e);
  }
  if (writers.empty() && readers.empty()) {
    for (const auto& n : TopicRegistry::catalogue().name_list()) names.push_back(n);
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
    std::cerr << unknown_topic_message("autonomy topic info", o.topic, names) << " (no process on domain " << o.domain
              << " writes or reads it now)\n";
    return kExitUsage;
  }
  const auto processes = participant_processes(participant);
  auto process_of = [&](const Endpoint& e) {
    const auto it = processes.find(to_string(e.participant));
    return it == processes.end() ? "participant " + to_string(e.participant) : it->second.str();
  };
  std::map<std::string, int> types;
  for (const auto* list : {&writers, &readers})
    for (const auto& e : *list) ++types[e.type];
  std::string type_line;
  for (const auto& [t, count] : types) type_line += (type_line.empty() ? "" : ", ") + t;
  print_line("Topic: " + o.topic);
  print_line("Type: " + type_line + (types.size() > 1 ? "  (DIFFERENT TYPE NAMES: endpoints of other types do not match)" : ""));
  const auto registry = TopicRegistry::catalogue();  // find() points into it
  if (const auto* entry = registry.find(o.topic))
    print_line("Catalogue: " + entry->type_name + ", QoS class " + dds::to_string(entry->qos));
  for (const auto* list : {&writers, &readers}) {
    print_line(std::string(list == &writers ? "Writers" : "Readers") + ": " + std::to_string(list->size()));
    for (const auto& e : *list)
      print_line("  " + process_of(e) + "  " + e.qos.str() + (types.size() > 1 ? "  type " + e.type : "") + "  " +
                 to_string(e.guid));
  }
  int mismatches = 0;
  for (const auto& w : writers)
    for (const auto& r : readers) {
      std::string why = qos_mismatch(w.qos, r.qos);
      if (why.empty() && w.type != r.type) why = "type " + w.type + " vs " + r.type;
      if (why.empty()) continue;
      if (mismatches++ == 0) print_line("QoS mismatches (these pairs do not communicate):");
      print_line("  writer " + process_of(w) + " -> reader " + process_of(r) + ": " + why);
    }
  if (mismatches == 0 && !writers.empty() && !readers.empty()) print_line("QoS: every writer/reader pair matches");
  return kExitOk;
}

}  // namespace

Command add_topic_info(CLI::App& topic) {
  auto o = std::make_shared<InfoOptions>();
  auto* cmd = topic.add_subcommand(
      "info",
      "Who writes and reads a topic (any topic on the domain): type, each writer and reader with its process (host, "
      "pid, program) and QoS, and the writer/reader pairs whose QoS (reliability, durability) or type name cannot "
      "match");
  add_domain_option(cmd, o->domain);
  cmd->add_option("topic", o->topic, "Topic name")->required();
  cmd->add_option("--discovery-wait", o->discovery_s, "Seconds to let discovery find the domain's endpoints")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->footer("Exit codes: 0 printed; 2 no endpoint of that topic on the domain (with the nearest names).");
  return {cmd, [o](Context& ctx) { return run_topic_info(*o, ctx); }};
}

}  // namespace autonomy::tools
