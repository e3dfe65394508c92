#include "common/service/shutdown.hpp"

#include <csignal>
#include <stdexcept>

namespace autonomy::service {

namespace {
sigset_t shutdown_set() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}
}  // namespace

ShutdownSignals::ShutdownSignals() {
  const sigset_t set = shutdown_set();
  if (pthread_sigmask(SIG_BLOCK, &set, nullptr) != 0) throw std::runtime_error("pthread_sigmask failed");
  thread_ = std::thread([this] { wait_for_signal(); });
}

ShutdownSignals::~ShutdownSignals() {
  closing_ = true;
  // Wake the sigwait with a signal aimed at that thread only; closing_ tells it not to report.
  pthread_kill(thread_.native_handle(), SIGTERM);
  thread_.join();
}

void ShutdownSignals::on_shutdown(std::function<void(int)> callback) {
  std::lock_guard lock(mutex_);
  callback_ = std::move(callback);
  if (pending_signal_ != 0 && callback_) callback_(pending_signal_);
}

void ShutdownSignals::wait_for_signal() {
  const sigset_t set = shutdown_set();
  for (;;) {
    int sig = 0;
    if (sigwait(&set, &sig) != 0) continue;
    if (closing_) return;
    if (requested_.exchange(true)) continue;
    std::lock_guard lock(mutex_);
    if (callback_)
      callback_(sig);
    else
      pending_signal_ = sig;
  }
}

}  // namespace autonomy::service
