// EventLoop::on_samples_at_arrival (common/service/event_loop.hpp): handlers run in the thread
// that delivers the sample, one at a time with the loop's other handlers, and fall back to the
// loop's thread when they cannot. Within one process Cyclone delivers in the writing thread, which
// stands in for the receive thread here. Domains 121-124, one per test.
#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"
#include "common/service/event_loop.hpp"
#include "common/test/test_support.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace autonomy::service {
namespace {

using namespace std::chrono_literals;
using Steady = std::chrono::steady_clock;

class EventLoopArrivalTest : public ::testing::Test {
 protected:
  void SetUp() override { test::use_loopback_profile(); }
};

// Waits (bounded) until done() holds; the loop runs in another thread.
template <typename Done>
bool wait_until(Done done) {
  const auto deadline = Steady::now() + 5s;
  while (!done() && Steady::now() < deadline) std::this_thread::sleep_for(1ms);
  return done();
}

msg::TickAck ack(int64_t tick) { return msg::TickAck{"p", tick, 0, 0}; }

// A participant with a matched reader and writer of tick acks.
struct Acks {
  explicit Acks(uint32_t domain) : p(domain), topic(p, dds::topics::tick_ack), reader(p, topic), writer(p, topic) {}
  dds::Participant p;
  dds::Topic<msg::TickAck> topic;
  dds::Reader<msg::TickAck> reader;
  dds::Writer<msg::TickAck> writer;
};

TEST_F(EventLoopArrivalTest, HandlersRunInTheDeliveringThreadNeverBesideAnother) {
  Acks acks(121);
  auto& [p, topic, reader, writer] = acks;
  ASSERT_TRUE(writer.wait_for_readers(1, 2s));

  EventLoop loop(p);
  loop.allow_handling_at_arrival();
  std::atomic<int> inside{0};
  std::atomic<bool> overlapped{false};
  std::atomic<bool> started{false};
  std::atomic<size_t> count{0};
  std::vector<int64_t> ticks;                  // written by handlers only, read after join
  std::vector<std::thread::id> handler_threads;
  std::vector<bool> said_receive_thread;  // in_receive_thread() in each handler run
  const auto enter = [&] {
    if (inside.fetch_add(1) != 0) overlapped = true;
  };
  loop.on_samples_at_arrival<msg::TickAck>(reader, [&](std::vector<dds::Sample<msg::TickAck>> samples) {
    enter();
    handler_threads.push_back(std::this_thread::get_id());
    said_receive_thread.push_back(loop.in_receive_thread());
    for (const auto& s : samples) ticks.push_back(s.value.tick);
    count = ticks.size();
    inside.fetch_sub(1);
  });
  // A timer, so that some samples arrive while the loop's thread holds the lock.
  loop.every(2ms, [&] {
    enter();
    started = true;
    std::this_thread::sleep_for(200us);
    inside.fetch_sub(1);
  });
  std::thread loop_thread([&] { loop.run(); });
  const std::thread::id loop_id = loop_thread.get_id();
  ASSERT_TRUE(wait_until([&] { return started.load(); }));

  constexpr int64_t kSamples = 200;
  bool all = true;
  for (int64_t t = 1; t <= kSamples && all; ++t) {  // one at a time: most find the lock free
    writer.write(ack(t));
    all = wait_until([&] { return count.load() == static_cast<size_t>(t); });
  }
  loop.stop();
  loop_thread.join();

  ASSERT_TRUE(all) << count.load() << " of " << kSamples;
  for (int64_t t = 1; t <= kSamples; ++t) EXPECT_EQ(ticks[static_cast<size_t>(t - 1)], t);  // each once, in order
  EXPECT_FALSE(overlapped.load());
  int in_writer = 0;
  for (size_t i = 0; i < handler_threads.size(); ++i) {
    const auto& id = handler_threads[i];
    EXPECT_TRUE(id == std::this_thread::get_id() || id == loop_id);
    EXPECT_EQ(said_receive_thread[i], id != loop_id);
    in_writer += id == std::this_thread::get_id();
  }
  EXPECT_GT(in_writer, 0) << "no sample was handled in the thread that delivered it";
}

TEST_F(EventLoopArrivalTest, NotAllowedTheHandlerRunsOnTheLoopsThread) {
  Acks acks(122);
  auto& [p, topic, reader, writer] = acks;
  ASSERT_TRUE(writer.wait_for_readers(1, 2s));

  EventLoop loop(p);  // as in a host that runs several loops on one thread
  std::vector<int64_t> ticks;
  std::vector<std::thread::id> handler_threads;
  loop.on_samples_at_arrival<msg::TickAck>(reader, [&](std::vector<dds::Sample<msg::TickAck>> samples) {
    handler_threads.push_back(std::this_thread::get_id());
    EXPECT_FALSE(loop.in_receive_thread());
    for (const auto& s : samples) ticks.push_back(s.value.tick);
  });
  writer.write(ack(1));
  writer.write(ack(2));
  EXPECT_TRUE(ticks.empty()) << "handled at the write";
  const auto deadline = Steady::now() + 2s;
  while (ticks.size() < 2 && Steady::now() < deadline) loop.run_once(100ms);
  EXPECT_EQ(ticks, (std::vector<int64_t>{1, 2}));
  for (const auto& id : handler_threads) EXPECT_EQ(id, std::this_thread::get_id());
}

// A handler's own write, delivered to a reader of the same loop in the same thread, is handled
// after that handler returns (by the loop's thread), not inside it.
TEST_F(EventLoopArrivalTest, WhatAHandlerWritesToItsOwnLoopIsHandledAfterIt) {
  Acks acks(123);
  auto& [p, ack_topic, ack_reader, ack_writer] = acks;
  dds::Topic<msg::SimClock> clock_topic(p, dds::topics::clock);
  dds::Reader<msg::SimClock> clock_reader(p, clock_topic);
  dds::Writer<msg::SimClock> clock_writer(p, clock_topic);
  ASSERT_TRUE(ack_writer.wait_for_readers(1, 2s));
  ASSERT_TRUE(clock_writer.wait_for_readers(1, 2s));

  EventLoop loop(p);
  loop.allow_handling_at_arrival();
  std::vector<std::string> events;  // handlers only; read after join
  std::atomic<int> clocks{0};
  loop.on_samples_at_arrival<msg::TickAck>(ack_reader, [&](std::vector<dds::Sample<msg::TickAck>> samples) {
    for (const auto& s : samples) {
      events.push_back("ack " + std::to_string(s.value.tick) + " begins");
      msg::SimClock c{};
      c.tick = s.value.tick;
      c.world_id = 1;
      clock_writer.write(c);
      events.push_back("ack " + std::to_string(s.value.tick) + " ends");
    }
  });
  loop.on_samples_at_arrival<msg::SimClock>(clock_reader, [&](std::vector<dds::Sample<msg::SimClock>> samples) {
    for (const auto& s : samples) events.push_back("clock " + std::to_string(s.value.tick));
    clocks += static_cast<int>(samples.size());
  });
  std::thread loop_thread([&] { loop.run(); });
  std::this_thread::sleep_for(20ms);  // run() is on
  ack_writer.write(ack(7));
  const bool handled = wait_until([&] { return clocks.load() == 1; });
  loop.stop();
  loop_thread.join();
  ASSERT_TRUE(handled);
  EXPECT_EQ(events, (std::vector<std::string>{"ack 7 begins", "ack 7 ends", "clock 7"}));
}

TEST_F(EventLoopArrivalTest, AHandlerThatThrowsInTheDeliveringThreadEndsRunWithItsError) {
  Acks acks(124);
  auto& [p, topic, reader, writer] = acks;
  ASSERT_TRUE(writer.wait_for_readers(1, 2s));

  EventLoop loop(p);
  loop.allow_handling_at_arrival();
  loop.on_samples_at_arrival<msg::TickAck>(reader, [&](std::vector<dds::Sample<msg::TickAck>> samples) {
    throw std::runtime_error("bad ack " + std::to_string(samples.front().value.tick));
  });
  std::string error;
  std::thread loop_thread([&] {
    try {
      loop.run();
    } catch (const std::exception& e) {
      error = e.what();
    }
  });
  std::this_thread::sleep_for(20ms);
  writer.write(ack(3));
  loop_thread.join();  // run() ends without stop()
  EXPECT_EQ(error, "bad ack 3");
  EXPECT_TRUE(loop.stopped());
}

}  // namespace
}  // namespace autonomy::service
