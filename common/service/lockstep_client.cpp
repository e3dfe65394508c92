#include "common/service/lockstep_client.hpp"

#include <spdlog/spdlog.h>

namespace autonomy::service {

LockstepClient::LockstepClient(const dds::Participant& participant, EventLoop& loop, std::string participant_name,
                               std::function<void(const msg::SimClock&)> on_tick)
    : name_(std::move(participant_name)),
      on_tick_(std::move(on_tick)),
      clock_topic_(participant, dds::topics::clock),
      registration_topic_(participant, dds::topics::lockstep_registration),
      ack_topic_(participant, dds::topics::tick_ack),
      clock_reader_(participant, clock_topic_),
      registration_writer_(participant, registration_topic_),
      ack_writer_(participant, ack_topic_) {
  loop.on_samples<msg::SimClock>(clock_reader_, [this](std::vector<dds::Sample<msg::SimClock>> samples) {
    // Only the newest tick matters: a participant that fell behind catches up in one step.
    const msg::SimClock* newest = nullptr;
    for (const auto& s : samples)
      if (s.valid && (!newest || s.value.tick > newest->tick)) newest = &s.value;
    if (!newest || newest->tick <= clock_.tick()) return;
    clock_.advance(newest->tick, newest->sim_time_ns);
    on_tick_(*newest);
  });
}

LockstepClient::~LockstepClient() {
  try {
    registration_writer_.dispose({name_, false});
  } catch (const std::exception& e) {
    spdlog::warn("could not leave lockstep cleanly: {}", e.what());
  }
}

void LockstepClient::register_participant() { registration_writer_.write({name_, true}); }

void LockstepClient::acknowledge(int64_t tick, uint32_t commands_sent, int64_t quiet_until_tick) {
  last_ack_ = {name_, tick, commands_sent, quiet_until_tick};
  ack_writer_.write(last_ack_);
}

void LockstepClient::wake() {
  if (!quiet()) return;
  last_ack_.quiet_until_tick = 0;
  ack_writer_.write(last_ack_);
}

}  // namespace autonomy::service
