#pragma once
// Round trips and throughput over DDS, through the project's typed layer (dds::Writer<T>,
// dds::Reader<T>, dds::WaitSet, the C++ <-> C conversions) or through the raw Cyclone C API
// (dds_write / dds_take with loans on the generated C type). Both sides of a measurement use the
// same API, the same QoS (the catalogue's "event" class: reliable, volatile, keep-last 256) and
// the same topology: this process and one helper process on loopback.
#include "common/dds/message_types.hpp"

#include "bench_types.h"

#include <cstdint>
#include <string>
#include <vector>

namespace autonomy::bench {

// The 1 KiB payload's C++ value type (idl: bench/bench_types.idl).
struct Blob {
  int32_t id = 0;
  int64_t seq = 0;
  std::vector<uint8_t> data;
};

enum class Api { Raw, Layer };
enum class Payload { RobotState, Blob1K };
const char* to_string(Api a);
const char* to_string(Payload p);
Api parse_api(const std::string& s);
Payload parse_payload(const std::string& s);

// Ping side: `warmup` unmeasured round trips, then `count` measured ones; returns RTTs in us.
// The helper process must run echo() with the same api, payload, domain and tag. It stops when
// this side ends.
std::vector<double> ping(Api api, Payload payload, int domain, const std::string& tag, int warmup, int count);
void echo(Api api, Payload payload, int domain, const std::string& tag);

// Throughput, 1 KiB payload: the writer writes back to back for `seconds`; the reader counts.
struct WriterStats {
  uint64_t written = 0;
  double seconds = 0.0;
};
struct ReaderStats {
  uint64_t received = 0;  // after the warm-up samples
  double seconds = 0.0;   // from the first counted sample to the end marker
  uint64_t lost = 0;      // sequence gaps (keep-last: a slow reader loses old samples)
};
WriterStats throughput_write(Api api, int domain, const std::string& tag, double seconds);
ReaderStats throughput_read(Api api, int domain, const std::string& tag);

// CPU cost of the API alone: a writer and a reader in ONE participant of this process (Cyclone
// delivers to local readers inside dds_write: no network, no thread hop), `samples` written and
// taken in batches of 64. Returns ns per sample (write + take, conversions included).
double local_cost_ns(Api api, Payload payload, int domain, const std::string& tag, int samples);

}  // namespace autonomy::bench

namespace autonomy::dds {
template <>
struct DdsType<bench::Blob> {
  using C = autonomy_bench_Blob;
  static const dds_topic_descriptor_t* descriptor() { return &autonomy_bench_Blob_desc; }
  static const char* type_name() { return autonomy_bench_Blob_desc.m_typename; }
  static void to_c(const bench::Blob& v, C& out, Arena&) {
    out.id = v.id;
    out.seq = v.seq;
    // dds_write copies before it returns: the sample may point into the value.
    const auto n = static_cast<uint32_t>(v.data.size());
    out.data = {n, n, const_cast<uint8_t*>(v.data.data()), false};
  }
  static bench::Blob from_c(const C& in) {
    bench::Blob v;
    v.id = in.id;
    v.seq = in.seq;
    v.data.assign(in.data._buffer, in.data._buffer + in.data._length);
    return v;
  }
};
}  // namespace autonomy::dds
