// autonomy play: republishes an MCAP recording's topics with their recorded QoS and timing.
#include <iostream>
#include <map>
#include <memory>
#include <set>

#include "common/mcap/reader.hpp"
#include "tools/autonomy/commands.hpp"
#include "tools/autonomy/suggest.hpp"
#include "tools/recording/raw_topic.hpp"

namespace autonomy::tools {

namespace {

struct PlayOptions {
  int domain = 0;
  std::string file;
  double rate = 1.0;
  bool loop = false;
  double start_offset_s = 0.0;
  std::vector<std::string> topics;
  double wait_s = 1.0;
};

struct Stopped {};  // thrown out of the reader's callback on Ctrl-C

int run_play(const PlayOptions& o, Context& ctx) {
  // First pass: the channels, and where the recording starts.
  std::map<uint16_t, mcap::Channel> channels;
  std::map<uint16_t, std::string> schema_names;
  uint64_t first = 0;
  bool any = false;
  {
    mcap::Reader reader(o.file);
    const auto report = reader.read([&](const mcap::Channel&, const mcap::Schema*, const mcap::Message& m) {
      if (!any || m.log_time < first) first = m.log_time;
      any = true;
    });
    if (!report.complete) std::cerr << "autonomy play: " << o.file << ": " << report.note << "; playing what is readable\n";
    channels = reader.channels();
    for (const auto& [id, c] : channels) {
      const auto s = reader.schemas().find(c.schema_id);
      schema_names[id] = s == reader.schemas().end() ? "" : s->second.name;
    }
  }
  std::vector<std::string> recorded_topics;
  for (const auto& [id, c] : channels) recorded_topics.push_back(c.topic);
  for (const auto& t : o.topics)
    if (std::find(recorded_topics.begin(), recorded_topics.end(), t) == recorded_topics.end()) {
      const auto hint = did_you_mean(t, recorded_topics);
      std::cerr << "autonomy play: --topics " << t << " is not in " << o.file << (hint.empty() ? "" : "; " + hint)
                << " (`autonomy bag info " << o.file << "` lists its topics)\n";
      return kExitUsage;
    }

  dds::Participant participant(o.domain);
  Interrupt interrupt(ctx.signals, participant);
  std::map<uint16_t, std::unique_ptr<recording::RawWriter>> writers;
  for (const auto& [id, c] : channels) {
    if (!o.topics.empty() && std::find(o.topics.begin(), o.topics.end(), c.topic) == o.topics.end()) continue;
    const auto* topic = recording::find_recordable(c.topic);
    if (!topic) {
      std::cerr << "autonomy play: " << o.file << ": topic " << c.topic << " is not in this build's catalogue; "
                << "leave it out with --topics\n";
      return kExitUsage;
    }
    if (c.message_encoding != "cdr" || schema_names[id] != topic->type_name) {
      std::cerr << "autonomy play: " << o.file << ": topic " << c.topic << " was recorded as " << schema_names[id] << " ("
                << c.message_encoding << "), this build's type is " << topic->type_name << " (cdr)\n";
      return kExitUsage;
    }
    try {
      const auto qos = recording::qos_from_metadata(c.metadata);
      writers[id] = std::make_unique<recording::RawWriter>(participant, *topic, qos.get());
    } catch (const std::runtime_error& e) {
      std::cerr << "autonomy play: " << o.file << ": topic " << c.topic << ": " << e.what() << "\n";
      return kExitUsage;
    }
  }
  if (writers.empty() || !any) {
    std::cerr << "autonomy play: " << o.file << ": nothing to play\n";
    return kExitFailed;
  }
  // Readers need a moment to match the new writers; volatile samples written before are lost.
  if (!sleep_for(interrupt, participant, seconds(o.wait_s))) return kExitInterrupted;

  const uint64_t from = first + static_cast<uint64_t>(o.start_offset_s * 1e9);
  uint64_t published = 0;
  try {
    do {
      const auto wall_start = std::chrono::steady_clock::now();
      mcap::Reader reader(o.file);
      reader.read([&](const mcap::Channel& c, const mcap::Schema*, const mcap::Message& m) {
        const auto w = writers.find(c.id);
        if (w == writers.end() || m.log_time < from) return;
        const auto due = wall_start + std::chrono::nanoseconds(static_cast<int64_t>((m.log_time - from) / o.rate));
        const auto left = due - std::chrono::steady_clock::now();
        if (left > std::chrono::nanoseconds::zero() && !sleep_for(interrupt, participant, left)) throw Stopped{};
        if (interrupt.requested()) throw Stopped{};
        w->second->write(m.data);
        ++published;
      });
    } while (o.loop && !interrupt.requested());
  } catch (const Stopped&) {
    print_line("played " + std::to_string(published) + " messages (interrupted)");
    return kExitOk;
  }
  print_line("played " + std::to_string(published) + " messages on " + std::to_string(writers.size()) + " topic(s)");
  return kExitOk;
}

}  // namespace

Command add_play(CLI::App& app) {
  auto o = std::make_shared<PlayOptions>();
  auto* cmd = app.add_subcommand("play",
                                 "Republish an MCAP recording made by `autonomy record`: each topic with its recorded "
                                 "QoS, messages spaced as they were received (log time), divided by --rate");
  add_domain_option(cmd, o->domain);
  cmd->add_option("file", o->file, "MCAP file")->required()->check(CLI::ExistingFile);
  cmd->add_option("-r,--rate", o->rate, "Speed factor (2: twice as fast)")->check(CLI::PositiveNumber)->capture_default_str();
  cmd->add_flag("-l,--loop", o->loop, "Start again at the end, until Ctrl-C");
  cmd->add_option("-s,--start-offset", o->start_offset_s, "Skip this many seconds from the start of the recording")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--topics", o->topics, "Only these recorded topics");
  cmd->add_option("--wait", o->wait_s, "Seconds to let readers match the writers before the first message")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  return {cmd, [o](Context& ctx) {
            try {
              return run_play(*o, ctx);
            } catch (const mcap::McapError& e) {
              std::cerr << "autonomy play: " << e.what() << "\n";
              return static_cast<int>(kExitFailed);
            }
          }};
}

}  // namespace autonomy::tools
