#pragma once
// A child process of a tool or a test: started with fork/exec with its own arguments and extra
// environment, stdout and stderr into one log file. The destructor SIGKILLs and reaps a child that
// is still running, so an error (or a failed assertion) leaves no orphan; the child also gets
// SIGKILL when its parent dies (PR_SET_PDEATHSIG), e.g. when ctest kills a test at its timeout.
#include <sys/types.h>

#include <chrono>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::process {

// How a child ended: exit code, or the signal that killed it.
struct ExitStatus {
  bool exited = false;  // true: ended with exit(code); false: killed by `signal`
  int code = 0;
  int signal = 0;
  std::string describe() const;
};

class ChildProcess {
 public:
  // Starts `program` with `args` (argv[1..]); `env` entries are added to (or override) this process's
  // environment. stdout goes to `log_file`, stderr too unless `stderr_file` names another file.
  // Throws std::runtime_error when the program cannot be started.
  ChildProcess(std::string name, const std::string& program, const std::vector<std::string>& args,
               const std::map<std::string, std::string>& env, const std::string& log_file,
               const std::string& stderr_file = "");
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  pid_t pid() const { return pid_; }
  const std::string& name() const { return name_; }
  const std::string& log_file() const { return log_file_; }

  // Sends a signal (no-op when the child was already reaped).
  void signal(int sig);
  // True while the child has not ended (reaps it when it has).
  bool running();
  // Waits at most `timeout` for the child to end; nullopt when it is still running.
  std::optional<ExitStatus> wait_for_exit(std::chrono::milliseconds timeout);
  // SIGKILL and reap; returns how it ended (a child that ended before keeps its own status).
  ExitStatus kill_and_wait();
  // The exit status once reaped.
  const std::optional<ExitStatus>& status() const { return status_; }
  // The last `max_bytes` of the log file, for failure messages.
  std::string log_tail(std::size_t max_bytes = 4000) const;
  const std::string& stderr_file() const { return stderr_file_; }

 private:
  bool try_reap();

  std::string name_;
  std::string log_file_;
  std::string stderr_file_;
  pid_t pid_ = -1;
  std::optional<ExitStatus> status_;
};

}  // namespace autonomy::process
