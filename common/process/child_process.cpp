#include "common/process/child_process.hpp"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

namespace autonomy::process {

std::string ExitStatus::describe() const {
  if (exited) return "exit code " + std::to_string(code);
  return "killed by signal " + std::to_string(signal) + " (" + strsignal(signal) + ")";
}

ChildProcess::ChildProcess(std::string name, const std::string& program, const std::vector<std::string>& args,
                           const std::map<std::string, std::string>& env, const std::string& log_file,
                           const std::string& stderr_file)
    : name_(std::move(name)), log_file_(log_file), stderr_file_(stderr_file.empty() ? log_file : stderr_file) {
  // Everything the child needs is prepared before fork: between fork and exec only
  // async-signal-safe calls are allowed (the parent may run Cyclone's threads).
  std::vector<std::string> argv_store;
  argv_store.push_back(program);
  argv_store.insert(argv_store.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_store) argv.push_back(a.data());
  argv.push_back(nullptr);

  std::map<std::string, std::string> merged;
  for (char** e = environ; e && *e; ++e) {
    const std::string entry(*e);
    const auto eq = entry.find('=');
    if (eq != std::string::npos) merged[entry.substr(0, eq)] = entry.substr(eq + 1);
  }
  for (const auto& [k, v] : env) merged[k] = v;
  std::vector<std::string> env_store;
  for (const auto& [k, v] : merged) env_store.push_back(k + "=" + v);
  std::vector<char*> envp;
  for (auto& e : env_store) envp.push_back(e.data());
  envp.push_back(nullptr);

  const int fd = ::open(log_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error("cannot open log file " + log_file + ": " + std::strerror(errno));
  int err_fd = fd;
  if (stderr_file_ != log_file_) {
    err_fd = ::open(stderr_file_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (err_fd < 0) {
      ::close(fd);
      throw std::runtime_error("cannot open log file " + stderr_file_ + ": " + std::strerror(errno));
    }
  }
  const int devnull = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  const pid_t parent = ::getpid();

  const pid_t pid = ::fork();
  if (pid < 0) {
    const int err = errno;
    ::close(fd);
    if (err_fd != fd) ::close(err_fd);
    if (devnull >= 0) ::close(devnull);
    throw std::runtime_error("fork failed: " + std::string(std::strerror(err)));
  }
  if (pid == 0) {
    // Child. Die with the parent; undo the signal mask and dispositions it may have set.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    for (int sig : {SIGINT, SIGTERM, SIGPIPE, SIGCHLD, SIGHUP}) ::signal(sig, SIG_DFL);
    ::setpgid(0, 0);  // not in the terminal's group: a Ctrl-C reaches the parent only, which decides
    if (devnull >= 0) ::dup2(devnull, STDIN_FILENO);
    ::dup2(fd, STDOUT_FILENO);
    ::dup2(err_fd, STDERR_FILENO);
    ::execve(argv[0], argv.data(), envp.data());
    static const char msg[] = "exec failed\n";
    (void)!::write(STDERR_FILENO, msg, sizeof msg - 1);
    ::_exit(127);
  }
  ::close(fd);
  if (err_fd != fd) ::close(err_fd);
  if (devnull >= 0) ::close(devnull);
  pid_ = pid;
}

ChildProcess::~ChildProcess() {
  if (pid_ > 0 && !status_) kill_and_wait();
}

bool ChildProcess::try_reap() {
  if (status_ || pid_ <= 0) return true;
  int st = 0;
  const pid_t r = ::waitpid(pid_, &st, WNOHANG);
  if (r == 0) return false;
  ExitStatus s;
  if (r < 0) {  // not our child any more (should not happen): treat as gone
    s.exited = true;
    s.code = -1;
  } else if (WIFEXITED(st)) {
    s.exited = true;
    s.code = WEXITSTATUS(st);
  } else if (WIFSIGNALED(st)) {
    s.signal = WTERMSIG(st);
  } else {
    return false;  // stopped/continued: still there
  }
  status_ = s;
  return true;
}

void ChildProcess::signal(int sig) {
  if (pid_ > 0 && !try_reap()) ::kill(pid_, sig);
}

bool ChildProcess::running() { return !try_reap(); }

std::optional<ExitStatus> ChildProcess::wait_for_exit(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!try_reap()) {
    if (std::chrono::steady_clock::now() >= deadline) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return status_;
}

ExitStatus ChildProcess::kill_and_wait() {
  if (!try_reap()) {
    ::kill(pid_, SIGKILL);
    int st = 0;
    pid_t r;
    do {
      r = ::waitpid(pid_, &st, 0);
    } while (r < 0 && errno == EINTR);
    ExitStatus s;
    if (r > 0 && WIFEXITED(st)) {
      s.exited = true;
      s.code = WEXITSTATUS(st);
    } else if (r > 0 && WIFSIGNALED(st)) {
      s.signal = WTERMSIG(st);
    } else {
      s.exited = true;
      s.code = -1;
    }
    status_ = s;
  }
  return *status_;
}

std::string ChildProcess::log_tail(std::size_t max_bytes) const {
  auto tail = [max_bytes](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    std::string text = ss.str();
    if (text.size() > max_bytes) text = "..." + text.substr(text.size() - max_bytes);
    return text;
  };
  std::string out = "---- " + name_ + " (" + log_file_ + ") ----\n" + tail(log_file_);
  if (stderr_file_ != log_file_) out += "\n---- " + name_ + " stderr (" + stderr_file_ + ") ----\n" + tail(stderr_file_);
  return out;
}

}  // namespace autonomy::process
