// autonomy topic pub: write JSON as any topic's message, checked and serialized by the topic's type.
#include <iostream>
#include <memory>

#include "common/dds/error.hpp"
#include "tools/autonomy/commands.hpp"
#include "tools/autonomy/suggest.hpp"
#include "tools/autonomy/processes.hpp"
#include "tools/autonomy/topic_registry.hpp"
#include "tools/autonomy/discovered_reader.hpp"
#include "tools/autonomy/discovery.hpp"
#include "tools/xtypes/cdr_encode.hpp"
#include "tools/xtypes/type_lookup.hpp"

#include <set>

namespace autonomy::tools {

namespace {

struct PubOptions {
  int domain = 0;
  std::string topic;
  std::string json_text;
  int64_t count = 1;
  double rate_hz = 1.0;
  double wait_s = 3.0;
  double ack_timeout_s = 5.0;
  bool quiet = false;
  bool anyway = false;
};

// Topics that one robot's controller reads, by the robot id in the message: every behavior
// process reads the whole topic and keeps its own robot's samples, so a matched reader does not
// mean that anyone serves the robot named. The controller of robot R has heartbeat behavior/R.
struct RobotAddressed {
  const char* topic;
  const char* service;
};
constexpr RobotAddressed kRobotAddressed[] = {{"autonomy/nav/goal", "behavior"}, {"autonomy/nav/cancel", "behavior"}};

const char* robot_service_of(const std::string& topic) {
  for (const auto& r : kRobotAddressed)
    if (topic == r.topic) return r.service;
  return nullptr;
}

// Waits (until `deadline`) for the heartbeat of SERVICE/robot; false with the robots that are
// served in `served` when none came. Heartbeats are state samples: a live controller's arrives
// as soon as its participant is discovered, so the usual answer costs no extra wait.
bool robot_served(Interrupt& interrupt, const dds::Participant& participant, const char* service,
                  const std::string& robot, std::chrono::steady_clock::time_point deadline, std::set<std::string>& served) {
  const dds::Topic<msg::Heartbeat> topic(participant, dds::topics::heartbeat);
  const dds::Reader<msg::Heartbeat> reader(participant, topic, every_process_qos().get());
  ProcessTable table;
  for (;;) {
    table.update(reader.read());
    served.clear();
    for (const auto& [key, row] : table.rows()) {
      if (key.service != service || row.instance_state != dds::InstanceState::Alive) continue;
      if (row.last.state == msg::ServiceState::Stopping) continue;
      if (key.instance == robot) return true;
      served.insert(key.instance);
    }
    if (std::chrono::steady_clock::now() >= deadline) return false;
    if (!sleep_for(interrupt, participant, std::chrono::milliseconds(20))) return false;
  }
}

int run_pub(const PubOptions& o, Context& ctx) {
  const TopicEntry* ours = TopicRegistry::catalogue().find(o.topic);
  dds::Participant participant(o.domain);
  Interrupt interrupt(ctx.signals, participant);
  // The type: the catalogue's compiled in, any other topic's from discovery (an endpoint of
  // another process must be there). Either way the JSON is checked and completed by that type.
  std::optional<xtypes::DiscoveredTopic> topic;
  try {
    topic = find_any_topic(participant, o.topic, interrupt, seconds(o.wait_s));
  } catch (const xtypes::TypeLookupError& e) {
    std::cerr << "autonomy topic pub: " << o.topic << ": " << e.what() << "\n";
    return kExitFailed;
  }
  if (!topic) {
    if (interrupt.requested()) return kExitInterrupted;
    auto names = TopicRegistry::catalogue().name_list();
    for (auto& n : discovered_topic_names(participant)) names.push_back(n);
    std::cerr << unknown_topic_message("autonomy topic pub", o.topic, names) << " (not in the catalogue, and no process on domain "
              << o.domain << " has an endpoint of it within " << o.wait_s << " s)\n";
    return kExitUsage;
  }
  xtypes::Encoded message;
  try {
    message = xtypes::json_to_cdr(*topic->type, xtypes::parse_json(o.json_text));
  } catch (const xtypes::CdrError& e) {
    std::cerr << "autonomy topic pub: " << e.what() << "\n  "
              << o.topic << " carries " << topic->type_name << " " << member_list(*topic->type) << " (`autonomy topic type "
              << o.topic << "` prints it)\n";
    return kExitUsage;
  }

  // The catalogue's class, or the QoS of the topic's writers. No dispose when this short-lived
  // writer goes: its readers see the instance lose its writer (no_writers), not a retraction of
  // what was published.
  dds::Qos qos = ours ? dds::make_qos(ours->qos)
                      : mirror_writers_qos(dds::QosClass::Event, Discovery(participant).writers_of(o.topic));
  dds_qset_writer_data_lifecycle(qos.get(), false);
  const auto writer = std::make_unique<TopicWriter>(participant, *topic, qos.get());
  const std::string topic_name = o.topic;

  // Volatile samples written before a reader is matched are lost: wait for one.
  const auto wait_deadline = std::chrono::steady_clock::now() + seconds(o.wait_s);
  while (writer->matched_readers() == 0 && std::chrono::steady_clock::now() < wait_deadline) {
    if (!sleep_for(interrupt, participant, std::chrono::milliseconds(10))) return kExitInterrupted;
  }
  if (writer->matched_readers() == 0)
    std::cerr << "autonomy topic pub: warning: no reader of " << topic_name << " matched within " << o.wait_s
              << " s; publishing anyway\n";

  // A goal for a robot that nobody drives would vanish in silence (no status ever comes): say so.
  if (const char* service = robot_service_of(topic_name); service && !o.anyway) {
    const std::string robot = message.complete.value("robot_id", "");
    std::set<std::string> served;
    if (!robot_served(interrupt, participant, service, robot, wait_deadline, served)) {
      if (interrupt.requested()) return kExitInterrupted;
      std::string list;
      for (const auto& r : served) list += (list.empty() ? "" : ", ") + r;
      std::cerr << "autonomy topic pub: no " << service << " process serves robot \"" << robot << "\" on domain "
                << o.domain << " (" << (list.empty() ? "none runs" : service + std::string(" runs for: ") + list)
                << "); nothing published (--anyway publishes regardless)\n";
      return kExitFailed;
    }
  }

  // With --count 0, Ctrl-C is the normal end: what was written is still acknowledged below.
  const bool until_interrupted = o.count == 0;
  const auto period = seconds(o.rate_hz > 0 ? 1.0 / o.rate_hz : 0.0);
  auto next = std::chrono::steady_clock::now();
  for (int64_t i = 1; until_interrupted || i <= o.count; ++i) {
    writer->write(message.cdr);
    if (!o.quiet) print_line("publishing #" + std::to_string(i) + ": " + message.complete.dump());
    if (!until_interrupted && i == o.count) break;
    next += period;
    const auto left = next - std::chrono::steady_clock::now();
    if (left > std::chrono::nanoseconds::zero()) (void)sleep_for(interrupt, participant, left);
    if (interrupt.requested()) {
      if (!until_interrupted) return kExitInterrupted;
      break;
    }
  }

  // Reliable samples may still be in flight (or waiting for a retransmit): wait for the
  // acknowledgements of every matched reader before the writer goes.
  const auto ack_deadline = std::chrono::steady_clock::now() + seconds(o.ack_timeout_s);
  for (;;) {
    const dds_return_t rc = dds_wait_for_acks(writer->handle(), DDS_MSECS(50));
    if (rc == DDS_RETCODE_OK) return kExitOk;
    if (rc != DDS_RETCODE_TIMEOUT) dds::check(rc, "dds_wait_for_acks");
    if (interrupt.requested() && !until_interrupted) return kExitInterrupted;
    if (std::chrono::steady_clock::now() >= ack_deadline) {
      std::cerr << "autonomy topic pub: not every reader acknowledged within " << o.ack_timeout_s << " s\n";
      return kExitFailed;
    }
  }
}

}  // namespace

Command add_topic_pub(CLI::App& topic) {
  auto o = std::make_shared<PubOptions>();
  auto* cmd = topic.add_subcommand(
      "pub",
      "Publish a message given as JSON on a topic, with the topic's QoS class. The JSON is checked against the topic's "
      "XTypes type: the catalogue's compiled in; any other topic's from discovery (a process must have an endpoint of "
      "it; the QoS mirrors its writers). Key fields are required; other fields left out take zero, \"\" or the first "
      "enum name. Waits for a reader (--wait), and before "
      "exiting for every matched reader to acknowledge (reliable topics). The writer lives only while "
      "pub runs: late joiners of a state topic get the message only until then (--count 0 keeps it up).\n"
      "Example: autonomy topic pub autonomy/nav/goal '{\"robot_id\":\"r1\",\"goal_id\":\"g1\",\"x\":17,\"y\":9}'");
  add_domain_option(cmd, o->domain);
  cmd->add_option("topic", o->topic, "Topic name, e.g. autonomy/nav/goal")->required();
  cmd->add_option("json", o->json_text, "The message as a JSON object")->required();
  cmd->add_option("-n,--count", o->count, "Number of times to publish (0: until Ctrl-C)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("-r,--rate", o->rate_hz, "Publications per second when --count is not 1 (0: back to back)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--wait", o->wait_s, "Seconds to wait for a matched reader before publishing (warns if none)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--ack-timeout", o->ack_timeout_s, "Seconds to wait for the readers' acknowledgements at the end")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", o->quiet, "Do not print each published message");
  cmd->add_flag("--anyway", o->anyway,
                "Publish a goal or cancel even when no behavior process serves its robot (by default that is "
                "refused with exit 1 and the robots that are served)");
  const std::string topics = "\nTopics of the catalogue: " + TopicRegistry::catalogue().names() + ".";
  cmd->footer(
      "Exit codes: 0 published and acknowledged (with --count 0: stopped by Ctrl-C); 1 not acknowledged in time, or "
      "DDS error; 2 unknown topic, "
      "invalid JSON, a missing key field, a wrong type or unknown field, bad arguments; 130 Ctrl-C before --count was "
      "reached." +
      topics);
  return {cmd, [o](Context& ctx) { return run_pub(*o, ctx); }};
}

}  // namespace autonomy::tools
