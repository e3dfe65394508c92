// autonomy record: catalogue topics into an MCAP file, as serialized samples (docs/recording.md).
#include <dds/version.h>
#include <unistd.h>

#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <sstream>

#include "common/mcap/writer.hpp"
#include "tools/autonomy/commands.hpp"
#include "tools/autonomy/discovery.hpp"
#include "tools/autonomy/text.hpp"
#include "tools/autonomy/suggest.hpp"
#include "tools/recording/idl_text.hpp"
#include "tools/recording/raw_topic.hpp"

namespace autonomy::tools {

namespace {

struct RecordOptions {
  int domain = 0;
  bool all = false;
  std::vector<std::string> topics;
  std::string regex;
  std::string output;
  std::string compression = "zstd";
  double chunk_s = 1.0;
  double duration_s = 0.0;
  bool progress = false, no_progress = false;
  bool verbose = false;
};

// One recorded topic: its reader, and its channel once the first sample arrived.
struct Recorded {
  std::unique_ptr<recording::RawReader> reader;
  int channel = -1;
  uint32_t sequence = 0;
  uint64_t messages = 0, bytes = 0;
  uint32_t writers_matched = 0;  // said with --verbose when it changes
};

// The QoS of the topic's writers as channel metadata: the first discovered writer's (they match
// the catalogue's class unless a foreign process differs); the class's when none is seen.
std::map<std::string, std::string> writer_qos_metadata(const Discovery& discovery,
                                                      const recording::RecordableTopic& topic) {
  const auto writers = discovery.writers_of(topic.name);
  auto qos = dds::make_qos(topic.qos);
  if (!writers.empty()) {
    const auto& w = writers.front().qos;
    dds_qset_reliability(qos.get(), w.reliable ? DDS_RELIABILITY_RELIABLE : DDS_RELIABILITY_BEST_EFFORT, DDS_SECS(1));
    dds_qset_durability(qos.get(), w.durability);
    dds_qset_history(qos.get(), w.history, w.depth);
  }
  return recording::qos_metadata(qos.get(), topic.qos);
}

void print_progress(std::ostream& out, const std::map<std::string, Recorded>& recorded, double elapsed_s,
                    uint64_t file_bytes, bool redraw, size_t& lines_drawn) {
  std::ostringstream s;
  size_t lines = 0;
  if (redraw && lines_drawn > 0) s << "\x1b[" << lines_drawn << "A";
  s << "\x1b[2K" << "recording " << std::fixed << std::setprecision(1) << elapsed_s << " s, file "
    << human_bytes(file_bytes) << "\n";
  ++lines;
  for (const auto& [name, r] : recorded) {
    if (r.messages == 0) continue;
    s << "\x1b[2K" << "  " << std::left << std::setw(40) << name << std::right << std::setw(9) << r.messages << " msgs "
      << std::setw(10) << human_bytes(r.bytes) << "\n";
    ++lines;
  }
  out << s.str() << std::flush;
  lines_drawn = lines;
}

enum RecordTag : dds_attach_t { kRecordInterrupt = 1, kRecordData = 2 };

int run_record(const RecordOptions& o, Context& ctx) {
  const auto& catalogue = recording::recordable_topics();
  std::vector<std::string> names;
  for (const auto& t : catalogue) names.push_back(t.name);

  std::vector<const recording::RecordableTopic*> selected;
  if (o.all) {
    for (const auto& t : catalogue) selected.push_back(&t);
  } else if (!o.regex.empty()) {
    std::regex re;
    try {
      re = std::regex(o.regex, std::regex::ECMAScript);
    } catch (const std::regex_error& e) {
      std::cerr << "autonomy record: --regex \"" << o.regex << "\" is not a regular expression: " << e.what() << "\n";
      return kExitUsage;
    }
    for (const auto& t : catalogue)
      if (std::regex_search(t.name, re)) selected.push_back(&t);
    if (selected.empty()) {
      std::cerr << "autonomy record: --regex \"" << o.regex << "\" matches no topic of the catalogue "
                << "(`autonomy topic list` shows them)\n";
      return kExitUsage;
    }
  } else {
    for (const auto& name : o.topics) {
      const auto* t = recording::find_recordable(name);
      if (!t) {
        std::cerr << unknown_topic_message("autonomy record", name, names) << "\n";
        return kExitUsage;
      }
      selected.push_back(t);
    }
  }
  if (selected.empty()) {
    std::cerr << "autonomy record: nothing to record: give topics, -a (every topic) or --regex R\n";
    return kExitUsage;
  }

  mcap::WriterOptions wo;
  wo.compression = o.compression == "none" ? "" : o.compression;
  wo.profile = "";
  wo.library = "autonomy record (Cyclone DDS " DDS_VERSION ")";
  mcap::Writer writer(o.output, wo);

  dds::Participant participant(o.domain);
  Interrupt interrupt(ctx.signals, participant);
  Discovery discovery(participant);
  dds::WaitSet waitset(participant);
  waitset.attach(interrupt.condition(), kRecordInterrupt);
  std::map<std::string, Recorded> recorded;
  for (const auto* t : selected) {
    auto& r = recorded[t->name];
    r.reader = std::make_unique<recording::RawReader>(participant, *t);
    waitset.attach(r.reader->data_condition(), kRecordData);
  }
  std::map<std::string, uint16_t> schema_ids;
  std::set<std::string> foreign_reported;

  const bool tty = ::isatty(STDERR_FILENO) != 0;
  const bool show_progress = o.progress || (tty && !o.no_progress);
  std::cerr << "autonomy record: " << selected.size() << " topic(s) on domain " << o.domain << " into " << o.output
            << " (" << (wo.compression.empty() ? "uncompressed" : wo.compression) << " chunks every " << o.chunk_s
            << " s); Ctrl-C stops\n";

  const auto start = std::chrono::steady_clock::now();
  auto next_flush = start + seconds(o.chunk_s);
  auto next_look = start;
  size_t lines_drawn = 0;
  std::vector<recording::RawSample> samples;
  for (;;) {
    for (auto& [name, r] : recorded) {
      samples.clear();
      r.reader->take(samples);
      for (auto& s : samples) {
        if (r.channel < 0) {
          const auto& t = r.reader->topic();
          auto sid = schema_ids.find(t.type_name);
          if (sid == schema_ids.end())
            sid = schema_ids.emplace(t.type_name, writer.add_schema(t.type_name, "omgidl", recording::omgidl_schema(t.type_name))).first;
          r.channel = writer.add_channel(sid->second, t.name, "cdr", writer_qos_metadata(discovery, t));
        }
        mcap::Message m;
        m.channel_id = static_cast<uint16_t>(r.channel);
        m.sequence = r.sequence++;
        m.log_time = static_cast<uint64_t>(s.reception_time);
        m.publish_time = static_cast<uint64_t>(s.source_timestamp > 0 ? s.source_timestamp : s.reception_time);
        r.bytes += s.cdr.size();
        ++r.messages;
        m.data = std::move(s.cdr);
        writer.write(m);
      }
    }
    // Discovery matches the recorder's readers with writers a moment after both exist: whoever
    // starts a fast (lockstep) world right after the recorder can wait for these lines instead
    // of losing its first ticks.
    if (o.verbose)
      for (auto& [name, r] : recorded)
        if (const auto n = r.reader->matched_writers(); n != r.writers_matched) {
          r.writers_matched = n;
          std::cerr << "autonomy record: " << name << ": " << n << " writer(s) matched\n";
        }
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start).count();
    if (now >= next_flush) {
      writer.flush_chunk();  // a kill -9 loses at most the last chunk period
      next_flush = now + seconds(o.chunk_s);
      if (show_progress) print_progress(std::cerr, recorded, elapsed, writer.bytes_written(), tty, lines_drawn);
    }
    if ((o.all || !o.regex.empty()) && now >= next_look) {
      next_look = now + std::chrono::seconds(1);
      for (const auto& e : discovery.endpoints()) {
        if (!e.writer || recording::find_recordable(e.topic) || e.topic.rfind("DCPS", 0) == 0) continue;
        if (!o.all && !std::regex_search(e.topic, std::regex(o.regex))) continue;
        if (foreign_reported.insert(e.topic).second)
          std::cerr << "autonomy record: topic " << e.topic << " (type " << e.type
                    << ") is not recorded: its type is not in this build's catalogue\n";
      }
    }
    if (interrupt.requested() || (o.duration_s > 0 && elapsed >= o.duration_s)) break;
    waitset.wait(std::chrono::milliseconds(100));
  }
  writer.close();
  uint64_t total = 0;
  for (const auto& [name, r] : recorded) total += r.messages;
  print_line("recorded " + std::to_string(total) + " messages on " + std::to_string(writer.statistics().channel_count) +
             " topic(s) into " + o.output + " (" + human_bytes(writer.bytes_written()) + ")");
  if (total == 0) std::cerr << "autonomy record: nothing received; " << where_we_looked(o.domain) << "\n";
  for (const auto& [name, r] : recorded)
    if (r.messages > 0) print_line("  " + name + ": " + std::to_string(r.messages) + " msgs, " + human_bytes(r.bytes));
  return kExitOk;
}

}  // namespace

