#pragma once
// The fixture of integration tests: one DDS domain and one folder per test, this test's own
// observer participant, and the project's programs started as child processes that are killed
// and reaped at the end whatever happens (their output tails are printed when the test failed).
// Needs AUTONOMY_SOURCE_DIR, AUTONOMY_SIMULATOR_BIN and AUTONOMY_BEHAVIOR_BIN from CMake.
#include "tests/support/test_dir.hpp"
#include "tests/support/dds_observer.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <list>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace autonomy::test {

// The Cyclone configuration every child and the observer use: loopback, unicast discovery.
inline std::string dds_uri() { return std::string("file://") + AUTONOMY_SOURCE_DIR + "/deploy/dds/loopback.xml"; }

inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Writes a file the test hands to a process (scenario, mission); a failed write fails the test.
inline void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  ASSERT_TRUE(out.good()) << "cannot write " << path;
}

class ProcessTest : public ::testing::Test {
 protected:
  // Every test begins with this: its own domain, its own folder, the observer participant.
  void join(int domain) {
    domain_ = domain;
    // The observer must use the same Cyclone configuration as the children.
    ASSERT_EQ(setenv("CYCLONEDDS_URI", uri().c_str(), 1), 0);
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::make_unique<TestDir>(std::string(info->test_suite_name()) + "." + info->name());
    participant_.emplace(domain);
  }

  void TearDown() override {
    if (HasFailure()) {
      for (auto& c : children_) {
        if (c.child->running())
          std::fprintf(stderr, "%s was still running\n", c.child->name().c_str());
        else if (c.child->status())
          std::fprintf(stderr, "%s ended: %s\n", c.child->name().c_str(), c.child->status()->describe().c_str());
        std::fprintf(stderr, "%s\n", c.child->log_tail().c_str());
      }
    }
    children_.clear();  // SIGKILL and reap whatever is left, before the participant goes
    participant_.reset();
    dir_.reset();
  }

  const dds::Participant& participant() const { return *participant_; }
  const TestDir& dir() const { return *dir_; }

  // must_keep_running: await() fails at once when this child ends while it waits.
  // args must name the domain themselves (`--domain`, where the program expects it).
  ChildProcess& start(const std::string& name, const std::string& program, std::vector<std::string> args,
                      bool must_keep_running = true, bool separate_stderr = false) {
    const std::map<std::string, std::string> env = {{"CYCLONEDDS_URI", uri()},
                                                    {"AUTONOMY_LOG_DIR", dir_->path()}};
    if (const auto at = placement_.find(name); at != placement_.end()) {
      // On another host: the same program inside that host's network namespace, naming the host
      // (a namespace keeps the machine's hostname) and its link for the hosts profile.
      args.insert(args.begin(), {"netns", "exec", at->second.first, "env", "AUTONOMY_HOST=" + at->second.second,
                                 "AUTONOMY_DDS_INTERFACE=hnet0", program});
      return start_child(name, ip_program(), std::move(args), env, must_keep_running, separate_stderr);
    }
    return start_child(name, program, std::move(args), env, must_keep_running, separate_stderr);
  }
  // Several hosts (tests/integration/hosts_test.cpp): the child of this name runs in network
  // namespace `ns` as host `host`; the children and the observer use `uri` instead of loopback.
  void place(const std::string& name, const std::string& ns, const std::string& host) { placement_[name] = {ns, host}; }
  void use_uri(std::string uri) { uri_ = std::move(uri); }
  std::string uri() const { return uri_.empty() ? dds_uri() : uri_; }
  static std::string ip_program() {
    for (const char* path : {"/usr/sbin/ip", "/sbin/ip", "/usr/bin/ip", "/bin/ip"})
      if (::access(path, X_OK) == 0) return path;
    return "/usr/sbin/ip";
  }

 private:
  ChildProcess& start_child(const std::string& name, const std::string& program, std::vector<std::string> args,
                            const std::map<std::string, std::string>& env, bool must_keep_running,
                            bool separate_stderr) {
    // <name>.out: the child's stdout (and stderr unless separate); services also write their own
    // log file (<service>-<instance>.log) into the same folder through --log-dir.
    const std::string log = dir_->file(name + ".out");
    children_.push_back(
        {std::make_unique<ChildProcess>(name, program, args, env, log, separate_stderr ? dir_->file(name + ".err") : ""),
         must_keep_running});
    return *children_.back().child;
  }

 protected:
  ChildProcess& start_simulator(std::vector<std::string> args = {}, bool must_keep_running = true,
                                const std::string& name = "simulator") {
    // Each test has its own domain, so the simulator's 1 s listen for another world only delays
    // the start: off unless the test passes --world-check (world_identity_test tests the check).
    if (std::find(args.begin(), args.end(), "--world-check") == args.end())
      args.insert(args.end(), {"--world-check", "0"});
    args.insert(args.end(), {"--domain", std::to_string(domain_), "--log-dir", dir_->path()});
    return start(name, AUTONOMY_SIMULATOR_BIN, args, must_keep_running);
  }
  ChildProcess& start_behavior(const std::string& robot, std::vector<std::string> args = {},
                               bool must_keep_running = true, std::string name = "") {
    args.insert(args.begin(), {"--robot", robot});
    args.insert(args.end(), {"--domain", std::to_string(domain_), "--log-dir", dir_->path()});
    if (name.empty()) name = "behavior-" + robot;
    return start(name, AUTONOMY_BEHAVIOR_BIN, args, must_keep_running);
  }
  void stop_watching(const ChildProcess& child) {
    for (auto& c : children_)
      if (c.child.get() == &child) c.must_keep_running = false;
  }

  // eventually(), and fails at once when a child that must keep running has ended.
  ::testing::AssertionResult await(const std::string& what, const std::function<bool()>& condition,
                                   std::chrono::milliseconds timeout = kDeadline) {
    std::string died;
    auto result = eventually(
        what,
        [&] {
          for (auto& c : children_) {
            if (c.must_keep_running && !c.child->running()) {
              died = c.child->name() + " ended (" + c.child->status()->describe() + ")";
              return true;
            }
          }
          return condition();
        },
        timeout);
    if (!died.empty()) return ::testing::AssertionFailure() << died << " while waiting for: " << what;
    return result;
  }

  // The heartbeat of the process with this pid says Ready.
  ::testing::AssertionResult await_ready(Recorder<msg::Heartbeat>& beats, const ChildProcess& child) {
    const pid_t pid = child.pid();
    return await(child.name() + " (pid " + std::to_string(pid) + ") heartbeat state ready", [&] {
      beats.poll();
      return !beats.matching([&](const msg::Heartbeat& h) { return h.pid == pid && h.state == msg::ServiceState::Ready; })
                  .empty();
    });
  }

  int domain_ = 0;

 private:
  std::map<std::string, std::pair<std::string, std::string>> placement_;  // child name -> (namespace, host)
  std::string uri_;
  struct Child {
    std::unique_ptr<ChildProcess> child;
    bool must_keep_running;
  };
  std::unique_ptr<TestDir> dir_;
  std::optional<dds::Participant> participant_;
  std::list<Child> children_;  // destroyed (killed) in TearDown, before the participant
};

}  // namespace autonomy::test
