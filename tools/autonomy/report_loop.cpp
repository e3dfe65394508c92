#include "tools/autonomy/report_loop.hpp"

#include <cstdio>
#include <iostream>

#include "tools/autonomy/discovered_reader.hpp"
#include "tools/autonomy/discovery.hpp"
#include "tools/autonomy/suggest.hpp"
#include "tools/autonomy/topic_registry.hpp"
#include "tools/recording/raw_topic.hpp"
#include "tools/xtypes/type_lookup.hpp"

namespace autonomy::tools {

int run_report_loop(const dds::Participant& participant, const Interrupt& interrupt, const ReportLoop& loop) {
  using Clock = ReportLoop::Clock;
  const bool has_end = loop.duration_s > 0;
  const auto end = loop.start + seconds(loop.duration_s);
  dds::WaitSet waitset(participant);
  waitset.attach(loop.data_condition, 1);
  waitset.attach(interrupt.condition(), 2);

  uint64_t total = 0, reported_total = 0;
  auto next_report = Clock::now() + std::chrono::seconds(1);
  for (;;) {
    total = loop.take();
    const auto now = Clock::now();
    if (interrupt.requested()) return kExitOk;
    if (now >= next_report) {
      print_line(total == reported_total ? std::string("no new messages") : loop.report());
      reported_total = total;
      next_report += std::chrono::seconds(1);
      if (next_report < now) next_report = now + std::chrono::seconds(1);
    }
    if (has_end && now >= end) {
      if (total == 0) {
        char line[100];
        std::snprintf(line, sizeof(line), "no messages received in %g s", loop.duration_s);
        print_line(line);
      }
      return kExitOk;
    }
    auto wake = next_report;
    if (has_end) wake = std::min(wake, end);
    waitset.wait(std::max<std::chrono::nanoseconds>(wake - Clock::now(), std::chrono::nanoseconds::zero()));
  }
}

std::chrono::nanoseconds discovery_wait_within(double discovery_s, double duration_s) {
  auto wait = seconds(discovery_s);
  if (duration_s > 0) wait = std::min<std::chrono::nanoseconds>(wait, seconds(duration_s));
  return wait;
}

std::unique_ptr<xtypes::CdrReader> open_counting_reader(const dds::Participant& participant, const Interrupt& interrupt,
                                                        const std::string& who, const std::string& topic, int domain,
                                                        std::chrono::nanoseconds wait, int* exit_code) {
  *exit_code = kExitOk;
  xtypes::DiscoveredTopic found;
  dds::QosClass without_writers = dds::QosClass::Event;
  if (const auto* ours = recording::find_recordable(topic)) {
    // The compiled descriptor: Cyclone 0.10.2's descriptor built from type objects aborts in
    // key extraction on the first sample of a type with a string key (autonomy/heartbeat).
    found = xtypes::compiled_topic(participant.handle(), ours->name, ours->descriptor);
    without_writers = ours->qos;
  } else {
    std::optional<xtypes::DiscoveredTopic> discovered;
    try {
      discovered = find_discovered_topic(participant, topic, interrupt, wait);
    } catch (const xtypes::TypeLookupError& e) {
      std::cerr << who << ": " << topic << ": " << e.what() << "\n";
      *exit_code = kExitFailed;
      return nullptr;
    }
    if (interrupt.requested()) return nullptr;
    if (!discovered) {
      auto names = TopicRegistry::catalogue().name_list();
      for (auto& n : discovered_topic_names(participant)) names.push_back(n);
      std::cerr << unknown_topic_message(who, topic, names) << " (not in the catalogue, and no process on domain "
                << domain << " has an endpoint of it within " << std::chrono::duration<double>(wait).count()
                << " s; --discovery-wait waits longer)\n";
      *exit_code = kExitUsage;
      return nullptr;
    }
    found = std::move(*discovered);
  }
  Discovery discovery(participant);
  const auto writers = wait_for_writers(discovery, topic, interrupt, participant, wait);
  if (interrupt.requested()) return nullptr;
  const dds::Qos qos = mirror_writers_qos(without_writers, writers);
  return std::make_unique<xtypes::CdrReader>(participant.handle(), found, qos.get());
}

}  // namespace autonomy::tools
