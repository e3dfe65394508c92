#pragma once
// Bookkeeping for the lockstep handshake (idl/clock.idl), without DDS or clocks: the caller
// feeds it samples and wall time and asks whether the world may step.
//
// Protocol, for one tick k at a time:
//  1. The simulator calls begin_tick(k, now) and publishes the clock sample for tick k.
//  2. Each registered participant reacts to tick k, writes its velocity commands stamped k and
//     then a TickAck{participant, k, commands_sent}. DDS orders samples per writer and per
//     topic only, so commands may arrive before or after the ack: the barrier counts both.
//  3. complete(k) holds when every participant waited for at tick k has acked k and all the
//     commands it announced for k have arrived. The simulator then applies the commands, steps
//     the world and calls end_tick(k), which forgets the counters of k.
//  4. A participant that has not completed k within `timeout` of begin_tick is dropped by
//     expire(), so a dead process cannot hang the world. A dropped participant that acks the
//     current tick later rejoins (its ack counts for that tick); one that called remove() (left
//     on purpose) must add() itself again.
//  A participant added while tick k is open is waited for from tick k+1 on (it may not have
//  seen tick k), unless it acks k anyway or is added `from_current` (registered while the
//  start was held: the world has not begun, so it takes part from tick 0). Acks and commands for ticks before the current one
//  are stale and ignored.
//
// Quiet ticks: an ack may declare its participant quiet until a later tick (it has nothing to do
// before then unless the world changes or it is sent something). quiet(k) holds when everybody
// waited for at k is quiet beyond k: the simulator may then step k without publishing it. Every
// ack replaces its participant's declaration, a stale one too: a quiet participant that is sent
// something acks its last tick again with no quiet tick to wake the world.
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace autonomy::sim {

class LockstepBarrier {
 public:
  using Tick = std::int64_t;

  enum class AckOutcome {
    Counted,       // a registered participant acked the current (or a later) tick
    Rejoined,      // a dropped participant acked and is registered again
    IgnoredStale,  // the ack is for a tick that has already ended
    IgnoredUnknown // never registered, or left on purpose: it must add() itself first
  };

  // Registers a participant (idempotent). Returns false when it was already registered.
  // `from_current`: wait for it at the open tick too (it registered before the world started,
  // while tick 0 was held for it, and reads that tick's clock sample from the durable topic).
  bool add(const std::string& participant, bool from_current = false);
  // A participant leaves on purpose: not waited for, and an ack does not bring it back.
  void remove(const std::string& participant);
  // A participant fell silent (its process died, stopped or is cut off): its quiet declaration
  // no longer holds, since it could not wake the world when sent something. It stays waited for.
  void silent(const std::string& participant);

  void begin_tick(Tick tick, double now_s);
  AckOutcome on_ack(const std::string& participant, Tick tick, std::uint32_t commands_sent, Tick quiet_until = 0);
  // Counts one command from `source` for `tick`. False when the tick has already ended or
  // `source` is neither registered nor dropped (a dropped participant's command counts: its ack
  // for the same tick may be the one that rejoins it, and announces it). An unknown source's
  // acks and commands are kept for the tick, so that one added `from_current` a moment later
  // (its registration overtaken by its answer) is complete at once.
  bool on_command(const std::string& source, Tick tick);

  // Every participant waited for at `tick` (the current tick) has acked it and all its announced
  // commands have arrived. False for any tick other than the current one.
  bool complete(Tick tick) const;
  // Everybody waited for at `tick` declared, by their last ack, that they need no tick before a
  // later one. False when nobody is waited for.
  bool quiet(Tick tick) const;
  // Drops and returns (sorted) the participants that have not completed the current tick
  // `tick` when `timeout_s` has passed since begin_tick.
  std::vector<std::string> expire(Tick tick, double now_s, double timeout_s);
  // Forgets the counters of `tick` and every earlier tick.
  void end_tick(Tick tick);

  std::vector<std::string> participants() const;  // registered, sorted
  bool has_participants() const { return !members_.empty(); }
  // Dropped by expire() and not back yet (sorted): an ack or add() takes one back.
  std::vector<std::string> dropped() const { return {dropped_.begin(), dropped_.end()}; }
  bool is_dropped(const std::string& participant) const { return dropped_.count(participant) > 0; }
  std::optional<Tick> current_tick() const { return current_; }

 private:
  struct TickCounters {
    std::map<std::string, std::uint32_t> announced;  // participant -> commands_sent of its ack
    std::map<std::string, std::uint32_t> received;   // source -> commands arrived
  };

  bool stale(Tick tick) const { return current_ && tick < *current_; }
  bool done(const std::string& participant, Tick tick) const;
  // Participants that must complete `tick`.
  std::vector<std::string> waited_for(Tick tick) const;

  std::map<std::string, Tick> members_;  // participant -> first tick it is waited for
  std::set<std::string> dropped_;        // expired, may rejoin by acking
  std::map<std::string, Tick> quiet_until_;  // participant -> the first tick it needs again
  std::map<Tick, TickCounters> ticks_;   // current tick and any early samples for later ones
  std::optional<Tick> current_;
  double tick_started_s_ = 0.0;
};

}  // namespace autonomy::sim
