// experiment_trial_host: one trial of the robot-teams experiment in one process: the simulator and
// its behavior controllers, each its own service (DDS participant, event loop, heartbeat),
// built from the same flags and node code as the simulator and behavior programs, on one domain.
// Cyclone DDS hands samples between participants of one process without the network: a trial's
// lockstep round trips were two thirds kernel time (UDP on loopback, the receive threads'
// wake-ups) when each node was a process of its own, 1.3-1.6 CPU-seconds per trial.
//
//   experiment_trial_host --log-dir DIR --name NAME +simulator SIMULATOR-FLAGS...
//                         +behavior BEHAVIOR-FLAGS... [+behavior BEHAVIOR-FLAGS...]
//
// Ends when the simulator's service ends (its --max-ticks or --stop-when-finished), then stops the
// controllers. Exit code: the simulator's; 1 when a controller ended first or failed, 2 on bad
// arguments. Every node logs to DIR/trial-NAME.log (one logger per process: spdlog's default).
#include "common/service/logging.hpp"
#include "common/service/service.hpp"
#include "services/behavior/behavior_cli.hpp"
#include "simulator/simulator_cli.hpp"

#include <CLI/CLI.hpp>

#include <pthread.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <functional>
#include <list>
#include <memory>
#include <string>
#include <vector>

using namespace autonomy;

namespace {

// One node of the trial: its flags, then its service and node once built.
struct Member {
  std::string name;  // "simulator/main", "behavior/r1"
  bool is_simulator = false;
  service::ServiceOptions options;
  std::function<std::shared_ptr<void>(service::Service&)> make_node;
  std::unique_ptr<service::Service> service;
  std::shared_ptr<void> node;
};

// Builds every member's service and node (the simulator first, as the runner starts its process
// first), then runs their event loops in turn on this one thread until the simulator's ends. One
// thread: a sample written in a handler lands in the reader's cache at once (Cyclone delivers
// within a process synchronously) and is handled in the same round, with no thread to wake; with
// a thread per node, the wake-ups (futex, scheduler) cost more than the nodes' work. The run is
// the same either way: a lockstep node acts on a tick only after draining everything sent for it.
// Returns the exit code: the simulator's, 1 when a node could not start, failed or a controller
// ended first.
int run_members(std::list<Member>& members) {
  for (auto& m : members) {
    try {
      m.service = std::make_unique<service::Service>(m.options);
      m.node = m.make_node(*m.service);
    } catch (const std::exception& e) {
      spdlog::critical("{}: cannot run: {}", m.name, e.what());
      return 1;
    }
  }
  Member& simulator = members.front();
  int code = 0;
  try {
    for (;;) {
      bool busy = false;
      for (auto& m : members)
        if (!m.service->loop().stopped()) busy = m.service->loop().run_once(std::chrono::nanoseconds(0)) || busy;
      if (simulator.service->loop().stopped()) {
        code = simulator.service->exit_code();
        break;
      }
      const auto ended = std::find_if(members.begin(), members.end(),
                                      [](const Member& m) { return m.service->loop().stopped(); });
      if (ended != members.end()) {
        spdlog::error("{} ended before the simulator (exit code {})", ended->name, ended->service->exit_code());
        code = 1;
        break;
      }
      // Nothing was ready in any loop: only a timer or something from outside the process (a
      // signal's stop) can start the next round. The simulator's waitset wakes on the latter.
      if (!busy) simulator.service->loop().run_once(std::chrono::milliseconds(1));
    }
  } catch (const std::exception& e) {
    spdlog::critical("a handler failed: {}", e.what());
    code = 1;
  }
  // The simulator's node and participant go first, as its process ended before the controllers
  // were stopped.
  for (auto& m : members) {
    m.service->heartbeat().set_state(msg::ServiceState::Stopping);
    m.node.reset();
    if (!m.is_simulator && m.service->exit_code() != 0 && code == 0) {
      spdlog::error("{} failed (exit code {})", m.name, m.service->exit_code());
      code = 1;
    }
    m.service.reset();
  }
  return code;
}

// argv split at the "+simulator" / "+behavior" markers; the part before the first is the host's.
struct Groups {
  std::vector<std::string> host;
  std::vector<std::pair<std::string, std::vector<std::string>>> nodes;  // marker, its flags
};

Groups split_groups(int argc, char** argv) {
  Groups g;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "+simulator" || a == "+behavior")
      g.nodes.push_back({a.substr(1), {}});
    else if (g.nodes.empty())
      g.host.push_back(a);
    else
      g.nodes.back().second.push_back(a);
  }
  return g;
}

