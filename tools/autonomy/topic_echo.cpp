// autonomy topic echo: a catalogue topic's samples as JSON lines.
#include <iostream>
#include <memory>

#include "tools/autonomy/commands.hpp"
#include "tools/autonomy/suggest.hpp"
#include "tools/autonomy/discovery.hpp"

namespace autonomy::tools {

namespace {

struct EchoOptions {
  int domain = 0;
  std::string topic;
  int64_t count = 0;
  double timeout_s = 0.0;
  double discovery_s = 1.0;
  bool verbose = false;
};

std::string dump(const json::Json& j) { return j.dump(-1, ' ', false, json::Json::error_handler_t::replace); }

enum Tag : dds_attach_t { kData = 1, kInterrupt = 2, kStatus = 3 };

int run_echo(const EchoOptions& o, Context& ctx) {
  const auto registry = TopicRegistry::catalogue();
  const TopicEntry* topic = registry.find(o.topic);
  if (!topic) {
    std::cerr << unknown_topic_message("autonomy topic echo", o.topic, registry.name_list()) << "\n";
    return kExitUsage;
  }
  const auto start = std::chrono::steady_clock::now();
  const bool has_deadline = o.timeout_s > 0;
  const auto deadline = start + seconds(o.timeout_s);

  dds::Participant participant(o.domain);
  Interrupt interrupt(ctx.signals, participant);
  std::string why;
  auto discovery_wait = seconds(o.discovery_s);
  if (has_deadline) discovery_wait = std::min<std::chrono::nanoseconds>(discovery_wait, seconds(o.timeout_s));
  const auto reader = open_mirroring_reader(participant, *topic, interrupt, discovery_wait, &why);
  if (o.verbose)
    std::cerr << "autonomy topic echo: " << topic->name << " (" << topic->type_name << "): " << why << "\n";

  dds::WaitSet waitset(participant);
  waitset.attach(reader->data_condition(), kData);
  waitset.attach(interrupt.condition(), kInterrupt);
  dds::check(dds_set_status_mask(reader->handle(), DDS_REQUESTED_INCOMPATIBLE_QOS_STATUS), "dds_set_status_mask");
  waitset.attach(reader->handle(), kStatus);

  int64_t printed = 0;
  auto emit = [&](const json::Json& j) {  // true once --count lines are out
    print_line(dump(j));
    ++printed;
    return o.count > 0 && printed >= o.count;
  };
  for (;;) {
    const auto samples = reader->take(true);
    for (size_t i = 0; i < samples.size(); ++i) {
      const auto& s = samples[i];
      if (s.valid && emit(s.json)) return kExitOk;
      // A disposed instance (its writer retracted it, or stopped cleanly) is news, printed once
      // after the instance's last sample of the batch: Cyclone reports the disposal on that
      // sample when it was still unread, else as a sample without data. An instance that only
      // lost its writers (no_writers) is not printed, as ros2 topic echo would not.
      const bool last_of_instance = i + 1 == samples.size() || samples[i + 1].key != s.key;
      if (last_of_instance && s.instance_state == dds::InstanceState::Disposed) {
        json::Json line = json::Json::object();
        line["instance_state"] = "disposed";
        for (const auto& [k, v] : s.key.items()) line[k] = v;
        if (emit(line)) return kExitOk;
      }
    }
    if (interrupt.requested()) return kExitOk;

    dds_requested_incompatible_qos_status_t incompatible{};
    if (dds_get_requested_incompatible_qos_status(reader->handle(), &incompatible) == DDS_RETCODE_OK &&
        incompatible.total_count_change > 0)
      std::cerr << "autonomy topic echo: a writer of " << topic->name << " does not match this reader's QoS (policy id "
                << incompatible.last_policy_id << "); its samples are not shown\n";

    auto wait = std::chrono::nanoseconds(std::chrono::seconds(1));
    if (has_deadline) {
      const auto left = deadline - std::chrono::steady_clock::now();
      if (left <= std::chrono::nanoseconds::zero()) {
        std::cerr << "autonomy topic echo: timeout after " << o.timeout_s << " s on " << topic->name << ": " << printed
                  << (o.count > 0 ? " of " + std::to_string(o.count) : std::string()) << " sample(s)\n";
        return kExitFailed;
      }
      wait = std::min(wait, std::chrono::duration_cast<std::chrono::nanoseconds>(left));
    }
    waitset.wait(wait);
  }
}

}  // namespace

Command add_topic_echo(CLI::App& topic) {
  auto o = std::make_shared<EchoOptions>();
  auto* cmd = topic.add_subcommand(
      "echo",
      "Print a catalogue topic's samples, one JSON object per line (every field; enums as lower-case names). "
      "A sample that only reports a disposed instance prints {\"instance_state\":\"disposed\", <key fields>} "
      "(and counts as a sample). The reader mirrors the QoS of the writers it discovers (durability, reliability), so "
      "the current state of state topics shows at once.");
  add_domain_option(cmd, o->domain);
  cmd->add_option("topic", o->topic, "Topic name, e.g. autonomy/robot/state (see `autonomy topic list`)")->required();
  cmd->add_option("-n,--count", o->count, "Exit 0 after this many samples (0: no limit)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("-t,--timeout", o->timeout_s, "Exit 1 after this many seconds unless --count was reached (0: none)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--discovery-wait", o->discovery_s, "Seconds to wait for the topic's writers, to mirror their QoS")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_flag("-v,--verbose", o->verbose, "Tell on stderr which QoS the reader uses and why");
  const std::string topics = "\nTopics of the catalogue: " + TopicRegistry::catalogue().names() + ".";
  cmd->footer(
      "Exit codes: 0 --count samples printed, or stopped with Ctrl-C; 1 --timeout passed first, or DDS error; "
      "2 unknown topic or bad arguments." +
      topics);
  return {cmd, [o](Context& ctx) { return run_echo(*o, ctx); }};
}

}  // namespace autonomy::tools