Command add_record(CLI::App& app) {
  auto o = std::make_shared<RecordOptions>();
  auto* cmd = app.add_subcommand("record", "Record topics into an MCAP file (-a, TOPIC..., --regex R; -o FILE.mcap)");
  cmd->footer(
      "One channel per topic with its writers' QoS as metadata, the type as a self-contained OMG IDL schema (omgidl), "
      "samples as CDR with their encapsulation header (cdr); log time = reception, publish time = the writer's source "
      "timestamp. Transient-local state present at start is captured; topics whose writers appear later are recorded "
      "too. A chunk is written every --chunk seconds, so a recorder killed with -9 leaves a file readable up to its last "
      "chunk. docs/recording.md.");
  add_domain_option(cmd, o->domain);
  auto* all = cmd->add_flag("-a,--all", o->all, "Every topic of the catalogue");
  auto* regex = cmd->add_option("--regex", o->regex, "Topics whose name matches this regular expression (ECMAScript)");
  auto* topics = cmd->add_option("topics", o->topics, "Topic names, e.g. autonomy/robot/state");
  all->excludes(regex)->excludes(topics);
  regex->excludes(topics);
  cmd->add_option("-o,--output", o->output, "MCAP file to write (replaced if it exists)")->required();
  cmd->add_option("--compression", o->compression, "Chunk compression")
      ->check(CLI::IsMember({"zstd", "none"}))
      ->capture_default_str();
  cmd->add_option("--chunk", o->chunk_s, "Seconds between chunks written to the file")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--duration", o->duration_s, "Stop after this many seconds (0: at Ctrl-C)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_flag("--progress", o->progress, "Print progress every chunk even when stderr is not a terminal");
  cmd->add_flag("--no-progress", o->no_progress, "No progress on a terminal");
  cmd->add_flag("-v,--verbose", o->verbose,
                "Say on stderr whenever the number of writers a topic's reader is matched with changes");
  return {cmd, [o](Context& ctx) { return run_record(*o, ctx); }};
}

}  // namespace autonomy::tools
