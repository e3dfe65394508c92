// autonomy topic list: every topic on the domain, from the built-in discovery topics.
#include <algorithm>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include "tools/autonomy/commands.hpp"
#include "tools/autonomy/text.hpp"
#include "tools/autonomy/discovery.hpp"

namespace autonomy::tools {

namespace {

struct TopicListOptions {
  int domain = 0;
  double wait_s = 1.0;
  bool verbose = false;
};

struct TopicRow {
  std::set<std::string> types;
  std::vector<Endpoint> writers;
  std::vector<Endpoint> readers;
};

// "reliable transient-local keep-last 1", or "2x A; 1x B" when the writers differ.
std::string qos_summary(const std::vector<Endpoint>& endpoints) {
  if (endpoints.empty()) return "-";
  std::map<std::string, int> counts;
  for (const auto& e : endpoints) ++counts[e.qos.str()];
  if (counts.size() == 1) return counts.begin()->first;
  std::string out;
  for (const auto& [qos, n] : counts) out += (out.empty() ? "" : "; ") + std::to_string(n) + "x " + qos;
  return out;
}

std::string join(const std::set<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ",") + s;
  return out;
}

std::string pad(const std::string& s, size_t width) {
  return s.size() >= width ? s : s + std::string(width - s.size(), ' ');
}

int run_topic_list(const TopicListOptions& o, Context& ctx) {
  dds::Participant participant(o.domain);
  Discovery discovery(participant);
  Interrupt interrupt(ctx.signals, participant);
  if (!sleep_for(interrupt, participant, seconds(o.wait_s))) return kExitInterrupted;

  std::map<std::string, TopicRow> topics;  // sorted by name
  for (auto& e : discovery.endpoints()) {
    auto& row = topics[e.topic];
    row.types.insert(e.type);
    (e.writer ? row.writers : row.readers).push_back(std::move(e));
  }
  if (topics.empty()) {
    std::cerr << "no topics seen on domain " << o.domain << " within " << o.wait_s << " s: " << where_we_looked(o.domain)
              << "\n";
    return kExitOk;
  }

  size_t name_w = 5, type_w = 4;
  for (const auto& [name, row] : topics) {
    name_w = std::max(name_w, name.size());
    type_w = std::max(type_w, join(row.types).size());
  }
  print_line(pad("TOPIC", name_w) + "  " + pad("TYPE", type_w) + "  " + "W   R   WRITER QOS");
  for (const auto& [name, row] : topics) {
    print_line(pad(name, name_w) + "  " + pad(join(row.types), type_w) + "  " +
               pad(std::to_string(row.writers.size()), 3) + " " + pad(std::to_string(row.readers.size()), 3) + " " +
               qos_summary(row.writers));
    if (!o.verbose) continue;
    for (const auto* list : {&row.writers, &row.readers}) {
      for (const auto& e : *list)
        print_line("    " + std::string(e.writer ? "writer " : "reader ") + to_string(e.guid) + "  " + e.qos.str());
    }
  }
  return kExitOk;
}

}  // namespace

Command add_topic_list(CLI::App& topic) {
  auto o = std::make_shared<TopicListOptions>();
  auto* cmd = topic.add_subcommand(
      "list",
      "List every topic seen on the domain, ours and other DDS processes' (from DCPSPublication and "
      "DCPSSubscription), sorted by name: type, number of writers (W) and readers (R), and the writers' "
      "QoS (reliability, durability, history). This tool's own endpoints are left out.");
  add_domain_option(cmd, o->domain);
  cmd->add_option("--wait", o->wait_s, "Seconds to listen for discovery before printing")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_flag("-v,--verbose", o->verbose, "Also one line per endpoint: writer/reader, GUID, QoS");
  cmd->footer("Exit codes: 0 listed (also when nothing was seen), 1 DDS error, 2 bad arguments, 130 Ctrl-C.");
  return {cmd, [o](Context& ctx) { return run_topic_list(*o, ctx); }};
}

}  // namespace autonomy::tools
