// autonomy replay: a recorded lockstep run fed back into a fresh world, checked tick by tick
// (docs/recording.md, "Replay"). The fresh simulator runs the recorded scenario in lockstep and
// waits for the participant `replay`. This tool stands in for every process of the recording
// but the simulator: it republishes, at the tick each was given at, what the recording holds on
// the topics the fresh world reads and does not write (registrations, spawn requests, commands,
// acknowledgements, team messages, injected faults; tools/recording/replay_script.hpp says
// when each is due), holds every tick as a lockstep participant of its own until the world's
// outputs recorded for it have arrived, and compares them with the fresh world's: every recorded
// sample stamped with a tick, on the topics the world writes, must come back exactly.
#include <algorithm>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <set>

#include "common/dds/message_types.hpp"
#include "common/dds/waitset.hpp"
#include "common/mcap/reader.hpp"
#include "tools/autonomy/commands.hpp"
#include "tools/autonomy/discovery.hpp"
#include "tools/recording/raw_topic.hpp"
#include "tools/recording/replay_script.hpp"
#include "tools/xtypes/cdr_encode.hpp"
#include "tools/xtypes/cdr_json.hpp"
#include "tools/xtypes/type_lookup.hpp"

namespace autonomy::tools {

namespace {

using recording::Json;
using recording::RecordedSample;

constexpr const char* kClockTopic = "autonomy/clock";
constexpr const char* kRegistrationTopic = "autonomy/lockstep/registration";
constexpr const char* kAckTopic = recording::kLockstepAckTopic;

struct ReplayOptions {
  int domain = 0;
  std::string file;
  std::string participant = "replay";
  double world_wait_s = 30.0;
  double output_wait_s = 5.0;
  bool verbose = false;
  std::vector<std::string> ignore = {"autonomy/heartbeat", "autonomy/sim/status"};
};

// The fresh world's endpoints: the participant that writes the clock, once its endpoint list
// stopped growing (a process creates its readers and writers together at start).
struct World {
  std::set<std::string> writes, reads;
};

std::optional<World> discover_world(const Discovery& discovery, const Interrupt& interrupt,
                                    const dds::Participant& participant, double wait_s) {
  const auto clocks = wait_for_writers(discovery, kClockTopic, interrupt, participant, seconds(wait_s));
  if (clocks.empty()) return std::nullopt;
  const std::string world = to_string(clocks.front().participant);
  World w;
  std::size_t seen = 0;
  for (int stable = 0; stable < 3;) {
    w = {};
    for (const auto& e : discovery.endpoints())
      if (to_string(e.participant) == world) (e.writer ? w.writes : w.reads).insert(e.topic);
    stable = w.writes.size() + w.reads.size() == seen ? stable + 1 : 0;
    seen = w.writes.size() + w.reads.size();
    if (!sleep_for(interrupt, participant, std::chrono::milliseconds(200))) return std::nullopt;
  }
  return w;
}

// A recorded topic as the replay handles it: its type, and its reader or writer in the fresh world.
struct ReplayTopic {
  xtypes::TypePtr type;
  std::unique_ptr<recording::RawWriter> writer;  // inputs
  std::unique_ptr<recording::RawReader> reader;  // outputs and the clock
  bool ticked = false;                           // its values carry a top-level integer "tick"
  std::size_t recorded = 0;
};

// How to start the fresh world: the recorded simulator's scenario (its heartbeat's detail).
std::string simulator_command(const std::map<std::string, uint16_t>& channel_of,
                              std::map<uint16_t, std::vector<mcap::Message>>& messages, const std::string& participant,
                              int domain) {
  std::string config;
  const auto* heartbeat = recording::find_recordable("autonomy/heartbeat");
  if (const auto it = channel_of.find("autonomy/heartbeat"); it != channel_of.end() && heartbeat)
    for (const auto& m : messages[it->second]) {
      try {
        recording::DecodedSample d(heartbeat->descriptor, m.data);
        const auto h = dds::DdsType<msg::Heartbeat>::from_c(*static_cast<const dds::DdsType<msg::Heartbeat>::C*>(d.get()));
        if (h.service == "simulator" && !h.detail.empty()) config = h.detail;
      } catch (const std::runtime_error&) {
      }
    }
  std::string command = "simulator";
  if (config.empty()) command += " --config <the recorded scenario>";
  else if (config.rfind("builtin:", 0) != 0) command += " --config " + config;
  return command + " --mode lockstep --wait-for " + participant + " --domain " + std::to_string(domain);
}

std::optional<int64_t> tick_of(const Json& value) {
  if (value.is_object() && value.contains("tick") && value.at("tick").is_number_integer())
    return value.at("tick").get<int64_t>();
  return std::nullopt;
}

int run_replay(const ReplayOptions& o, Context& ctx) {
  // The recording, by channel.
  std::map<uint16_t, mcap::Channel> channels;
  std::map<uint16_t, std::vector<mcap::Message>> messages;
  {
    mcap::Reader reader(o.file);
    const auto report = reader.read([&](const mcap::Channel& c, const mcap::Schema*, const mcap::Message& m) {
      messages[c.id].push_back(m);
    });
    if (!report.complete) std::cerr << "autonomy replay: " << o.file << ": " << report.note << "; replaying what is readable\n";
    channels = reader.channels();
  }
  std::map<std::string, uint16_t> channel_of;
  for (const auto& [id, c] : channels) channel_of[c.topic] = id;
  if (!channel_of.count(kClockTopic)) {
    std::cerr << "autonomy replay: " << o.file << " has no " << kClockTopic
              << ": record the whole run (autonomy record -a, started before the world)\n";
    return kExitUsage;
  }

  dds::Participant participant(o.domain);
  Interrupt interrupt(ctx.signals, participant);
  Discovery discovery(participant);
  const std::string start_world = simulator_command(channel_of, messages, o.participant, o.domain);
  std::cerr << "autonomy replay: waiting for a fresh world on domain " << o.domain << " (" << start_world << ")\n";
  const auto world = discover_world(discovery, interrupt, participant, o.world_wait_s);
  if (!world) {
    if (interrupt.requested()) return kExitInterrupted;
    std::cerr << "autonomy replay: no world on domain " << o.domain << " within " << o.world_wait_s
              << " s: start one with the recorded scenario, in lockstep, waiting for the replay:\n  " << start_world
              << "\n";
    return kExitFailed;
  }

  // Which recorded topics go in, which are checked, which are neither.
  xtypes::TypeLookup lookup(participant.handle(), DDS_SECS(2));
  std::map<std::string, ReplayTopic> inputs, outputs;
  std::vector<std::string> unused;
  for (const auto& [topic_name, id] : channel_of) {
    const auto* topic = recording::find_recordable(topic_name);
    if (!topic) {
      unused.push_back(topic_name + " (not in this build's catalogue)");
      continue;
    }
    const bool written = world->writes.count(topic_name) > 0, read = world->reads.count(topic_name) > 0;
    const bool ignored = std::find(o.ignore.begin(), o.ignore.end(), topic_name) != o.ignore.end();
    ReplayTopic t;
    t.recorded = messages[id].size();
    if (written && !ignored) {
      t.reader = std::make_unique<recording::RawReader>(participant, *topic);
      t.type = lookup.resolve_entity(t.reader->topic_handle());
      outputs[topic_name] = std::move(t);
    } else if (read && !written) {
      try {
        const auto qos = recording::qos_from_metadata(channels.at(id).metadata);
        t.writer = std::make_unique<recording::RawWriter>(participant, *topic, qos.get());
      } catch (const std::runtime_error& e) {
        std::cerr << "autonomy replay: " << o.file << ": topic " << topic_name << ": " << e.what() << "\n";
        return kExitUsage;
      }
      t.type = lookup.resolve_entity(t.writer->topic_handle());
      inputs[topic_name] = std::move(t);
    } else {
      unused.push_back(topic_name + (ignored ? " (ignored: the simulator's own figures)" : " (the world neither reads nor writes it)"));
    }
  }
  // The replay's own registration and acks go out with the recorded participants'.
  for (const char* name : {kRegistrationTopic, kAckTopic})
    if (!inputs.count(name)) {
      ReplayTopic t;
      const auto* topic = recording::find_recordable(name);
      t.writer = std::make_unique<recording::RawWriter>(participant, *topic, dds::make_qos(topic->qos).get());
      t.type = lookup.resolve_entity(t.writer->topic_handle());
      inputs[name] = std::move(t);
    }
  if (!outputs.count(kClockTopic)) {
    std::cerr << "autonomy replay: the world on domain " << o.domain << " does not write " << kClockTopic << "\n";
    return kExitFailed;
  }

  // The script: every recorded sample decoded once.
  std::vector<RecordedSample> script_inputs, script_outputs, script_clocks;
  auto decode = [&](ReplayTopic& t, const std::string& name, std::vector<RecordedSample>& into, bool keep_cdr) {
    for (const auto& m : messages[channel_of.at(name)]) {
      RecordedSample s{name, m.log_time, m.publish_time, keep_cdr ? m.data : "", xtypes::cdr_to_json(*t.type, m.data),
                       std::nullopt};
      s.tick = tick_of(s.value);
      t.ticked = t.ticked || s.tick.has_value();
      into.push_back(std::move(s));
    }
  };
  try {
    for (auto& [name, t] : inputs)
      if (channel_of.count(name)) decode(t, name, script_inputs, true);
    for (auto& [name, t] : outputs) decode(t, name, name == kClockTopic ? script_clocks : script_outputs, false);
    script_outputs.insert(script_outputs.end(), script_clocks.begin(), script_clocks.end());
  } catch (const xtypes::CdrError& e) {
    std::cerr << "autonomy replay: " << o.file << ": a sample does not decode: " << e.what() << "\n";
    return kExitUsage;
  }
  if (const auto holes = recording::unacknowledged_commands(script_inputs)) {
    std::cerr << "autonomy replay: " << o.file << " is incomplete: " << *holes
              << ". The recorder missed samples: start `autonomy record -a` before the world and let it match the "
                 "writers before the world runs (`autonomy record -v` says when they match), and stop it after the "
                 "world went quiet\n";
    return kExitUsage;
  }
  // The fresh world writes tick 0 when it starts, before this tool can have joined it (it then
  // holds tick 0 for the replay): what it wrote on volatile topics then is gone. Not compared.
  const auto before = script_outputs.size();
  script_outputs.erase(std::remove_if(script_outputs.begin(), script_outputs.end(),
                                      [&](const RecordedSample& s) {
                                        const auto& metadata = channels.at(channel_of.at(s.topic)).metadata;
                                        const auto d = metadata.find("durability");
                                        return s.tick == 0 && d != metadata.end() && d->second == "volatile";
                                      }),
                       script_outputs.end());
  const std::size_t unreachable = before - script_outputs.size();
  // What is left of tick 0 is durable: the held fresh world has it written already.
  std::set<std::string> at_tick_zero;
  for (const auto& s : script_outputs)
    if (s.tick == 0) at_tick_zero.insert(s.topic);
  recording::ReplayScript script(std::move(script_inputs), std::move(script_outputs), std::move(script_clocks));
  if (script.clock_ticks().empty()) {
    std::cerr << "autonomy replay: " << o.file << ": no clock sample: nothing to replay\n";
    return kExitUsage;
  }
  const int64_t last_tick = script.last_tick();
  std::cerr << "autonomy replay: " << o.file << ": ticks " << script.clock_ticks().front() << "-" << last_tick << ", "
            << script.inputs().size() << " inputs on";
  for (const auto& [name, t] : inputs)
    if (t.recorded) std::cerr << " " << name << " (" << t.recorded << ")";
  std::cerr << "; " << script.outputs() << " outputs to check on";
  for (const auto& [name, t] : outputs)
    if (t.ticked) std::cerr << " " << name << " (" << t.recorded << ")";
  std::cerr << "\n";
  std::vector<std::string> unchecked;
  for (const auto& [name, t] : outputs)
    if (!t.ticked) unchecked.push_back(name);

  // The world's readers match the writers, and its writers the readers, before anything volatile
  // goes out: the world starts once the registration below arrives.
  const auto match_deadline = std::chrono::steady_clock::now() + seconds(o.world_wait_s);
  auto matched = [&] {
    for (const auto& [name, t] : inputs)
      if (t.writer->matched_readers() == 0) return false;
    for (const auto& [name, t] : outputs)
      if (t.reader->matched_writers() == 0) return false;
    return true;
  };
  while (!matched() && std::chrono::steady_clock::now() < match_deadline)
    if (!sleep_for(interrupt, participant, std::chrono::milliseconds(20))) return kExitInterrupted;
  auto write_own = [&](const char* topic, const Json& value) {
    auto& t = inputs.at(topic);
    t.writer->write(xtypes::json_to_cdr(*t.type, value).cdr);
  };
  std::size_t next_input = 0, published = 0;
  auto publish_due = [&](int64_t tick) {
    const auto& all = script.inputs();
    for (; next_input < all.size() && all[next_input].due <= tick; ++next_input, ++published) {
      auto& t = inputs.at(all[next_input].topic);
      if (o.verbose)
        std::cerr << "  at tick " << tick << " input due " << all[next_input].due << " " << all[next_input].topic << " "
                  << xtypes::cdr_to_json(*t.type, all[next_input].cdr).dump() << "\n";
      t.writer->write(all[next_input].cdr);
    }
  };
  // A sample that does not decode (another writer on the domain) is counted and said once per
  // topic, not compared: the tool goes on.
  std::map<std::string, std::size_t> undecodable;
  auto take_outputs = [&](std::vector<int64_t>* clocks) {
    std::vector<recording::RawSample> samples;
    for (auto& [name, t] : outputs) {
      samples.clear();
      t.reader->take(samples);
      for (const auto& s : samples) {
        Json value;
        try {
          value = xtypes::cdr_to_json(*t.type, s.cdr);
        } catch (const xtypes::CdrError& e) {
          if (undecodable[name]++ == 0)
            std::cerr << "autonomy replay: a sample on " << name << " from the fresh world does not decode: " << e.what()
                      << "\n";
          continue;
        }
        const auto tick = tick_of(value);
        if (!tick) continue;
        if (name == kClockTopic && clocks) clocks->push_back(*tick);
        script.fresh_output(name, *tick, std::move(value));
      }
    }
  };

  // Woken by the world's samples (or Ctrl-C) instead of polling.
  dds::WaitSet waitset(participant);
  waitset.attach(interrupt.condition(), 0);
  for (const auto& [name, t] : outputs) waitset.attach(t.reader->data_condition(), 1);
  auto wait_for_samples = [&](std::chrono::milliseconds at_most) {
    waitset.wait(at_most);
    return !interrupt.requested();
  };

  // Each side of a topic matches the other on its own: the world's writer of robot states may
  // match this reader a moment after this reader matched it, and once the world went past tick 0
  // its durable tick-0 state would be gone (seen as "published nothing at tick 0" in CI under
  // load). The held world has written tick 0 already: the registration that starts it goes out
  // once every durable tick-0 output the recording holds has come from the fresh world.
  std::vector<int64_t> held_clocks;
  auto tick_zero_arrived = [&] {
    return std::all_of(at_tick_zero.begin(), at_tick_zero.end(), [&](const auto& t) { return script.has_fresh(t, 0); });
  };
  for (take_outputs(&held_clocks); !tick_zero_arrived() && std::chrono::steady_clock::now() < match_deadline;
       take_outputs(&held_clocks))
    if (!wait_for_samples(std::chrono::milliseconds(50))) return kExitInterrupted;

  publish_due(recording::kAtStart);
  write_own(kRegistrationTopic, Json{{"participant", o.participant}, {"active", true}});

  int64_t clock = recording::kAtStart;
  auto last_progress = std::chrono::steady_clock::now();
  auto last_clock_at = last_progress;
  std::optional<recording::OutputMismatch> mismatch;
  bool finished = false;
  while (!finished && !interrupt.requested()) {
    std::vector<int64_t> clocks = std::move(held_clocks);  // the held tick 0's, the first time
    held_clocks.clear();
    take_outputs(&clocks);
    std::sort(clocks.begin(), clocks.end());
    for (const int64_t tick : clocks) {
      if (tick <= clock) continue;
      clock = tick;
      if (o.verbose) std::cerr << "  fresh clock " << clock << "\n";
      last_clock_at = std::chrono::steady_clock::now();
      // The outputs recorded by this tick: they were written before its clock, so they come.
      const auto deadline = last_clock_at + seconds(o.output_wait_s);
      while ((mismatch = script.check_due_by(clock)) && std::chrono::steady_clock::now() < deadline) {
        if (!wait_for_samples(std::chrono::milliseconds(50))) return kExitInterrupted;
        take_outputs(nullptr);
      }
      if (mismatch) break;
      publish_due(clock);
      const auto next = script.next_clock_after(clock);
      write_own(kAckTopic, Json{{"participant", o.participant},
                                {"tick", clock},
                                {"commands_sent", 0},
                                {"quiet_until_tick", next && *next > clock + 1 ? *next : 0}});
      if (clock >= last_tick) {
        finished = true;
        break;
      }
    }
    if (mismatch) break;
    const auto now = std::chrono::steady_clock::now();
    if (!finished && now - last_clock_at > seconds(o.output_wait_s + 10.0)) {
      std::cerr << "autonomy replay: the world did not go on after tick " << clock << " for "
                << std::setprecision(3) << o.output_wait_s + 10.0 << " s (recorded ticks go on to " << last_tick
                << "); is every recorded participant's input in the recording?\n";
      write_own(kRegistrationTopic, Json{{"participant", o.participant}, {"active", false}});
      return kExitFailed;
    }
    if (now - last_progress > std::chrono::seconds(1)) {
      last_progress = now;
      std::cerr << "autonomy replay: tick " << clock << " of " << last_tick << ", " << published << " inputs, "
                << script.matched() << " of " << script.outputs() << " outputs matched\n";
    }
    if (!finished && !wait_for_samples(std::chrono::milliseconds(100))) break;
  }
  if (interrupt.requested()) return kExitInterrupted;
  if (finished) {
    // Outputs the recorder took after the last clock.
    const auto deadline = std::chrono::steady_clock::now() + seconds(o.output_wait_s);
    while ((mismatch = script.check_due_by(INT64_MAX)) && std::chrono::steady_clock::now() < deadline) {
      if (!wait_for_samples(std::chrono::milliseconds(50))) return kExitInterrupted;
      take_outputs(nullptr);
    }
  }
  write_own(kRegistrationTopic, Json{{"participant", o.participant}, {"active", false}});

  if (mismatch) {
    print_line("replay differs from the recording: " + mismatch->describe());
    print_line("matched " + std::to_string(script.matched()) + " of " + std::to_string(script.outputs()) +
               " recorded outputs before it; " + std::to_string(published) + " inputs replayed");
    return kExitFailed;
  }
  print_line("replay matches the recording: " + std::to_string(script.matched()) + " of " +
             std::to_string(script.outputs()) + " recorded outputs, ticks " + std::to_string(script.clock_ticks().front()) +
             "-" + std::to_string(last_tick) + ", " + std::to_string(published) + " inputs replayed");
  for (const auto& [name, n] : script.outputs_by_topic()) print_line("  " + name + ": " + std::to_string(n) + " matched");
  for (const auto& name : unchecked) print_line("  not compared (no tick in its type): " + name);
  if (unreachable > 0)
    print_line("  not compared: " + std::to_string(unreachable) +
               " samples of tick 0 on volatile topics (written before a replay can join the fresh world)");
  for (const auto& name : unused) print_line("  not replayed: " + name);
  for (const auto& [name, n] : undecodable)
    print_line("  not compared: " + std::to_string(n) + " samples on " + name + " that did not decode");
  return kExitOk;
}

}  // namespace

Command add_replay(CLI::App& app) {
  auto o = std::make_shared<ReplayOptions>();
  auto* cmd = app.add_subcommand(
      "replay",
      "Feed a recorded lockstep run back into a fresh world and check that it does the same, tick by tick");
  cmd->footer(
      "Start the simulator first, on its own domain, with the recorded scenario, in lockstep and with --wait-for "
      "replay. The recording must hold the whole run (autonomy record -a, started before the world). Inputs are the "
      "recorded topics the fresh world reads and does not write; every recorded sample stamped with a tick on a topic "
      "it writes must come back exactly (world ids aside). Exit 0: the replay matches; 1: the first difference, or a "
      "world that stopped. docs/recording.md.");
  add_domain_option(cmd, o->domain);
  cmd->add_option("file", o->file, "MCAP file recorded by `autonomy record -a`")->required()->check(CLI::ExistingFile);
  cmd->add_option("--participant", o->participant, "Lockstep name of the replay (the simulator's --wait-for)")
      ->capture_default_str();
  cmd->add_option("--world-wait", o->world_wait_s, "Seconds to wait for the fresh world to appear")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--output-wait", o->output_wait_s, "Seconds a recorded output may take to come back")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_flag("-v,--verbose", o->verbose, "Print every fresh clock and every input as it goes out");
  cmd->add_option("--ignore", o->ignore, "Topics the world writes that are not compared")->capture_default_str();
  return {cmd, [o](Context& ctx) {
            try {
              return run_replay(*o, ctx);
            } catch (const mcap::McapError& e) {
              std::cerr << "autonomy replay: " << e.what() << "\n";
              return static_cast<int>(kExitFailed);
            } catch (const xtypes::TypeLookupError& e) {
              std::cerr << "autonomy replay: " << e.what() << "\n";
              return static_cast<int>(kExitFailed);
            } catch (const std::runtime_error& e) {  // DDS errors writing an input
              std::cerr << "autonomy replay: " << e.what() << "\n";
              return static_cast<int>(kExitFailed);
            }
          }};
}

}  // namespace autonomy::tools
