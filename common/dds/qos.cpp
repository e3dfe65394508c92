#include "common/dds/qos.hpp"

namespace autonomy::dds {

const char* to_string(QosClass c) {
  switch (c) {
    case QosClass::State: return "state";
    case QosClass::Stream: return "stream";
    case QosClass::Command: return "command";
    case QosClass::Event: return "event";
    case QosClass::Request: return "request";
    case QosClass::Reply: return "reply";
    case QosClass::Queue: return "queue";
  }
  return "?";
}

Qos make_qos(QosClass c) {
  Qos q(dds_create_qos());
  // A reliable writer may block this long when a reader's history is full before write fails.
  const dds_duration_t max_blocking = DDS_MSECS(500);
  switch (c) {
    case QosClass::State:
      dds_qset_reliability(q.get(), DDS_RELIABILITY_RELIABLE, max_blocking);
      dds_qset_durability(q.get(), DDS_DURABILITY_TRANSIENT_LOCAL);
      dds_qset_history(q.get(), DDS_HISTORY_KEEP_LAST, 1);
      break;
    case QosClass::Stream:
      dds_qset_reliability(q.get(), DDS_RELIABILITY_BEST_EFFORT, 0);
      dds_qset_durability(q.get(), DDS_DURABILITY_VOLATILE);
      dds_qset_history(q.get(), DDS_HISTORY_KEEP_LAST, 4);
      break;
    case QosClass::Command:
      dds_qset_reliability(q.get(), DDS_RELIABILITY_RELIABLE, max_blocking);
      dds_qset_durability(q.get(), DDS_DURABILITY_VOLATILE);
      dds_qset_history(q.get(), DDS_HISTORY_KEEP_LAST, 32);
      break;
    case QosClass::Event:
      dds_qset_reliability(q.get(), DDS_RELIABILITY_RELIABLE, max_blocking);
      dds_qset_durability(q.get(), DDS_DURABILITY_VOLATILE);
      dds_qset_history(q.get(), DDS_HISTORY_KEEP_LAST, 256);
      break;
    case QosClass::Request:
    case QosClass::Reply:
      dds_qset_reliability(q.get(), DDS_RELIABILITY_RELIABLE, max_blocking);
      dds_qset_durability(q.get(), DDS_DURABILITY_VOLATILE);
      dds_qset_history(q.get(), DDS_HISTORY_KEEP_LAST, 64);
      break;
    case QosClass::Queue:
      dds_qset_reliability(q.get(), DDS_RELIABILITY_RELIABLE, max_blocking);
      dds_qset_durability(q.get(), DDS_DURABILITY_VOLATILE);
      dds_qset_history(q.get(), DDS_HISTORY_KEEP_ALL, 0);
      break;
  }
  return q;
}

}  // namespace autonomy::dds
