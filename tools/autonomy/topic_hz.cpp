// autonomy topic hz: the rate at which a catalogue topic's samples arrive.
#include <cmath>
#include <cstdio>
#include <deque>
#include <iostream>
#include <memory>

#include "tools/autonomy/commands.hpp"
#include "tools/autonomy/suggest.hpp"
#include "tools/autonomy/discovery.hpp"

namespace autonomy::tools {

namespace {

struct HzOptions {
  int domain = 0;
  std::string topic;
  size_t window = 10000;
  double duration_s = 0.0;
  double discovery_s = 1.0;
};

using Clock = std::chrono::steady_clock;

// Arrival times of the last window+1 samples: window intervals.
class RateWindow {
 public:
  explicit RateWindow(size_t window) : window_(window) {}
  void add(Clock::time_point t) {
    arrivals_.push_back(t);
    while (arrivals_.size() > window_ + 1) arrivals_.pop_front();
    ++total_;
  }
  uint64_t total() const { return total_; }

  // "average rate: 10.001 Hz  min: 0.099 s  max: 0.101 s  std dev: 0.00051 s  window: 10"
  std::string report() const {
    const size_t n = arrivals_.size() < 2 ? 0 : arrivals_.size() - 1;
    if (n == 0) return "";
    double sum = 0, lo = 1e300, hi = 0;
    for (size_t i = 1; i < arrivals_.size(); ++i) {
      const double d = std::chrono::duration<double>(arrivals_[i] - arrivals_[i - 1]).count();
      sum += d;
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
    const double mean = sum / n;
    double var = 0;
    for (size_t i = 1; i < arrivals_.size(); ++i) {
      const double d = std::chrono::duration<double>(arrivals_[i] - arrivals_[i - 1]).count() - mean;
      var += d * d;
    }
    char line[200];
    std::snprintf(line, sizeof(line), "average rate: %.3f Hz  min: %.5f s  max: %.5f s  std dev: %.5f s  window: %zu",
                  mean > 0 ? 1.0 / mean : 0.0, lo, hi, std::sqrt(var / n), n);
    return line;
  }

 private:
  size_t window_;
  std::deque<Clock::time_point> arrivals_;
  uint64_t total_ = 0;
};

int run_hz(const HzOptions& o, Context& ctx) {
  const auto registry = TopicRegistry::catalogue();
  const TopicEntry* topic = registry.find(o.topic);
  if (!topic) {
    std::cerr << unknown_topic_message("autonomy topic hz", o.topic, registry.name_list()) << "\n";
    return kExitUsage;
  }
  const auto start = Clock::now();
  const bool has_end = o.duration_s > 0;
  const auto end = start + seconds(o.duration_s);

  dds::Participant participant(o.domain);
  Interrupt interrupt(ctx.signals, participant);
  auto discovery_wait = seconds(o.discovery_s);
  if (has_end) discovery_wait = std::min<std::chrono::nanoseconds>(discovery_wait, seconds(o.duration_s));
  const auto reader = open_mirroring_reader(participant, *topic, interrupt, discovery_wait, nullptr);

  dds::WaitSet waitset(participant);
  waitset.attach(reader->data_condition(), 1);
  waitset.attach(interrupt.condition(), 2);

  RateWindow window(o.window);
  uint64_t reported_total = 0;
  auto next_report = Clock::now() + std::chrono::seconds(1);
  for (;;) {
    const auto samples = reader->take(false);
    const auto now = Clock::now();
    for (const auto& s : samples)
      if (s.valid) window.add(now);
    if (interrupt.requested()) return kExitOk;
    if (now >= next_report) {
      print_line(window.total() == reported_total ? std::string("no new messages") : window.report());
      reported_total = window.total();
      next_report += std::chrono::seconds(1);
      if (next_report < now) next_report = now + std::chrono::seconds(1);
    }
    if (has_end && now >= end) {
      if (window.total() == 0) {
        char line[100];
        std::snprintf(line, sizeof(line), "no messages received in %g s", o.duration_s);
        print_line(line);
      }
      return kExitOk;
    }
    auto wake = next_report;
    if (has_end) wake = std::min(wake, end);
    waitset.wait(std::max<std::chrono::nanoseconds>(wake - Clock::now(), std::chrono::nanoseconds::zero()));
  }
}

}  // namespace

Command add_topic_hz(CLI::App& topic) {
  auto o = std::make_shared<HzOptions>();
  auto* cmd = topic.add_subcommand(
      "hz",
      "Print, every second, the rate of a catalogue topic's samples as they arrive here: average rate, "
      "min/max interval and standard deviation over the last --window intervals.");
  add_domain_option(cmd, o->domain);
  cmd->add_option("topic", o->topic, "Topic name, e.g. autonomy/robot/state")->required();
  cmd->add_option("-w,--window", o->window, "Number of intervals the statistics cover")
      ->check(CLI::Range(size_t{1}, size_t{10'000'000}))
      ->capture_default_str();
  cmd->add_option("-d,--duration", o->duration_s, "Stop after this many seconds (0: until Ctrl-C)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--discovery-wait", o->discovery_s, "Seconds to wait for the topic's writers, to mirror their QoS")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  const std::string topics = "\nTopics of the catalogue: " + TopicRegistry::catalogue().names() + ".";
  cmd->footer("Exit codes: 0 after --duration or Ctrl-C; 1 DDS error; 2 unknown topic or bad arguments." + topics);
  return {cmd, [o](Context& ctx) { return run_hz(*o, ctx); }};
}

}  // namespace autonomy::tools
