#pragma once
// QoS classes by purpose (DESIGN.md, "Topics"). Every topic names one class; nothing else in the
// project builds a dds_qos_t by hand.
#include <dds/dds.h>

#include <memory>
#include <string>

namespace autonomy::dds {

enum class QosClass {
  State,    // reliable, transient-local, keep-last 1 per key: late joiners get the current state
  Stream,   // best effort, volatile, keep-last 4: high-rate sensing, newest wins
  Command,  // reliable, volatile, keep-last 32 per key: every command of a tick is seen
  Event,    // reliable, volatile, keep-last 256: occurrences, counted by their readers
  Request,  // reliable, volatile, keep-last 64: the asking half of request/reply
  Reply,    // reliable, volatile, keep-last 64: the answering half, correlated by request id
  Queue,    // reliable, volatile, keep-all: nothing dropped; a writer whose readers fall behind
            // blocks (up to the blocking time) and then fails its write, so the loss is seen
};

const char* to_string(QosClass c);

struct QosDeleter {
  void operator()(dds_qos_t* q) const { dds_delete_qos(q); }
};
using Qos = std::unique_ptr<dds_qos_t, QosDeleter>;

// The QoS for readers and writers of a class; topic QoS is left at its default so that readers
// of another class (tools matching a writer) can still share the topic.
Qos make_qos(QosClass c);

// Writers of the state class dispose their instances when they are deleted, so a cleanly stopped
// service's state disappears; a crashed one's stays until its lease expires.
}  // namespace autonomy::dds
