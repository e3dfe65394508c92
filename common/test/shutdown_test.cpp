// SIGINT/SIGTERM to a callback on the signal thread (common/service/shutdown.hpp). This binary
// starts no DDS: every thread of the process must block the signals for the test to be valid.
#include "common/service/shutdown.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <mutex>
#include <thread>
#include <unistd.h>

namespace autonomy::service {
namespace {

bool eventually(const std::function<bool()>& pred) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  while (!pred()) {
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

struct Recorder {
  std::atomic<int> calls{0};
  std::atomic<int> signal{0};
  std::mutex mutex;
  std::thread::id thread;

  std::function<void(int)> callback() {
    return [this](int sig) {
      {
        std::lock_guard lock(mutex);
        thread = std::this_thread::get_id();
      }
      signal = sig;
      ++calls;
    };
  }
  std::thread::id caller() {
    std::lock_guard lock(mutex);
    return thread;
  }
};

TEST(ShutdownSignalsTest, SigintCallsTheCallbackOnceOnAnotherThread) {
  Recorder rec;
  ShutdownSignals signals;
  signals.on_shutdown(rec.callback());
  EXPECT_FALSE(signals.requested());

  ASSERT_EQ(::kill(::getpid(), SIGINT), 0);
  ASSERT_TRUE(eventually([&] { return rec.calls.load() == 1; }));
  EXPECT_EQ(rec.signal.load(), SIGINT);
  EXPECT_TRUE(signals.requested());
  EXPECT_NE(rec.caller(), std::this_thread::get_id());

  // A second signal (an impatient ^C) is swallowed: no second call, and the process lives on.
  ASSERT_EQ(::kill(::getpid(), SIGINT), 0);
  ASSERT_EQ(::kill(::getpid(), SIGTERM), 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_EQ(rec.calls.load(), 1);
}

TEST(ShutdownSignalsTest, SigtermIsAShutdownSignalToo) {
  Recorder rec;
  ShutdownSignals signals;
  signals.on_shutdown(rec.callback());
  ASSERT_EQ(::kill(::getpid(), SIGTERM), 0);
  ASSERT_TRUE(eventually([&] { return rec.calls.load() == 1; }));
  EXPECT_EQ(rec.signal.load(), SIGTERM);
  EXPECT_TRUE(signals.requested());
}

TEST(ShutdownSignalsTest, SignalBeforeTheCallbackIsDeliveredWhenItIsSet) {
  Recorder rec;
  ShutdownSignals signals;
  ASSERT_EQ(::kill(::getpid(), SIGINT), 0);
  ASSERT_TRUE(eventually([&] { return signals.requested(); }));
  EXPECT_EQ(rec.calls.load(), 0);
  signals.on_shutdown(rec.callback());
  EXPECT_EQ(rec.calls.load(), 1);
  EXPECT_EQ(rec.signal.load(), SIGINT);
}

TEST(ShutdownSignalsTest, DestructionWithoutSignalCallsNothing) {
  Recorder rec;
  {
    ShutdownSignals signals;
    signals.on_shutdown(rec.callback());
    EXPECT_FALSE(signals.requested());
  }  // the destructor wakes its thread with a SIGTERM of its own, which must not be reported
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(rec.calls.load(), 0);
}

TEST(ShutdownSignalsTest, SignalsStayBlockedInTheConstructingThread) {
  ShutdownSignals signals;
  sigset_t mask;
  ASSERT_EQ(pthread_sigmask(SIG_BLOCK, nullptr, &mask), 0);
  EXPECT_TRUE(sigismember(&mask, SIGINT));
  EXPECT_TRUE(sigismember(&mask, SIGTERM));
}

}  // namespace
}  // namespace autonomy::service
