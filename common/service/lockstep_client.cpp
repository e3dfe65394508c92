#include "common/service/lockstep_client.hpp"

#include <spdlog/spdlog.h>

#include <chrono>

namespace autonomy::service {

namespace {
// A second world publishes every tick: the first few warnings say what happens, then one in a
// thousand keeps the log readable while the count in the heartbeat stays exact.
bool worth_a_warning(uint64_t count) { return count <= 5 || count % 1000 == 0; }
// The clock's class keeps one sample: another writer's sample (a second world, a forgery) could
// then replace a real tick before this reader took it, and the tick would never be acknowledged.
// A few samples of history keep every writer's latest.
dds::Qos clock_reader_qos() {
  dds::Qos q = dds::make_qos(dds::topics::clock.qos);
  dds_qset_history(q.get(), DDS_HISTORY_KEEP_LAST, 8);
  return q;
}
int64_t steady_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}
}  // namespace

LockstepClient::LockstepClient(Service& service, std::string participant_name,
                               std::function<void(const msg::SimClock&)> on_tick, TickHandling handling)
    : name_(std::move(participant_name)),
      heartbeat_(service.heartbeat()),
      on_tick_(std::move(on_tick)),
      clock_topic_(service.participant(), dds::topics::clock),
      registration_topic_(service.participant(), dds::topics::lockstep_registration),
      ack_topic_(service.participant(), dds::topics::tick_ack),
      clock_reader_(service.participant(), clock_topic_, clock_reader_qos().get()),
      registration_writer_(service.participant(), registration_topic_),
      ack_writer_(service.participant(), ack_topic_) {
  auto on_clock = [this](std::vector<dds::Sample<msg::SimClock>> samples) {
    // Only the newest tick matters: a participant that fell behind catches up in one step.
    const msg::SimClock* newest = nullptr;
    bool ack_again = false;
    for (const auto& s : samples) {
      if (!s.valid) continue;
      const clock::ClockReading r{s.value.world_id, s.value.tick, s.value.sim_time_ns, s.value.step_ns};
      const clock::ClockVerdict v = check_.check(r, steady_ns());
      // The simulator repeats the clock of a tick it still waits for: an ack of that tick may
      // have been lost (written while this process and the simulator had lost each other, e.g.
      // right after a SIGSTOP or a cut), so it is written again.
      if (v == clock::ClockVerdict::Repeated && acked_ && s.value.tick == last_ack_.tick) ack_again = true;
      if (v == clock::ClockVerdict::Follow) {
        // Built only when logged: explain() formats a string, and this runs at every tick.
        if (!newest && spdlog::should_log(spdlog::level::debug)) spdlog::debug("following {}", check_.explain(r, v));
        newest = &s.value;
      } else if (v != clock::ClockVerdict::Repeated) {
        const uint64_t n = check_.counts().ignored();
        if (worth_a_warning(n)) spdlog::warn("clock sample ignored ({} so far): {}", n, check_.explain(r, v));
        heartbeat_.set_clock_samples_ignored(n);
      }
    }
    if (ack_again && !newest) {
      // Announcing no commands: those written with the lost ack were lost with it (a velocity
      // command holds for one tick; the next tick's replaces it), and the world must not wait
      // for them.
      msg::TickAck again = last_ack_;
      again.commands_sent = 0;
      ack_writer_.write(again);
    }
    if (!newest) return;
    if (clock_.tick() < 0) spdlog::info("joined world {} at tick {}", newest->world_id, newest->tick);
    heartbeat_.set_world(newest->world_id);
    clock_.advance(newest->tick, newest->sim_time_ns);
    on_tick_(*newest);
  };
  if (handling == TickHandling::AtArrival)
    service.loop().on_samples_at_arrival<msg::SimClock>(clock_reader_, std::move(on_clock));
  else
    service.loop().on_samples<msg::SimClock>(clock_reader_, std::move(on_clock));
}

LockstepClient::~LockstepClient() {
  try {
    // Said first, then disposed: the simulator tells a participant that leaves from one whose
    // registration ended with its process (killed, stopped, cut off), which it keeps waiting for.
    registration_writer_.write({name_, false});
    registration_writer_.dispose({name_, false});
  } catch (const std::exception& e) {
    spdlog::warn("could not leave lockstep cleanly: {}", e.what());
  }
}

void LockstepClient::register_participant() { registration_writer_.write({name_, true}); }

void LockstepClient::acknowledge(int64_t tick, uint32_t commands_sent, int64_t quiet_until_tick) {
  last_ack_ = {name_, tick, commands_sent, quiet_until_tick};
  acked_ = true;
  // The clock (state, transient-local) can reach a new participant before its ack writer is
  // matched with the simulator's reader; an ack written then is lost (volatile) and the simulator
  // drops the participant after its ack timeout. Under DDS Security each endpoint pair matches
  // only after its crypto tokens are exchanged, so this window is wide: wait for the match.
  if (ack_writer_.matched_readers() == 0 && !ack_writer_.wait_for_readers(1, std::chrono::seconds(2)))
    spdlog::warn("lockstep: no simulator reads the acks of {} yet; tick {} acknowledged anyway", name_, tick);
  ack_writer_.write(last_ack_);
}

void LockstepClient::wake() {
  if (!quiet()) return;
  last_ack_.quiet_until_tick = 0;
  ack_writer_.write(last_ack_);
}

}  // namespace autonomy::service
