// autonomy topic hz: the rate at which a topic's samples arrive (any topic on the domain).
#include <cmath>
#include <cstdio>
#include <deque>
#include <iostream>
#include <memory>

#include "tools/autonomy/commands.hpp"
#include "tools/autonomy/suggest.hpp"
#include "tools/autonomy/discovery.hpp"
#include "tools/autonomy/report_loop.hpp"
#include "tools/autonomy/topic_registry.hpp"

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
  ReportLoop loop;
  loop.start = Clock::now();
  loop.duration_s = o.duration_s;

  dds::Participant participant(o.domain);
  Interrupt interrupt(ctx.signals, participant);
  int failed = kExitOk;
  const auto reader = open_counting_reader(participant, interrupt, "autonomy topic hz", o.topic, o.domain,
                                           discovery_wait_within(o.discovery_s, o.duration_s), &failed);
  if (!reader) return failed;
  RateWindow window(o.window);
  loop.data_condition = reader->data_condition();
  loop.take = [&] {
    const auto samples = reader->take();
    const auto now = Clock::now();
    for (const auto& s : samples)
      if (s.valid) window.add(now);
    return window.total();
  };
  loop.report = [&] { return window.report(); };
  return run_report_loop(participant, interrupt, loop);
}

}  // namespace

Command add_topic_hz(CLI::App& topic) {
  auto o = std::make_shared<HzOptions>();
  auto* cmd = topic.add_subcommand(
      "hz",
      "Print, every second, the rate of a topic's samples as they arrive here (any topic on the domain: a topic not "
      "in the catalogue is read with the type its endpoints announce in discovery): average rate, min/max interval "
      "and standard deviation over the last --window intervals.");
  add_domain_option(cmd, o->domain);
  cmd->add_option("topic", o->topic, "Topic name, e.g. autonomy/robot/state or any topic on the domain")->required();
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
  cmd->footer("Exit codes: 0 after --duration or Ctrl-C; 1 type not obtainable, or DDS error; 2 unknown topic or bad "
              "arguments." + topics);
  return {cmd, [o](Context& ctx) { return run_hz(*o, ctx); }};
}

}  // namespace autonomy::tools
