#pragma once
// The participant's side of simulated time: follow autonomy/clock, register for lockstep, and
// acknowledge each tick once this process's commands for it are written.
//
// Protocol (the simulator's side is simulator/core/lockstep_barrier.hpp):
//   1. the simulator publishes the world state of tick k, then SimClock{tick = k};
//   2. each registered participant computes from the state of tick k, writes its commands stamped
//      k, then writes TickAck{k, commands_sent};
//   3. the simulator applies the commands once every participant's ack and announced commands
//      for k arrived (or drops a participant that stays silent past the ack timeout), steps to k+1.
//
// Every service reads the clock here, so the clock check lives here once: the process joins the
// world of the first clock it hears and ignores another world's clock, a tick that goes back and
// an absurd leap forward, each with a warning, counted in its heartbeat (common/clock/clock_check.hpp).
#include "common/clock/clock.hpp"
#include "common/clock/clock_check.hpp"
#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"
#include "common/service/event_loop.hpp"
#include "common/service/service.hpp"

#include <functional>
#include <string>

namespace autonomy::service {

// Where on_tick runs: InLoop on the loop's thread; AtArrival in the DDS receive thread that
// delivered the clock when the loop allows it (EventLoop::on_samples_at_arrival; one thread
// wake-up less per tick), for participants whose tick handler is short.
enum class TickHandling { InLoop, AtArrival };

class LockstepClient {
 public:
  // on_tick runs for every new tick of the joined world (one at a time with the loop's other
  // handlers, see TickHandling); repeated ticks are skipped, ignored ones (clock_check()) are
  // warned about and counted in the service's heartbeat.
  LockstepClient(Service& service, std::string participant_name, std::function<void(const msg::SimClock&)> on_tick,
                 TickHandling handling = TickHandling::InLoop);
  // Leaves the lockstep set at once (disposes the registration) instead of waiting for a timeout.
  ~LockstepClient();

  // Joins the set of participants the simulator waits for.
  void register_participant();
  // quiet_until_tick > tick + 1: nothing to do before that tick unless the world changes or
  // this process is sent something (idl/clock.idl); 0: not quiet.
  void acknowledge(int64_t tick, uint32_t commands_sent, int64_t quiet_until_tick = 0);
  // This process was sent something while it was quiet: the world must not skip the next tick.
  // Acks the last tick again without a quiet tick; does nothing when not quiet.
  void wake();
  bool quiet() const { return last_ack_.quiet_until_tick > last_ack_.tick + 1; }
  int64_t quiet_until_tick() const { return last_ack_.quiet_until_tick; }

  const clock::SimulatedClock& clock() const { return clock_; }
  const clock::ClockCheck& clock_check() const { return check_; }
  const std::string& name() const { return name_; }

 private:
  std::string name_;
  clock::SimulatedClock clock_;
  clock::ClockCheck check_;
  HeartbeatPublisher& heartbeat_;
  std::function<void(const msg::SimClock&)> on_tick_;
  dds::Topic<msg::SimClock> clock_topic_;
  dds::Topic<msg::LockstepRegistration> registration_topic_;
  dds::Topic<msg::TickAck> ack_topic_;
  dds::Reader<msg::SimClock> clock_reader_;
  dds::Writer<msg::LockstepRegistration> registration_writer_;
  dds::Writer<msg::TickAck> ack_writer_;
  msg::TickAck last_ack_;
  bool acked_ = false;  // last_ack_ was written (a tick was acknowledged)
};

}  // namespace autonomy::service
