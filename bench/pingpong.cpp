#include "bench/pingpong.hpp"

#include "bench/bench_support.hpp"
#include "common/dds/reader.hpp"
#include "common/dds/waitset.hpp"
#include "common/dds/writer.hpp"

#include <array>
#include <stdexcept>
#include <thread>

namespace autonomy::bench {

namespace {

constexpr auto kQos = dds::QosClass::Event;  // reliable, volatile, keep-last 256
constexpr size_t kBatch = 64;                // the layer's take batch, used by the raw side too
constexpr int64_t kThroughputWarmup = 20000;  // samples the throughput reader does not count
constexpr size_t kBlobBytes = 1024;

std::string ping_topic(const std::string& tag) { return "bench/ping/" + tag; }
std::string pong_topic(const std::string& tag) { return "bench/pong/" + tag; }
std::string tp_topic(const std::string& tag) { return "bench/throughput/" + tag; }

// The sequence number each payload carries (a negative one ends the run).
int64_t& seq_of(msg::RobotState& v) { return v.tick; }
int64_t& seq_of(Blob& v) { return v.seq; }
int64_t seq_of(const autonomy_RobotState& c) { return c.tick; }
int64_t& seq_of(autonomy_RobotState& c) { return c.tick; }
int64_t seq_of(const autonomy_bench_Blob& c) { return c.seq; }
int64_t& seq_of(autonomy_bench_Blob& c) { return c.seq; }

msg::RobotState robot_state_value() {
  msg::RobotState s;
  s.robot_id = "r1";
  s.sim_time_ns = 123456789;
  s.x = 2.0;
  s.y = 3.0;
  s.theta = 0.5;
  s.vx = 0.8;
  s.omega = 0.1;
  s.kinematics = msg::Kinematics::Unicycle;
  s.radius = 0.3;
  s.max_speed = 1.0;
  s.max_omega = 2.0;
  return s;
}

Blob blob_value() {
  Blob b;
  b.id = 1;
  b.data.resize(kBlobBytes);
  for (size_t i = 0; i < kBlobBytes; ++i) b.data[i] = static_cast<uint8_t>(i * 7);
  return b;
}

// C samples for the raw side point at these (dds_write copies).
char g_robot_id[] = "r1";
std::array<uint8_t, kBlobBytes> g_blob_bytes{};

autonomy_RobotState robot_state_c() {
  autonomy_RobotState c{};
  dds::Arena arena;
  dds::DdsType<msg::RobotState>::to_c(robot_state_value(), c, arena);
  c.robot_id = g_robot_id;
  return c;
}

autonomy_bench_Blob blob_c() {
  for (size_t i = 0; i < kBlobBytes; ++i) g_blob_bytes[i] = static_cast<uint8_t>(i * 7);
  autonomy_bench_Blob c{};
  c.id = 1;
  c.data = {kBlobBytes, kBlobBytes, g_blob_bytes.data(), false};
  return c;
}

template <typename Pred>
void wait_until(Pred pred, const char* what) {
  const auto deadline = Clock::now() + std::chrono::seconds(15);
  while (!pred()) {
    if (Clock::now() > deadline) throw std::runtime_error(std::string("timed out waiting for ") + what);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

uint32_t raw_pub_matched(dds_entity_t w) {
  dds_publication_matched_status_t st{};
  dds_get_publication_matched_status(w, &st);
  return st.current_count;
}
uint32_t raw_sub_matched(dds_entity_t r) {
  dds_subscription_matched_status_t st{};
  dds_get_subscription_matched_status(r, &st);
  return st.current_count;
}

dds_entity_t checked(dds_entity_t e, const char* what) {
  if (e < 0) throw std::runtime_error(std::string(what) + ": " + dds_strretcode(e));
  return e;
}

// ---------------------------------------------------------------- typed layer

template <typename T>
std::vector<double> layer_ping(int domain, const std::string& tag, int warmup, int count, T value) {
  const std::string ping_name = ping_topic(tag), pong_name = pong_topic(tag);
  dds::Participant p(domain);
  dds::Topic<T> ping_t(p, dds::TopicSpec<T>{ping_name.c_str(), kQos});
  dds::Topic<T> pong_t(p, dds::TopicSpec<T>{pong_name.c_str(), kQos});
  dds::Writer<T> writer(p, ping_t);
  dds::Reader<T> reader(p, pong_t);
  dds::WaitSet ws(p);
  ws.attach(reader.data_condition(), 1);
  wait_until([&] { return writer.matched_readers() >= 1 && reader.matched_writers() >= 1; }, "echo (layer)");

  std::vector<double> rtt;
  rtt.reserve(static_cast<size_t>(count));
  for (int64_t i = 0; i < warmup + count; ++i) {
    seq_of(value) = i;
    const auto t0 = Clock::now();
    writer.write(value);
    bool got = false;
    int timeouts = 0;
    while (!got) {
      if (ws.wait(std::chrono::seconds(1)).empty()) {
        if (++timeouts > 5) throw std::runtime_error("echo (layer) does not answer");
        writer.write(value);  // the first samples may precede the far side's discovery
        continue;
      }
      for (const auto& s : reader.take())
        if (s.valid && seq_of(const_cast<T&>(s.value)) == i) got = true;
    }
    if (i >= warmup) rtt.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
  }
  seq_of(value) = -1;
  writer.write(value);
  return rtt;
}

template <typename T>
void layer_echo(int domain, const std::string& tag) {
  const std::string ping_name = ping_topic(tag), pong_name = pong_topic(tag);
  dds::Participant p(domain);
  dds::Topic<T> ping_t(p, dds::TopicSpec<T>{ping_name.c_str(), kQos});
  dds::Topic<T> pong_t(p, dds::TopicSpec<T>{pong_name.c_str(), kQos});
  dds::Reader<T> reader(p, ping_t);
  dds::Writer<T> writer(p, pong_t);
  dds::WaitSet ws(p);
  ws.attach(reader.data_condition(), 1);
  wait_until([&] { return writer.matched_readers() >= 1; }, "ping side (layer)");
  for (;;) {
    if (ws.wait(std::chrono::seconds(10)).empty()) throw std::runtime_error("ping side (layer) went silent");
    for (const auto& s : reader.take()) {
      if (!s.valid) continue;
      writer.write(s.value);
      if (seq_of(const_cast<T&>(s.value)) < 0) return;
    }
  }
}

template <typename T>
WriterStats layer_tp_write(int domain, const std::string& tag, double seconds, T value) {
  const std::string name = tp_topic(tag);
  dds::Participant p(domain);
  dds::Topic<T> topic(p, dds::TopicSpec<T>{name.c_str(), kQos});
  dds::Writer<T> writer(p, topic);
  if (!writer.wait_for_readers(1, std::chrono::seconds(15))) throw std::runtime_error("no throughput reader (layer)");
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // let the reader side match too
  WriterStats st;
  const auto t0 = Clock::now();
  int64_t i = 0;
  while (seconds_since(t0) < seconds) {
    for (int k = 0; k < 256; ++k) {
      seq_of(value) = i++;
      writer.write(value);
    }
  }
  st.seconds = seconds_since(t0);
  st.written = static_cast<uint64_t>(i);
  seq_of(value) = -1;
  writer.write(value);
  return st;
}

template <typename T>
ReaderStats layer_tp_read(int domain, const std::string& tag) {
  const std::string name = tp_topic(tag);
  dds::Participant p(domain);
  dds::Topic<T> topic(p, dds::TopicSpec<T>{name.c_str(), kQos});
  dds::Reader<T> reader(p, topic);
  dds::WaitSet ws(p);
  ws.attach(reader.data_condition(), 1);
  ReaderStats st;
  Clock::time_point first{};
  int64_t last = -1;
  for (;;) {
    if (ws.wait(std::chrono::seconds(20)).empty()) throw std::runtime_error("throughput writer (layer) went silent");
    for (const auto& s : reader.take()) {
      if (!s.valid) continue;
      const int64_t seq = s.value.seq;
      if (seq < 0) {
        st.seconds = std::chrono::duration<double>(Clock::now() - first).count();
        return st;
      }
      if (seq < kThroughputWarmup) continue;
      if (st.received == 0) first = Clock::now();
      else if (seq > last + 1) st.lost += static_cast<uint64_t>(seq - last - 1);
      last = seq;
      ++st.received;
    }
  }
}

// ---------------------------------------------------------------- raw Cyclone C API

struct RawParticipant {
  dds_entity_t handle;
  explicit RawParticipant(int domain)
      : handle(checked(dds_create_participant(static_cast<dds_domainid_t>(domain), nullptr, nullptr),
                       "dds_create_participant")) {}
  ~RawParticipant() { dds_delete(handle); }
};

template <typename C>
std::vector<double> raw_ping(int domain, const std::string& tag, int warmup, int count,
                             const dds_topic_descriptor_t* desc, C sample) {
  RawParticipant p(domain);
  const dds::Qos qos = dds::make_qos(kQos);
  const dds_entity_t ping_t = checked(dds_create_topic(p.handle, desc, ping_topic(tag).c_str(), nullptr, nullptr), "topic");
  const dds_entity_t pong_t = checked(dds_create_topic(p.handle, desc, pong_topic(tag).c_str(), nullptr, nullptr), "topic");
  const dds_entity_t w = checked(dds_create_writer(p.handle, ping_t, qos.get(), nullptr), "writer");
  const dds_entity_t r = checked(dds_create_reader(p.handle, pong_t, qos.get(), nullptr), "reader");
  const dds_entity_t rc = checked(dds_create_readcondition(r, DDS_ANY_STATE), "readcondition");
  const dds_entity_t ws = checked(dds_create_waitset(p.handle), "waitset");
  dds_waitset_attach(ws, rc, 1);
  wait_until([&] { return raw_pub_matched(w) >= 1 && raw_sub_matched(r) >= 1; }, "echo (raw)");

  std::vector<double> rtt;
  rtt.reserve(static_cast<size_t>(count));
  void* buf[kBatch];
  dds_sample_info_t info[kBatch];
  for (int64_t i = 0; i < warmup + count; ++i) {
    seq_of(sample) = i;
    const auto t0 = Clock::now();
    checked(dds_write(w, &sample), "dds_write");
    bool got = false;
    int timeouts = 0;
    while (!got) {
      dds_attach_t x;
      if (dds_waitset_wait(ws, &x, 1, DDS_SECS(1)) == 0) {
        if (++timeouts > 5) throw std::runtime_error("echo (raw) does not answer");
        dds_write(w, &sample);
        continue;
      }
      buf[0] = nullptr;
      const dds_return_t n = checked(dds_take(rc, buf, info, kBatch, kBatch), "dds_take");
      for (dds_return_t j = 0; j < n; ++j)
        if (info[j].valid_data && seq_of(*static_cast<const C*>(buf[j])) == i) got = true;
      if (n > 0) dds_return_loan(rc, buf, n);
    }
    if (i >= warmup) rtt.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
  }
  seq_of(sample) = -1;
  dds_write(w, &sample);
  return rtt;
}

template <typename C>
void raw_echo(int domain, const std::string& tag, const dds_topic_descriptor_t* desc) {
  RawParticipant p(domain);
  const dds::Qos qos = dds::make_qos(kQos);
  const dds_entity_t ping_t = checked(dds_create_topic(p.handle, desc, ping_topic(tag).c_str(), nullptr, nullptr), "topic");
  const dds_entity_t pong_t = checked(dds_create_topic(p.handle, desc, pong_topic(tag).c_str(), nullptr, nullptr), "topic");
  const dds_entity_t r = checked(dds_create_reader(p.handle, ping_t, qos.get(), nullptr), "reader");
  const dds_entity_t w = checked(dds_create_writer(p.handle, pong_t, qos.get(), nullptr), "writer");
  const dds_entity_t rc = checked(dds_create_readcondition(r, DDS_ANY_STATE), "readcondition");
  const dds_entity_t ws = checked(dds_create_waitset(p.handle), "waitset");
  dds_waitset_attach(ws, rc, 1);
  wait_until([&] { return raw_pub_matched(w) >= 1; }, "ping side (raw)");
  void* buf[kBatch];
  dds_sample_info_t info[kBatch];
  for (;;) {
    dds_attach_t x;
    if (dds_waitset_wait(ws, &x, 1, DDS_SECS(10)) == 0) throw std::runtime_error("ping side (raw) went silent");
    buf[0] = nullptr;
    const dds_return_t n = checked(dds_take(rc, buf, info, kBatch, kBatch), "dds_take");
    bool stop = false;
    for (dds_return_t j = 0; j < n; ++j) {
      if (!info[j].valid_data) continue;
      dds_write(w, buf[j]);  // the loaned sample goes straight back
      if (seq_of(*static_cast<const C*>(buf[j])) < 0) stop = true;
    }
    if (n > 0) dds_return_loan(rc, buf, n);
    if (stop) return;
  }
}

WriterStats raw_tp_write(int domain, const std::string& tag, double seconds) {
  RawParticipant p(domain);
  const dds::Qos qos = dds::make_qos(kQos);
  const dds_entity_t t =
      checked(dds_create_topic(p.handle, &autonomy_bench_Blob_desc, tp_topic(tag).c_str(), nullptr, nullptr), "topic");
  const dds_entity_t w = checked(dds_create_writer(p.handle, t, qos.get(), nullptr), "writer");
  wait_until([&] { return raw_pub_matched(w) >= 1; }, "throughput reader (raw)");
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  autonomy_bench_Blob sample = blob_c();
  WriterStats st;
  const auto t0 = Clock::now();
  int64_t i = 0;
  while (seconds_since(t0) < seconds) {
    for (int k = 0; k < 256; ++k) {
      sample.seq = i++;
      checked(dds_write(w, &sample), "dds_write");
    }
  }
  st.seconds = seconds_since(t0);
  st.written = static_cast<uint64_t>(i);
  sample.seq = -1;
  dds_write(w, &sample);
  return st;
}

ReaderStats raw_tp_read(int domain, const std::string& tag) {
  RawParticipant p(domain);
  const dds::Qos qos = dds::make_qos(kQos);
  const dds_entity_t t =
      checked(dds_create_topic(p.handle, &autonomy_bench_Blob_desc, tp_topic(tag).c_str(), nullptr, nullptr), "topic");
  const dds_entity_t r = checked(dds_create_reader(p.handle, t, qos.get(), nullptr), "reader");
  const dds_entity_t rc = checked(dds_create_readcondition(r, DDS_ANY_STATE), "readcondition");
  const dds_entity_t ws = checked(dds_create_waitset(p.handle), "waitset");
  dds_waitset_attach(ws, rc, 1);
  ReaderStats st;
  Clock::time_point first{};
  int64_t last = -1;
  void* buf[kBatch];
  dds_sample_info_t info[kBatch];
  for (;;) {
    dds_attach_t x;
    if (dds_waitset_wait(ws, &x, 1, DDS_SECS(20)) == 0) throw std::runtime_error("throughput writer (raw) went silent");
    for (;;) {  // like the layer: take until a batch comes back short
      buf[0] = nullptr;
      const dds_return_t n = checked(dds_take(rc, buf, info, kBatch, kBatch), "dds_take");
      bool end = false;
      for (dds_return_t j = 0; j < n; ++j) {
        if (!info[j].valid_data) continue;
        const auto& s = *static_cast<const autonomy_bench_Blob*>(buf[j]);
        if (s.seq < 0) {
          end = true;
          break;
        }
        if (s.seq < kThroughputWarmup) continue;
        if (st.received == 0) first = Clock::now();
        else if (s.seq > last + 1) st.lost += static_cast<uint64_t>(s.seq - last - 1);
        last = s.seq;
        ++st.received;
      }
      if (n > 0) dds_return_loan(rc, buf, n);
      if (end) {
        st.seconds = std::chrono::duration<double>(Clock::now() - first).count();
        return st;
      }
      if (static_cast<size_t>(n) < kBatch) break;
    }
  }
}

template <typename T>
double layer_local(int domain, const std::string& tag, int samples, T value) {
  const std::string name = "bench/local/" + tag;
  dds::Participant p(domain);
  dds::Topic<T> topic(p, dds::TopicSpec<T>{name.c_str(), kQos});
  dds::Writer<T> writer(p, topic);
  dds::Reader<T> reader(p, topic);
  int64_t seq = 0, taken = 0;
  const auto t0 = Clock::now();
  while (seq < samples) {
    for (size_t k = 0; k < kBatch; ++k) {
      seq_of(value) = seq++;
      writer.write(value);
    }
    for (const auto& s : reader.take()) taken += s.valid ? 1 : 0;
  }
  const double ns = std::chrono::duration<double, std::nano>(Clock::now() - t0).count();
  if (taken != seq) throw std::runtime_error("local cost (layer): samples lost");
  return ns / static_cast<double>(seq);
}

template <typename C>
double raw_local(int domain, const std::string& tag, int samples, const dds_topic_descriptor_t* desc, C sample) {
  RawParticipant p(domain);
  const dds::Qos qos = dds::make_qos(kQos);
  const dds_entity_t t = checked(dds_create_topic(p.handle, desc, ("bench/local/" + tag).c_str(), nullptr, nullptr), "topic");
  const dds_entity_t w = checked(dds_create_writer(p.handle, t, qos.get(), nullptr), "writer");
  const dds_entity_t r = checked(dds_create_reader(p.handle, t, qos.get(), nullptr), "reader");
  const dds_entity_t rc = checked(dds_create_readcondition(r, DDS_ANY_STATE), "readcondition");
  void* buf[kBatch];
  dds_sample_info_t info[kBatch];
  int64_t seq = 0, taken = 0, sink = 0;
  const auto t0 = Clock::now();
  while (seq < samples) {
    for (size_t k = 0; k < kBatch; ++k) {
      seq_of(sample) = seq++;
      checked(dds_write(w, &sample), "dds_write");
    }
    for (;;) {
      buf[0] = nullptr;
      const dds_return_t n = checked(dds_take(rc, buf, info, kBatch, kBatch), "dds_take");
      for (dds_return_t j = 0; j < n; ++j)
        if (info[j].valid_data) {
          ++taken;
          sink += seq_of(*static_cast<const C*>(buf[j]));
        }
      if (n > 0) dds_return_loan(rc, buf, n);
      if (static_cast<size_t>(n) < kBatch) break;
    }
  }
  const double ns = std::chrono::duration<double, std::nano>(Clock::now() - t0).count();
  if (taken != seq || sink < 0) throw std::runtime_error("local cost (raw): samples lost");
  return ns / static_cast<double>(seq);
}

}  // namespace

double local_cost_ns(Api api, Payload payload, int domain, const std::string& tag, int samples) {
  if (api == Api::Layer)
    return payload == Payload::RobotState ? layer_local(domain, tag, samples, robot_state_value())
                                          : layer_local(domain, tag, samples, blob_value());
  return payload == Payload::RobotState
             ? raw_local(domain, tag, samples, &autonomy_RobotState_desc, robot_state_c())
             : raw_local(domain, tag, samples, &autonomy_bench_Blob_desc, blob_c());
}

const char* to_string(Api a) { return a == Api::Raw ? "raw" : "layer"; }
const char* to_string(Payload p) { return p == Payload::RobotState ? "robotstate" : "blob1k"; }
Api parse_api(const std::string& s) {
  if (s == "raw") return Api::Raw;
  if (s == "layer") return Api::Layer;
  throw std::runtime_error("unknown api " + s);
}
Payload parse_payload(const std::string& s) {
  if (s == "robotstate") return Payload::RobotState;
  if (s == "blob1k") return Payload::Blob1K;
  throw std::runtime_error("unknown payload " + s);
}

std::vector<double> ping(Api api, Payload payload, int domain, const std::string& tag, int warmup, int count) {
  if (api == Api::Layer)
    return payload == Payload::RobotState ? layer_ping(domain, tag, warmup, count, robot_state_value())
                                          : layer_ping(domain, tag, warmup, count, blob_value());
  return payload == Payload::RobotState
             ? raw_ping(domain, tag, warmup, count, &autonomy_RobotState_desc, robot_state_c())
             : raw_ping(domain, tag, warmup, count, &autonomy_bench_Blob_desc, blob_c());
}

void echo(Api api, Payload payload, int domain, const std::string& tag) {
  if (api == Api::Layer) {
    if (payload == Payload::RobotState) layer_echo<msg::RobotState>(domain, tag);
    else layer_echo<Blob>(domain, tag);
  } else {
    if (payload == Payload::RobotState) raw_echo<autonomy_RobotState>(domain, tag, &autonomy_RobotState_desc);
    else raw_echo<autonomy_bench_Blob>(domain, tag, &autonomy_bench_Blob_desc);
  }
}

WriterStats throughput_write(Api api, int domain, const std::string& tag, double seconds) {
  return api == Api::Layer ? layer_tp_write(domain, tag, seconds, blob_value()) : raw_tp_write(domain, tag, seconds);
}

ReaderStats throughput_read(Api api, int domain, const std::string& tag) {
  return api == Api::Layer ? layer_tp_read<Blob>(domain, tag) : raw_tp_read(domain, tag);
}

}  // namespace autonomy::bench
