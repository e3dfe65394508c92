// autonomy topic echo: any topic's samples as JSON lines, printed by the walker from the topic's type.
#include <iostream>
#include <memory>

#include "common/dds/error.hpp"
#include "tools/autonomy/commands.hpp"
#include "tools/autonomy/discovered_reader.hpp"
#include "tools/autonomy/discovery.hpp"
#include "tools/autonomy/suggest.hpp"
#include "tools/autonomy/topic_registry.hpp"
#include "tools/xtypes/field_path.hpp"
#include "tools/xtypes/json_reader.hpp"
#include "tools/xtypes/type_lookup.hpp"

namespace autonomy::tools {

namespace {

struct EchoOptions {
  int domain = 0;
  std::string topic;
  int64_t count = 0;
  double timeout_s = 0.0;
  double discovery_s = 1.0;
  bool verbose = false;
  std::string field;
  std::string bytes = "base64";
};

xtypes::BytesStyle bytes_style_of(const std::string& name) {
  return name == "hex" ? xtypes::BytesStyle::Hex : name == "array" ? xtypes::BytesStyle::Numbers : xtypes::BytesStyle::Base64;
}

// --field checked against the type before waiting for samples; prints the error and returns false.
bool field_fits(const EchoOptions& o, const xtypes::Type& type) {
  if (o.field.empty()) return true;
  try {
    xtypes::check_field_path(type, o.field);
    return true;
  } catch (const xtypes::FieldPathError& e) {
    const std::string hint = did_you_mean(e.word, e.candidates);
    std::cerr << "autonomy topic echo: " << e.what() << (hint.empty() ? "" : "; " + hint) << "\n";
    return false;
  }
}

std::string dump(const xtypes::Json& j) { return j.dump(-1, ' ', false, xtypes::Json::error_handler_t::replace); }

enum Tag : dds_attach_t { kData = 1, kInterrupt = 2, kStatus = 3 };

int run_echo(const EchoOptions& o, Context& ctx) {
  const TopicEntry* ours = TopicRegistry::catalogue().find(o.topic);
  const auto start = std::chrono::steady_clock::now();
  const bool has_deadline = o.timeout_s > 0;
  const auto deadline = start + seconds(o.timeout_s);

  dds::Participant participant(o.domain);
  Interrupt interrupt(ctx.signals, participant);
  std::string why;
  auto discovery_wait = seconds(o.discovery_s);
  if (has_deadline) discovery_wait = std::min<std::chrono::nanoseconds>(discovery_wait, seconds(o.timeout_s));
  // The type: the catalogue's compiled in, any other topic's from discovery. Either way the
  // samples are printed by the one walker.
  std::optional<xtypes::DiscoveredTopic> topic;
  try {
    topic = find_any_topic(participant, o.topic, interrupt, discovery_wait);
  } catch (const xtypes::TypeLookupError& e) {
    std::cerr << "autonomy topic echo: " << o.topic << ": " << e.what() << "\n";
    return kExitFailed;
  }
  if (interrupt.requested()) return kExitOk;
  if (!topic) {
    auto names = TopicRegistry::catalogue().name_list();
    for (auto& n : discovered_topic_names(participant)) names.push_back(n);
    std::cerr << unknown_topic_message("autonomy topic echo", o.topic, names) << " (not in the catalogue, and no process on domain "
              << o.domain << " has an endpoint of it within " << o.discovery_s
              << " s; --discovery-wait waits longer)\n";
    return kExitUsage;
  }
  if (!field_fits(o, *topic->type)) return kExitUsage;
  xtypes::WalkOptions walk;
  walk.bytes = bytes_style_of(o.bytes);
  // What is left of the discovery wait (finding another process's topic took some of it) for
  // the writers whose QoS the reader mirrors.
  const auto writers_wait =
      std::max<std::chrono::nanoseconds>(std::chrono::nanoseconds::zero(), start + discovery_wait - std::chrono::steady_clock::now());
  const auto reader = open_mirroring_reader(participant, *topic, ours ? ours->qos : dds::QosClass::Event, interrupt,
                                            writers_wait, walk, &why);
  if (interrupt.requested()) return kExitOk;
  const std::string type_name = topic->type_name;
  const std::string topic_name = o.topic;
  if (o.verbose) std::cerr << "autonomy topic echo: " << topic_name << " (" << type_name << "): " << why << "\n";

  dds::WaitSet waitset(participant);
  waitset.attach(reader->data_condition(), kData);
  waitset.attach(interrupt.condition(), kInterrupt);
  dds::check(dds_set_status_mask(reader->handle(), DDS_REQUESTED_INCOMPATIBLE_QOS_STATUS), "dds_set_status_mask");
  waitset.attach(reader->handle(), kStatus);

  int64_t printed = 0;
  auto emit = [&](const xtypes::Json& j) {  // true once --count lines are out
    if (!o.field.empty() && !j.contains("instance_state")) {
      try {
        print_line(dump(xtypes::select_field(j, o.field)));
      } catch (const xtypes::FieldPathError& e) {  // e.g. an index beyond this sample's sequence
        std::cerr << "autonomy topic echo: " << e.what() << "\n";
        return false;
      }
    } else {
      print_line(dump(j));
    }
    ++printed;
    return o.count > 0 && printed >= o.count;
  };
  for (;;) {
    const auto samples = reader->take(true);
    for (size_t i = 0; i < samples.size(); ++i) {
      const auto& s = samples[i];
      if (!s.error.empty())
        std::cerr << "autonomy topic echo: a sample of " << topic_name << " does not fit its type " << type_name << ": "
                  << s.error << "\n";
      if (s.valid && !s.json.is_null() && emit(s.json)) return kExitOk;
      // A disposed instance (its writer retracted it, or stopped cleanly) is news, printed once
      // after the instance's last sample of the batch: Cyclone reports the disposal on that
      // sample when it was still unread, else as a sample without data. An instance that only
      // lost its writers (no_writers) is not printed, as ros2 topic echo would not.
      const bool last_of_instance = i + 1 == samples.size() || samples[i + 1].key != s.key;
      if (last_of_instance && s.instance_state == DDS_IST_NOT_ALIVE_DISPOSED) {
        xtypes::Json line = xtypes::Json::object();
        line["instance_state"] = "disposed";
        for (const auto& [k, v] : s.key.items()) line[k] = v;
        if (emit(line)) return kExitOk;
      }
    }
    if (interrupt.requested()) return kExitOk;

    dds_requested_incompatible_qos_status_t incompatible{};
    if (dds_get_requested_incompatible_qos_status(reader->handle(), &incompatible) == DDS_RETCODE_OK &&
        incompatible.total_count_change > 0)
      std::cerr << "autonomy topic echo: a writer of " << topic_name << " does not match this reader's QoS (policy id "
                << incompatible.last_policy_id << "); its samples are not shown\n";

    auto wait = std::chrono::nanoseconds(std::chrono::seconds(1));
    if (has_deadline) {
      const auto left = deadline - std::chrono::steady_clock::now();
      if (left <= std::chrono::nanoseconds::zero()) {
        std::cerr << "autonomy topic echo: timeout after " << o.timeout_s << " s on " << topic_name << ": " << printed
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
      "Print a topic's samples, one JSON object per line (every field; enums as lower-case names; octet sequences "
      "as {\"length\", \"base64\"}), printed by the one generic walker from the topic's XTypes type information: "
      "the catalogue's compiled in, any other topic's as its writers announce it in discovery. "
      "A sample that only reports a disposed instance prints {\"instance_state\":\"disposed\", <key fields>} "
      "(and counts as a sample). The reader mirrors the QoS of the writers it discovers (durability, reliability), so "
      "the current state of state topics shows at once.");
  add_domain_option(cmd, o->domain);
  cmd->add_option("topic", o->topic, "Topic name, e.g. autonomy/robot/state or any topic on the domain (see `autonomy topic list`)")->required();
  cmd->add_option("--field", o->field, "Print only this member: a.b, points[2].x (checked against the type)");
  cmd->add_option("--bytes", o->bytes, "Octet sequences as base64, hex or array (of numbers)")
      ->check(CLI::IsMember({"base64", "hex", "array"}))
      ->capture_default_str();
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
      "2 unknown topic, --field not in the type, or bad arguments." +
      topics);
  return {cmd, [o](Context& ctx) { return run_echo(*o, ctx); }};
}

}  // namespace autonomy::tools
