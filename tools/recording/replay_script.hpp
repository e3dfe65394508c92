#pragma once
// A recorded lockstep run turned into what `autonomy replay` does (docs/recording.md, "Replay"):
// the inputs to republish into a fresh world, each at the tick it was given at, and the world's
// recorded outputs the fresh world must reproduce. No DDS here: the tool decodes the samples,
// this orders the inputs and checks the outputs.
//
// When an input is due. A sample stamped with a tick (commands, acks) is due at that tick. An
// ack that repeats its participant's ack of an earlier tick woke a quiet world: it is due at the
// tick of that participant's next ack (where the recorded world woke). Any other sample is due
// at the tick the recorded world showed when it was written: the last clock published before it
// (by the writers' source timestamps, which order samples of one host exactly; the recorder's
// own reception times do not: it takes a topic's samples in batches). Before the first clock:
// at the start. At one tick the acks go last, so that whatever a participant wrote before its
// ack is there when the fresh world may step.
//
// When an output is checked. A recorded output stamped with tick t was written before the
// world published any later tick: it is due at the first recorded clock after t, and must match
// a fresh output of the same topic and tick exactly (the decoded value, world_id members left
// out: every run draws its own). A recorder can miss samples of state topics (keep-last 1), so
// the fresh world may publish more than was recorded; never less or other.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace autonomy::recording {

using Json = nlohmann::ordered_json;

inline constexpr int64_t kAtStart = -1;

struct RecordedSample {
  std::string topic;
  uint64_t log_time = 0;         // when the recorder took it (the file's order)
  uint64_t publish_time = 0;     // the writer's source timestamp
  std::string cdr;              // what the tool republishes (inputs)
  Json value;                   // decoded (outputs; the participant of acks)
  std::optional<int64_t> tick;  // the value's own top-level "tick", when its type has one
};

struct ReplayInput {
  int64_t due = kAtStart;
  std::string topic;
  std::string cdr;
};

// The lockstep acknowledgements: the one input topic a replay orders specially.
inline constexpr const char* kLockstepAckTopic = "autonomy/lockstep/ack";

// A value without the members that name the run rather than the world (world_id, at any depth).
Json world_content(Json value);

inline constexpr const char* kLockstepRegistrationTopic = "autonomy/lockstep/registration";

// A recording a replay cannot reproduce exactly, found before replaying it: commands stamped
// with a tick (inputs with a "source") from a registered lockstep participant whose ack of that
// tick is not in the file. Every such participant acks each tick it sent commands for, after
// them, and the fresh world waits for the replayed ack before it applies them: without it the
// world may apply them a tick late. A recorder whose readers matched the writers only after the
// world began (or that stopped before the last samples reached it) leaves such holes. Returns
// one sentence naming how many and the first; nullopt when every command has its ack.
std::optional<std::string> unacknowledged_commands(const std::vector<RecordedSample>& inputs);

struct OutputMismatch {
  std::string topic;
  int64_t tick = 0;
  Json recorded;
  std::vector<Json> fresh;  // the fresh world's samples of that topic and tick
  std::string describe() const;  // one paragraph: what differs, as JSON paths
};

class ReplayScript {
 public:
  // inputs, outputs: recorded samples of the topics to republish and of those to check; clocks:
  // the recorded clock samples. Any order: sorted here by log time (one topic's samples keep
  // the order they were written in).
  ReplayScript(std::vector<RecordedSample> inputs, std::vector<RecordedSample> outputs,
               std::vector<RecordedSample> clocks);

  // Every input in the order to republish it, with the tick it is due at.
  const std::vector<ReplayInput>& inputs() const { return inputs_; }
  // The recorded clock ticks, ascending; the first one after `tick` (nullopt: none).
  const std::vector<int64_t>& clock_ticks() const { return clock_ticks_; }
  std::optional<int64_t> next_clock_after(int64_t tick) const;
  // The tick the fresh world must reach: the last recorded clock, or a later tick an input is
  // due at or an output is stamped with (the recorder may have taken those after its last clock).
  int64_t last_tick() const { return last_tick_; }
  // Recorded outputs to check (those stamped with a tick).
  std::size_t outputs() const { return outputs_.size(); }

  // A fresh output, decoded (world_content applied here).
  void fresh_output(const std::string& topic, int64_t tick, Json value);
  // Whether a fresh output of `topic` stamped `tick` has arrived (matched or not).
  bool has_fresh(const std::string& topic, int64_t tick) const { return fresh_.count({topic, tick}) > 0; }
  // Matches the outputs due by `clock` against the fresh ones. Returns the first that has no
  // fresh twin (so far), or nullopt when every output due has one. Matched outputs are not
  // looked at again. One fresh sample answers every recorded sample equal to it: a world held
  // at a tick writes its clock again each second, so how many copies a recording holds follows
  // wall time, not the world.
  std::optional<OutputMismatch> check_due_by(int64_t clock);
  std::size_t matched() const { return matched_; }
  // Topics of the outputs, with their counts (for the summary).
  std::map<std::string, std::size_t> outputs_by_topic() const;

 private:
  struct Expected {
    int64_t due = 0;
    std::string topic;
    int64_t tick = 0;
    Json value;
  };
  std::vector<ReplayInput> inputs_;
  std::vector<int64_t> clock_ticks_;
  int64_t last_tick_ = kAtStart;
  std::vector<Expected> outputs_;  // by due, then log time
  std::size_t next_unchecked_ = 0;
  std::size_t matched_ = 0;
  // Fresh outputs not matched yet, by (topic, tick).
  std::map<std::pair<std::string, int64_t>, std::vector<Json>> fresh_;
};

}  // namespace autonomy::recording
