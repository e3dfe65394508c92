#pragma once
// Helpers shared by the benchmarks: child processes, percentiles, progress lines.
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include <sys/types.h>

namespace autonomy::bench {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// p in [0, 100]; values need not be sorted (a copy is sorted).
double percentile(std::vector<double> values, double p);
double mean(const std::vector<double>& values);
double median(std::vector<double> values);

// A child process started with execv; its stdout can be captured through a pipe.
class ChildProcess {
 public:
  ChildProcess() = default;
  // Starts argv[0] with argv. capture_stdout: read it later with read_all_stdout().
  // log_file: when set, the child's stdout (if not captured) and stderr go to this file.
  ChildProcess(const std::vector<std::string>& argv, bool capture_stdout, const std::string& log_file = {});
  ChildProcess(ChildProcess&& o) noexcept;
  ChildProcess& operator=(ChildProcess&& o) noexcept;
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;
  ~ChildProcess();  // SIGTERM then SIGKILL if still running

  pid_t pid() const { return pid_; }
  std::string read_all_stdout();  // until EOF
  // Waits up to timeout for the child to exit; returns its exit status or -1 on timeout.
  int wait(std::chrono::milliseconds timeout);
  void terminate();  // SIGTERM, wait 3 s, SIGKILL

 private:
  pid_t pid_ = -1;
  int stdout_fd_ = -1;
};

// The path of the running executable (for re-executing it as a helper process).
std::string self_exe();
// The folder of the running executable (build/bin).
std::string self_dir();

// Prints to stderr at once (progress lines while long runs go on).
void progress(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

}  // namespace autonomy::bench
