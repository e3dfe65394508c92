// autonomy topic bw: the bandwidth a topic's samples take, as serialized (CDR, the 4-byte
// encapsulation header included, as on the wire): bytes per second and the sizes of the samples
// over the last --window samples, printed every second. Any topic on the domain: the reader takes
// its type from discovery and its samples as the serialized bytes (no decoding).
#include <cstdio>
#include <deque>
#include <iostream>
#include <memory>

#include "tools/autonomy/commands.hpp"
#include "tools/autonomy/report_loop.hpp"
#include "tools/autonomy/text.hpp"

namespace autonomy::tools {

namespace {

struct BwOptions {
  int domain = 0;
  std::string topic;
  size_t window = 100;
  double duration_s = 0.0;
  double discovery_s = 1.0;
};

// Arrival time and serialized size of the last `window` samples.
class BandwidthWindow {
 public:
  explicit BandwidthWindow(size_t window) : window_(window) {}
  void add(ReportLoop::Clock::time_point t, size_t bytes) {
    samples_.emplace_back(t, bytes);
    while (samples_.size() > window_) samples_.pop_front();
    ++total_;
  }
  uint64_t total() const { return total_; }

  // "average: 50200 B/s (49.0 KiB/s)  mean: 1004 B  min: 1004 B  max: 1004 B  window: 100"
  // The rate is the bytes that arrived after the window's first sample, over the time from its
  // arrival to the last one's.
  std::string report() const {
    if (samples_.empty()) return "";
    uint64_t sum = 0, after_first = 0;
    size_t lo = SIZE_MAX, hi = 0;
    for (size_t i = 0; i < samples_.size(); ++i) {
      const size_t b = samples_[i].second;
      sum += b;
      if (i > 0) after_first += b;
      lo = std::min(lo, b);
      hi = std::max(hi, b);
    }
    const double span = std::chrono::duration<double>(samples_.back().first - samples_.front().first).count();
    std::string rate = "-";
    if (samples_.size() >= 2 && span > 0) {
      const double bps = static_cast<double>(after_first) / span;
      char r[100];
      std::snprintf(r, sizeof(r), "%.0f B/s (%s/s)", bps, human_bytes(static_cast<uint64_t>(bps)).c_str());
      rate = r;
    }
    char line[300];
    std::snprintf(line, sizeof(line), "average: %s  mean: %.0f B  min: %zu B  max: %zu B  window: %zu", rate.c_str(),
                  static_cast<double>(sum) / static_cast<double>(samples_.size()), lo, hi, samples_.size());
    return line;
  }

 private:
  size_t window_;
  std::deque<std::pair<ReportLoop::Clock::time_point, size_t>> samples_;
  uint64_t total_ = 0;
};

int run_bw(const BwOptions& o, Context& ctx) {
  ReportLoop loop;
  loop.start = ReportLoop::Clock::now();
  loop.duration_s = o.duration_s;

  dds::Participant participant(o.domain);
  Interrupt interrupt(ctx.signals, participant);
  int failed = kExitOk;
  const auto reader = open_counting_reader(participant, interrupt, "autonomy topic bw", o.topic, o.domain,
                                           discovery_wait_within(o.discovery_s, o.duration_s), &failed);
  if (!reader) return failed;

  BandwidthWindow window(o.window);
  loop.data_condition = reader->data_condition();
  loop.take = [&] {
    const auto samples = reader->take();
    const auto now = ReportLoop::Clock::now();
    for (const auto& s : samples)
      if (s.valid) window.add(now, s.cdr.size());
    return window.total();
  };
  loop.report = [&] { return window.report(); };
  return run_report_loop(participant, interrupt, loop);
}

}  // namespace

Command add_topic_bw(CLI::App& topic) {
  auto o = std::make_shared<BwOptions>();
  auto* cmd = topic.add_subcommand(
      "bw",
      "Print, every second, the bandwidth of a topic's samples as they arrive here (any topic on the domain: the "
      "type comes from discovery): bytes per second over the last --window samples, and their mean, min and max "
      "size. Sizes are of the serialized sample (CDR with its 4-byte encapsulation header), as on the wire "
      "without the RTPS headers.");
  add_domain_option(cmd, o->domain);
  cmd->add_option("topic", o->topic, "Topic name, e.g. autonomy/robot/state or any topic on the domain")->required();
  cmd->add_option("-w,--window", o->window, "Number of samples the statistics cover")
      ->check(CLI::Range(size_t{2}, size_t{10'000'000}))
      ->capture_default_str();
  cmd->add_option("-d,--duration", o->duration_s, "Stop after this many seconds (0: until Ctrl-C)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--discovery-wait", o->discovery_s, "Seconds to wait for the topic's endpoints (its type, its writers' QoS)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->footer(
      "Exit codes: 0 after --duration or Ctrl-C; 1 type not obtainable, or DDS error; 2 unknown topic or bad "
      "arguments.");
  return {cmd, [o](Context& ctx) { return run_bw(*o, ctx); }};
}

}  // namespace autonomy::tools
