// autonomy: topics and processes on a DDS domain, in the manner of `ros2 topic` and `ros2 node`.
// Each subcommand lives in its own file (topic_*.cpp, node_*.cpp); this file only wires them.
#include <iostream>

#include "common/dds/error.hpp"
#include "common/service/shutdown.hpp"
#include "tools/autonomy/commands.hpp"
#include "tools/autonomy/suggest.hpp"

namespace {

// Checks the command words (`autonomy topic echo ...`) before CLI11 parses: a wrong word gets
// its name and the nearest command instead of CLI11's "A subcommand is required". Only levels
// that take no options of their own are walked, so every word there must be a command.
int check_command_words(const CLI::App& app, int argc, char** argv) {
  const CLI::App* at = &app;
  std::string path = "autonomy";
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    const auto subs = at->get_subcommands([](const CLI::App*) { return true; });
    if (subs.empty() || word.empty() || word[0] == '-') return 0;
    std::vector<std::string> names;
    const CLI::App* next = nullptr;
    for (const auto* s : subs) {
      names.push_back(s->get_name());
      if (s->get_name() == word) next = s;
    }
    if (!next) {
      const auto hint = autonomy::tools::did_you_mean(word, names, 2);
      std::string all;
      for (size_t k = 0; k < names.size(); ++k) all += (k ? ", " : "") + names[k];
      std::cerr << path << ": unknown command \"" << word << "\"" << (hint.empty() ? "" : "; " + hint)
                << " (commands: " << all << "; " << path << " --help)\n";
      return autonomy::tools::kExitUsage;
    }
    at = next;
    path += " " + word;
  }
  const auto subs = at->get_subcommands([](const CLI::App*) { return true; });
  if (!subs.empty() && at->get_require_subcommand_min() > 0) {
    std::string all;
    for (size_t k = 0; k < subs.size(); ++k) all += (k ? ", " : "") + subs[k]->get_name();
    std::cerr << path << ": a command is needed after \"" << path << "\": " << all << " (" << path << " --help)\n";
    return autonomy::tools::kExitUsage;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace autonomy::tools;
  // First: blocks SIGINT/SIGTERM before Cyclone starts its threads; Ctrl-C then reaches the
  // commands as a guard condition (Interrupt), and every command returns normally.
  autonomy::service::ShutdownSignals signals;

  CLI::App app{"Topics and processes of the autonomy middleware on a DDS domain.", "autonomy"};
  app.require_subcommand(1);
  app.footer(
      "Exit codes: 0 success; 1 failure (timeout, not acknowledged, DDS error); 2 usage error (bad arguments, "
      "unknown topic, JSON that does not fit the message); 130 interrupted (Ctrl-C) before the goal of "
      "pub or node wait was reached. echo, hz and bw end with 0 on Ctrl-C.\n"
      "Environment: AUTONOMY_DOMAIN (default for --domain), CYCLONEDDS_URI (Cyclone DDS configuration, e.g. "
      "file://.../deploy/dds/loopback.xml).");
  auto* topic = app.add_subcommand("topic", "Topics: list, echo, hz, bw, pub, type, info");
  topic->require_subcommand(1);
  auto* node = app.add_subcommand("node", "Our processes, from their heartbeats: list, info, wait, watch");
  node->require_subcommand(1);
  auto* courier = app.add_subcommand("courier", "The courier service: send, jobs, cancel; knowledge (what it learned)");
  courier->require_subcommand(1);
  auto* bag = app.add_subcommand("bag", "Recordings (MCAP): info");
  bag->require_subcommand(1);
  auto* interface = app.add_subcommand("interface", "Types: show (as IDL)");
  interface->require_subcommand(1);

  const std::vector<Command> commands = {add_topic_list(*topic), add_topic_echo(*topic), add_topic_hz(*topic),
                                         add_topic_bw(*topic),   add_topic_pub(*topic),  add_topic_type(*topic),
                                         add_topic_info(*topic), add_interface_show(*interface),
                                         add_node_list(*node),   add_node_info(*node),   add_node_wait(*node),
                                         add_node_watch(*node),
                                         add_courier_send(*courier), add_courier_jobs(*courier),
                                         add_courier_cancel(*courier), add_courier_knowledge(*courier),
                                         add_plan(app), add_record(app), add_play(app), add_replay(app), add_bag_info(*bag)};
  if (const int bad = check_command_words(app, argc, argv); bad != 0) return bad;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? kExitOk : kExitUsage;
  }

  Context context{signals};
  for (const auto& c : commands) {
    if (!c.app->parsed()) continue;
    try {
      return c.run(context);
    } catch (const autonomy::dds::DdsError& e) {
      std::cerr << "autonomy: DDS error: " << e.what() << "\n";
      return kExitFailed;
    } catch (const std::exception& e) {
      std::cerr << "autonomy: " << e.what() << "\n";
      return kExitFailed;
    }
  }
  return kExitUsage;  // not reached: CLI11 requires a subcommand
}
