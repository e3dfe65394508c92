// experiment_trial_host: one trial of the robot-teams experiment in one process: the simulator and
// its behavior controllers, each its own service (DDS participant, event-loop thread, heartbeat),
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

#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <functional>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

using namespace autonomy;

namespace {

// One node of the trial and the thread that runs its service.
struct Member {
  std::string name;  // "simulator/main", "behavior/r1"
  bool is_simulator = false;
  service::ServiceOptions options;
  std::function<std::shared_ptr<void>(service::Service&)> make_node;
  // Guarded by Host::mutex.
  service::Service* running = nullptr;
  bool ended = false;
  int code = 1;
};

class Host {
 public:
  // Runs every member on a thread of its own until the simulator ends (or a controller ends
  // first); returns the exit code.
  int run(std::list<Member>& members) {
    std::vector<std::thread> threads;
    for (auto& m : members) threads.emplace_back([this, &m] { run_member(m); });
    int code = 0;
    {
      std::unique_lock lock(mutex_);
      for (;;) {
        const Member* first_ended = nullptr;
        for (const auto& m : members)
          if (m.ended && !first_ended) first_ended = &m;
        if (first_ended) {
          if (first_ended->is_simulator) {
            code = first_ended->code;
          } else {
            spdlog::error("{} ended before the simulator (exit code {})", first_ended->name, first_ended->code);
            code = 1;
          }
          break;
        }
        changed_.wait(lock);
      }
      stopping_ = true;
      for (auto& m : members)
        if (m.running) m.running->stop();
    }
    for (auto& t : threads) t.join();
    for (const auto& m : members)
      if (!m.is_simulator && m.code != 0 && code == 0) {
        spdlog::error("{} failed (exit code {})", m.name, m.code);
        code = 1;
      }
    return code;
  }

 private:
  void run_member(Member& m) {
    int code = 1;
    try {
      service::Service service(m.options);
      // Detaches before the service is destroyed, so that run() never stops a service that is gone.
      struct Attachment {
        Host& host;
        Member& member;
        Attachment(Host& h, Member& mem, service::Service& s) : host(h), member(mem) {
          std::lock_guard lock(host.mutex_);
          member.running = &s;
          if (host.stopping_) s.stop();
        }
        ~Attachment() {
          std::lock_guard lock(host.mutex_);
          member.running = nullptr;
        }
      } attachment(*this, m, service);
      std::shared_ptr<void> node = m.make_node(service);
      service.run();
      node.reset();
      code = service.exit_code();
    } catch (const std::exception& e) {
      spdlog::critical("{}: cannot run: {}", m.name, e.what());
    }
    std::lock_guard lock(mutex_);
    m.ended = true;
    m.code = code;
    changed_.notify_all();
  }

  std::mutex mutex_;
  std::condition_variable changed_;
  bool stopping_ = false;
};

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
  // its own service, and the host then stops the rest).
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
  try {
    if (!members.empty()) host_options.log_level = members.front().options.log_level;
    const std::string log_file = service::setup_logging(host_options);
    spdlog::info("trial {}: {} nodes in one process, log file {}", host_options.instance, members.size(), log_file);
    Host host;
    const int code = host.run(members);
    spdlog::info("stopped (exit code {})", code);
    return code;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "experiment_trial_host: %s\n", e.what());
    return 1;
  }
}
