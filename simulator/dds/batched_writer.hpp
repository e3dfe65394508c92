#pragma once
// A writer whose samples leave only when flushed: the robot states of one tick go out as one
// datagram per reader process instead of one per robot and reader (3 robots, 3 behaviors: 3
// sendmsg calls instead of 9, and each behavior woken once for the states instead of three times).
//
// Cyclone 0.10 batches per writer (whc_batch) but sets the flag only from the domain's
// configuration when a writer is created; dds_write_set_batch() changes that configuration. So the
// flag is switched on for this writer's creation only and off again at once: every other writer
// of the process still sends at each write. Should dds_write_set_batch(false) ever reach this
// writer too, its writes would again leave one by one: slower, never lost, since flush() is then
// a no-op.
#include "common/dds/writer.hpp"

namespace autonomy::sim {

template <typename T>
class BatchedWriter {
 public:
  BatchedWriter(const dds::Participant& participant, const dds::Topic<T>& topic)
      : writer_(create(participant, topic)) {}

  // Queued in the writer until flush().
  void write(const T& value) const { writer_.write(value); }
  // Sends what was written since the last flush (in order, before anything written after).
  void flush() const { dds_write_flush(writer_.handle()); }
  dds_entity_t handle() const { return writer_.handle(); }

 private:
  static dds::Writer<T> create(const dds::Participant& participant, const dds::Topic<T>& topic) {
    struct BatchingWhileCreated {
      BatchingWhileCreated() { dds_write_set_batch(true); }
      ~BatchingWhileCreated() { dds_write_set_batch(false); }
    } batching;
    return dds::Writer<T>(participant, topic);  // constructed in place, before batching ends
  }

  dds::Writer<T> writer_;
};

}  // namespace autonomy::sim
