#pragma once
// The loop of `topic hz` and `topic bw`: wait for samples (or Ctrl-C), take them, and print a
// report line every second ("no new messages" when none came since the previous line), until
// Ctrl-C or the end of --duration.
#include <chrono>
#include <cstdint>
#include <functional>
#include <string>

#include <memory>

#include "tools/autonomy/common.hpp"
#include "tools/xtypes/discovered_topic.hpp"

namespace autonomy::tools {

struct ReportLoop {
  using Clock = std::chrono::steady_clock;
  dds_entity_t data_condition = 0;   // triggers while the reader holds samples
  Clock::time_point start;           // --duration counts from here (the command's start)
  double duration_s = 0.0;           // 0: until Ctrl-C
  // Takes what the reader holds; returns the number of samples taken so far.
  std::function<uint64_t()> take;
  // The statistics line, printed every second when samples came since the previous one.
  std::function<std::string()> report;
};

// Runs the loop; returns kExitOk on Ctrl-C or at the end of the duration ("no messages received
// in D s" when nothing came at all).
int run_report_loop(const dds::Participant& participant, const Interrupt& interrupt, const ReportLoop& loop);

// How long to wait for a topic's endpoints: --discovery-wait, but not beyond --duration.
std::chrono::nanoseconds discovery_wait_within(double discovery_s, double duration_s);

// A reader of any topic's samples as serialized (CDR, encapsulation header included; nothing is
// decoded), for the commands that count them: a catalogue topic with its compiled type, any
// other with the type its endpoints announce in discovery. Its reliability and durability mirror
// the writers discovered within `wait`, so that every writer matches. On failure it prints why
// (as `who`, e.g. "autonomy topic bw") and returns null with *exit_code set: 2 unknown topic
// (with the nearest names), 1 the type cannot be had; null with kExitOk when interrupted.
std::unique_ptr<xtypes::CdrReader> open_counting_reader(const dds::Participant& participant, const Interrupt& interrupt,
                                                        const std::string& who, const std::string& topic, int domain,
                                                        std::chrono::nanoseconds wait, int* exit_code);

}  // namespace autonomy::tools
