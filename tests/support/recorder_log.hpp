#pragma once
// What `autonomy record --verbose` said about its readers: a lockstep world runs faster than a
// loaded machine discovers, so a test that records a run holds the world until the recorder's
// readers matched the writers whose samples a replay needs (docs/recording.md, "A recording must
// hold every input").
#include <chrono>
#include <map>
#include <regex>
#include <string>
#include <thread>

#include "common/mcap/reader.hpp"

namespace autonomy::test {

// The last number of writers the recorder said `topic`'s reader is matched with is at least
// `writers` ("autonomy record: TOPIC: N writer(s) matched" lines in `recorder_output`).
inline bool recorder_matched(const std::string& recorder_output, const std::string& topic, unsigned writers) {
  const std::regex line("autonomy record: " + topic + ": ([0-9]+) writer\\(s\\) matched");
  unsigned last = 0;
  for (std::sregex_iterator it(recorder_output.begin(), recorder_output.end(), line), end; it != end; ++it)
    last = static_cast<unsigned>(std::stoul((*it)[1]));
  return last >= writers;
}

// Whether the recording being written stopped growing: its messages per topic (complete chunks;
// heartbeats and the simulator's status left out, they go on at 1 Hz in a quiet or stopped world)
// are the same as at the previous call, kept in `last`. A recorder is slower than a lockstep world
// on a loaded machine: a test stops the world first (or waits until it is quiet), then calls this
// until it holds, and only then stops the recorder, so the file's tail is whole. Waits two chunk
// periods (`chunk_s`) when it does not hold, so that the next call sees newer chunks.
inline bool recording_stopped_growing(const std::string& file, std::map<std::string, std::size_t>& last,
                                      double chunk_s = 0.2) {
  std::map<std::string, std::size_t> now;
  try {
    mcap::Reader reader(file);
    reader.read([&](const mcap::Channel& c, const mcap::Schema*, const mcap::Message&) {
      if (c.topic != "autonomy/heartbeat" && c.topic != "autonomy/sim/status") ++now[c.topic];
    });
  } catch (const mcap::McapError&) {
    now.clear();  // not even the header yet
  }
  const bool same = !now.empty() && now == last;
  last = std::move(now);
  if (!same) std::this_thread::sleep_for(std::chrono::duration<double>(2 * chunk_s));
  return same;
}

}  // namespace autonomy::test