// Parses one group's flags as its program would (CLI11 wants argv with the program name first).
void parse(CLI::App& app, const std::string& program, const std::vector<std::string>& flags) {
  std::vector<const char*> args = {program.c_str()};
  for (const auto& f : flags) args.push_back(f.c_str());
  app.parse(static_cast<int>(args.size()), args.data());
}

}  // namespace

int main(int argc, char** argv) {
  // Before any thread starts: SIGINT/SIGTERM reach only the services' signal threads (each stops
  // its own service, and the host then ends the trial).
  sigset_t shutdown;
  sigemptyset(&shutdown);
  sigaddset(&shutdown, SIGINT);
  sigaddset(&shutdown, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &shutdown, nullptr);

  const Groups groups = split_groups(argc, argv);
  service::ServiceOptions host_options;
  host_options.service = "trial";
  host_options.log_dir = service::default_log_dir();
  CLI::App host_app{"Runs one trial of the robot-teams experiment (a simulator and its behavior controllers) in one "
                    "process; node flags follow +simulator and each +behavior",
                    "experiment_trial_host"};
  host_app.add_option("--log-dir", host_options.log_dir, "Folder for the trial's log file")->capture_default_str();
  host_app.add_option("--name", host_options.instance, "The trial's name: the log file is trial-NAME.log")->required();

  // The CLI objects hold the parsed flags until the nodes are built: one per member, never moved.
  std::list<sim::SimulatorCli> simulator_clis;
  std::list<behavior::BehaviorCli> behavior_clis;
  std::list<Member> members;
  try {
    parse(host_app, "experiment_trial_host", groups.host);
    for (const auto& [program, flags] : groups.nodes) {
      Member m;
      m.options.service = program;
      const bool is_simulator = program == "simulator";
      CLI::App app{is_simulator ? sim::kSimulatorDescription : behavior::kBehaviorDescription, program};
      service::add_service_options(app, m.options,
                                   is_simulator ? service::InstanceFlag::Instance : service::InstanceFlag::Robot);
      if (is_simulator) {
        auto& cli = simulator_clis.emplace_back();
        cli.add_options(app);
        m.make_node = [&cli](service::Service& s) -> std::shared_ptr<void> { return cli.make_node(s); };
      } else {
        auto& cli = behavior_clis.emplace_back();
        cli.add_options(app);
        m.make_node = [&cli](service::Service& s) -> std::shared_ptr<void> { return cli.make_node(s); };
      }
      try {
        parse(app, program, flags);
      } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help of one node's flags
        std::fprintf(stderr, "experiment_trial_host: +%s: %s\n", program.c_str(), e.what());
        return 2;
      }
      m.is_simulator = is_simulator;
      m.name = program + "/" + m.options.instance;
      members.push_back(std::move(m));
    }
  } catch (const CLI::ParseError& e) {
    return host_app.exit(e);  // the host's own flags
  }
  if (simulator_clis.size() != 1 || behavior_clis.empty()) {
    std::fprintf(stderr, "experiment_trial_host: needs one +simulator and at least one +behavior (got %zu and %zu)\n",
                 simulator_clis.size(), behavior_clis.size());
    return 2;
  }
  // The simulator first (see run_members).
  members.splice(members.begin(), members,
                 std::find_if(members.begin(), members.end(), [](const Member& m) { return m.is_simulator; }));
  try {
    if (!members.empty()) host_options.log_level = members.front().options.log_level;
    const std::string log_file = service::setup_logging(host_options);
    spdlog::info("trial {}: {} nodes in one process, log file {}", host_options.instance, members.size(), log_file);
    const int code = run_members(members);
    spdlog::info("stopped (exit code {})", code);
    return code;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "experiment_trial_host: %s\n", e.what());
    return 1;
  }
}
