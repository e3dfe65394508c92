// Issue 21's acceptance: service sets split across hosts. Each test makes its own hosts (network
// namespaces on a bridge, deploy/hosts.sh) with its own network name and subnet, runs the real
// processes inside them over the hosts DDS profile, with packet loss and partitions from
// nftables, and removes its hosts at the end whatever happened (RAII; a network left behind by a
// killed run is removed before the next one makes it). Needs root (CI runs as root); skipped
// otherwise.
//
//   domain  network / subnet  test
//   ------  ----------------  ------------------------------------------------------------
//    95-97  h95-h97 / 95-97   HostsCourierTest.ThePaperExampleAcrossThreeHosts/{0,10,30} % loss
//    98     h98 / 98          HostsExecutiveTest.TheDs1DayOnThreeHostsAtTwentyPercentLoss
//    99     h99 / 99          HostsTeamTest.ThreeRobotsOnThreeHostsFinishTheirMissions
//   100     h100 / 100        HostsTeamTest.ARobotHostCutOffForTenSecondsRejoinsAndTheMissionCompletes
//   101     h101 / 101        HostsLaunchTest.AServiceKilledOnARemoteHostIsRespawnedAndTheMissionCompletes
//   102     h102 / 102        HostsTeamTest.APacedWorldAcrossHostsAtTwentyPercentLossFinishesTheMissions
// (ctest names them integration.<suite>.<test>.)
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "tests/integration/courier_fixture.hpp"
#include "tests/support/executive_watch.hpp"

namespace autonomy::test {
namespace {

using namespace std::chrono_literals;

const std::string kHostsScript = std::string(AUTONOMY_SOURCE_DIR) + "/deploy/hosts.sh";

// Runs deploy/hosts.sh with these arguments; its output goes to `log`. True when it succeeded.
bool hosts_sh(const std::string& args, const std::string& log) {
  const std::string cmd = "bash " + kHostsScript + " " + args + " >>" + log + " 2>&1";
  return std::system(cmd.c_str()) == 0;
}

// One network of hosts for one test: made in the constructor, removed in the destructor (also
// when the test failed or threw). `net` and `subnet` must be unique per test so that tests run in
// parallel.
class HostNetwork {
 public:
  HostNetwork(std::string net, int subnet, std::vector<std::string> hosts, std::string log)
      : net_(std::move(net)), subnet_(subnet), hosts_(std::move(hosts)), log_(std::move(log)) {
    hosts_sh("down " + net_, log_);  // what a killed earlier run may have left
    std::string args = "up " + net_;
    for (const auto& h : hosts_) args += " " + h;
    up_ = hosts_sh(args + " --subnet " + std::to_string(subnet_), log_);
  }
  ~HostNetwork() { hosts_sh("down " + net_, log_); }
  HostNetwork(const HostNetwork&) = delete;
  HostNetwork& operator=(const HostNetwork&) = delete;

  bool up() const { return up_; }
  std::string ns(const std::string& host) const { return net_ + "-" + host; }
  const std::string& net() const { return net_; }
  // The hosts profile with every host and the bridge (this machine: the test's observer) as peers.
  std::string uri() const {
    std::string peers = "<Peer address=\"10.231." + std::to_string(subnet_) + ".254\"/>";
    for (size_t i = 0; i < hosts_.size(); ++i)
      peers += "<Peer address=\"10.231." + std::to_string(subnet_) + "." + std::to_string(i + 1) + "\"/>";
    return std::string("file://") + AUTONOMY_SOURCE_DIR + "/deploy/dds/hosts.xml,<Discovery><Peers>" + peers +
           "</Peers></Discovery>";
  }
  // Loss on what `host` sends: with every host at N %, each packet between two hosts is lost
  // with N % probability, in each direction (loss on both ends would compound to 1 - (1 - N)^2).
  bool loss(const std::string& host, int percent) {
    return hosts_sh("loss " + net_ + " " + host + " " + std::to_string(percent) + " out", log_);
  }
  bool partition(const std::string& host) { return hosts_sh("partition " + net_ + " " + host, log_); }
  bool heal(const std::string& host) { return hosts_sh("heal " + net_ + " " + host, log_); }

 private:
  std::string net_;
  int subnet_;
  std::vector<std::string> hosts_;
  std::string log_;
  bool up_ = false;
};

std::string hosts_log() { return ::testing::TempDir() + "hosts-test.log"; }

// Root is needed for namespaces; without it the test says so and is skipped.
#define NEED_ROOT()                                                                             \
  if (::geteuid() != 0) GTEST_SKIP() << "needs root (network namespaces, veth, nftables): run " \
                                        "as root, as CI does"

// A fixture whose test runs on its own hosts. The network outlives the fixture's TearDown (a
// member goes after it): the children and the observer's participant are gone before their
// links are (a participant deleted after its interface vanished waits on its sends).
template <class Base>
class OnHosts : public Base {
 protected:
  // Makes the network and points this test's observer and children at it: the observer talks
  // on the bridge, each placed child on its own host's link.
  void make_hosts(const std::string& net, int subnet, std::vector<std::string> hosts) {
    network_.emplace(net, subnet, std::move(hosts), hosts_log());
    ASSERT_TRUE(network_->up()) << "deploy/hosts.sh up failed, see " << hosts_log();
    ASSERT_EQ(setenv("AUTONOMY_DDS_INTERFACE", ("hb-" + net).c_str(), 1), 0);
    this->use_uri(network_->uri());
  }
  HostNetwork& network() { return *network_; }
  std::optional<HostNetwork> network_;
};

// 1. The courier paper's example (Fig. 5: A-120 closes, then opens) with the simulator, rhino's
// behavior and the courier each on its own host, at 0, 10 and 30 % loss on every packet between hosts (each way):
// both jobs complete with the same sequence of events as on loopback (courier_test.cpp).
class HostsCourierTest : public OnHosts<CourierTest>, public ::testing::WithParamInterface<int> {};

TEST_P(HostsCourierTest, ThePaperExampleAcrossThreeHosts) {
  NEED_ROOT();
  const int loss = GetParam();
  const int domain = loss == 0 ? 95 : loss == 10 ? 96 : 97;
  make_hosts("h" + std::to_string(domain), domain, {"world", "robot", "office"});
  for (const char* h : {"world", "robot", "office"}) ASSERT_TRUE(network().loss(h, loss));
  place("simulator", network().ns("world"), "world");
  place("behavior-rhino", network().ns("robot"), "robot");
  place("courier", network().ns("office"), "office");
  setup_observers(domain);
  start_world(office_scenario(kFig5Script));
  send_paper_commands();
  ASSERT_TRUE(both_jobs_finished("both jobs finished"));
  expect_fig5_sequence();
  // The heartbeats name the hosts the processes ran on.
  beats_->poll();
  for (const auto& [service, host] : std::vector<std::pair<std::string, std::string>>{
           {"simulator", "world"}, {"behavior", "robot"}, {"courier", "office"}})
    EXPECT_FALSE(beats_->matching([&](const msg::Heartbeat& b) { return b.service == service && b.host == host; })
                     .empty())
        << service << " never reported host " << host;
}

INSTANTIATE_TEST_SUITE_P(Loss, HostsCourierTest, ::testing::Values(0, 10, 30),
                         [](const auto& info) { return std::to_string(info.param) + "Percent"; });

// 2. The DS1 day (executive_test.cpp's flight: planner, executive, simulator in lockstep, the
// first four hours) on three hosts at 20 % loss on every packet between hosts: every goal achieved, as on loopback.
class HostsExecutiveTest : public OnHosts<ProcessTest> {};

TEST_F(HostsExecutiveTest, TheDs1DayOnThreeHostsAtTwentyPercentLoss) {
  NEED_ROOT();
  make_hosts("h98", 98, {"ground", "flight", "world"});
  for (const char* h : {"ground", "flight", "world"}) ASSERT_TRUE(network().loss(h, 20));
  place("planner", network().ns("ground"), "ground");
  place("executive", network().ns("flight"), "flight");
  place("simulator", network().ns("world"), "world");
  join(98);
  ExecutiveWatch watch(participant());
  start("planner", AUTONOMY_PLANNER_BIN, {"--domain", "98", "--log-dir", dir().path()});
  start("executive", AUTONOMY_EXECUTIVE_BIN,
        {"--config", std::string(AUTONOMY_SOURCE_DIR) + "/services/executive/examples/ds1-4h.pbtxt", "--domain", "98",
         "--log-dir", dir().path(), "--report-dir", dir().file("report")});
  start_simulator({"--config", std::string(AUTONOMY_SOURCE_DIR) + "/deploy/scenarios/ds1.pbtxt", "--wait-for",
                   "executive/main"});
  ASSERT_TRUE(await("the executive finished the four hours", [&] {
    watch.poll();
    return watch.finished();
  }, 300s)) << watch.story(false);
  const std::vector<std::string> all = sorted({"nav1_1", "nav1_2", "nav1_3", "nav1_4", "nav2_1", "nav2_2", "nav2_3",
                                               "nav2_4", "thrust1", "thrust2", "down1", "down2", "hidden1", "pass1",
                                               "hidden2", "pass2"});
  EXPECT_EQ(watch.achieved(), all) << watch.story(false);
  EXPECT_TRUE(watch.lost().empty()) << watch.story(false);
  EXPECT_TRUE(watch.events("aborted").empty()) << watch.story(false);
}

// 3 and 4. The robot-teams paper's reconnaissance with three robots on communication-sensitive
// plans in parallel (deploy/sets/recon-parallel.set's missions), the world on one host and each
// robot's behavior on its own, in lockstep until every mission finished.
class HostsTeamTest : public OnHosts<ProcessTest> {
 protected:
  // Lockstep, or paced: the world ticks on wall time (10 times faster than real time), whoever
  // hears it.
  void start_team(bool paced = false) {
    for (const char* h : {"r1", "r2", "r3"}) place("behavior-" + std::string(h), network().ns(h), h);
    place("simulator", network().ns("world"), "world");
    const std::string repo = AUTONOMY_SOURCE_DIR;
    std::vector<std::string> args = {"--config", repo + "/deploy/scenarios/recon.pbtxt", "--without-robots",
                                     "--mode", "lockstep", "--stop-when-finished", "--max-ticks", "200000",
                                     "--metrics", dir().file("metrics"), "--wait-for", "behavior/r1",
                                     "--wait-for", "behavior/r2", "--wait-for", "behavior/r3"};
    if (paced) {
      std::string scenario = read_file(repo + "/deploy/scenarios/recon.pbtxt");
      const std::string from = "mode: LOCKSTEP\n  step_s: 0.1\n";
      EXPECT_NE(scenario.find(from), std::string::npos);
      scenario.replace(scenario.find(from), from.size(), "mode: PACED\n  step_s: 0.1\n  warp: 10\n");
      // The copy lives in the test's folder: its map file by its full path.
      const std::string map = "yaml: \"recon/";
      EXPECT_NE(scenario.find(map), std::string::npos);
      scenario.replace(scenario.find(map), map.size(), "yaml: \"" + repo + "/deploy/scenarios/recon/");
      write_file(dir().file("recon-paced.pbtxt"), scenario);
      args = {"--config", dir().file("recon-paced.pbtxt"), "--without-robots", "--stop-when-finished",
              "--max-ticks", "200000", "--metrics", dir().file("metrics")};
    }
    simulator_ = &start_simulator(args, false);
    for (const auto& [robot, x] : std::vector<std::pair<std::string, std::string>>{{"r1", "40"}, {"r2", "125"},
                                                                                     {"r3", "210"}})
      start_behavior(robot, {"--mission", repo + "/deploy/missions/comm_parallel_" + robot + ".pbtxt", "--start", x,
                             "3", "--resolution", "1"},
                     false);
  }
  // Every mission finished: the simulator stopped by itself and its metrics say so.
  void expect_all_finished() {
    const auto ended = simulator_->wait_for_exit(240s);
    ASSERT_TRUE(ended.has_value()) << "the simulator did not stop within 240 s";
    EXPECT_TRUE(ended->exited && ended->code == 0) << ended->describe();
    const auto metrics = nlohmann::json::parse(read_file(dir().file("metrics.json")));
    EXPECT_TRUE(metrics.at("team").at("all_finished").get<bool>()) << metrics.at("team").dump();
    for (const auto& r : metrics.at("robots")) EXPECT_TRUE(r.at("finished").get<bool>()) << r.dump();
  }
  ChildProcess* simulator_ = nullptr;
};

TEST_F(HostsTeamTest, ThreeRobotsOnThreeHostsFinishTheirMissions) {
  NEED_ROOT();
  make_hosts("h99", 99, {"world", "r1", "r2", "r3"});
  join(99);
  start_team();
  expect_all_finished();
}

// r2's host is cut off for 10 s once the mission runs: the world drops r2 from lockstep (it names
// it in its log) and goes on; healed, r2 answers again, rejoins and finishes its mission.
TEST_F(HostsTeamTest, ARobotHostCutOffForTenSecondsRejoinsAndTheMissionCompletes) {
  NEED_ROOT();
  make_hosts("h100", 100, {"world", "r1", "r2", "r3"});
  join(100);
  Recorder<msg::SimClock> clock(participant(), dds::topics::clock);
  start_team();
  ASSERT_TRUE(await("the mission under way (tick 300)", [&] {
    for (const auto& c : clock.poll())
      if (c.tick >= 300) return true;
    return false;
  }, 120s));
  Recorder<msg::SimulatorStatus> sim_status(participant(), dds::topics::sim_status);
  ASSERT_TRUE(network().partition("r2"));
  std::this_thread::sleep_for(10s);
  ASSERT_TRUE(network().heal("r2"));
  expect_all_finished();
  // The drop and the return are published in the world's status, naming r2 and why: its
  // registration ended (the lease ran out: cut off 10 s, lease 3 s) before or after the ack
  // timeout (2 s) dropped it.
  sim_status.poll();
  ASSERT_FALSE(sim_status.all().empty());
  const auto& changes = sim_status.all().back().lockstep_changes;
  const auto drop = std::find_if(changes.begin(), changes.end(),
                                 [](const auto& c) { return c.participant == "behavior/r2" && c.dropped; });
  ASSERT_NE(drop, changes.end()) << sim_status.all().back().lockstep_changes.size() << " changes";
  EXPECT_NE(drop->reason.find("did not acknowledge tick " + std::to_string(drop->tick)), std::string::npos)
      << drop->reason;
  const auto rejoin = std::find_if(drop, changes.end(),
                                   [](const auto& c) { return c.participant == "behavior/r2" && !c.dropped; });
  ASSERT_NE(rejoin, changes.end());
  EXPECT_TRUE(rejoin->reason == "it registered again" ||
              rejoin->reason == "it acknowledged tick " + std::to_string(rejoin->tick) + " again")
      << rejoin->reason;
  EXPECT_TRUE(sim_status.all().back().lockstep_dropped.empty());
  const std::string log = read_file(dir().file("simulator.out"));
  // Cut off longer than the ack timeout (2 s) and the lease (3 s): dropped, named, then back.
  const auto dropped = log.find("participant behavior/r2 is silent");
  ASSERT_NE(dropped, std::string::npos) << log;
  // Back after the heal: by its next ack ("answered again ... rejoined") or by its registration
  // arriving again ("joined"), whichever the network delivers first.
  const bool back = log.find("participant behavior/r2 answered again", dropped) != std::string::npos ||
                    log.find("participant behavior/r2 joined lockstep", dropped) != std::string::npos;
  EXPECT_TRUE(back) << log;
}

// A paced world (ticks on wall time, 10 times faster than real time, nobody waited for) on one
// host and the three robots on theirs, at 20 % loss on every packet between hosts: clock samples,
// robot states and velocity commands are lost and retransmitted (or replaced by newer ones), and
// every mission still finishes.
TEST_F(HostsTeamTest, APacedWorldAcrossHostsAtTwentyPercentLossFinishesTheMissions) {
  NEED_ROOT();
  make_hosts("h102", 102, {"world", "r1", "r2", "r3"});
  for (const char* h : {"world", "r1", "r2", "r3"}) ASSERT_TRUE(network().loss(h, 20));
  join(102);
  start_team(true);
  expect_all_finished();
}

// 5. deploy/launch.sh --hosts with the recon-parallel set's behaviors (respawn, journal) each on
// its own robot host and the world in lockstep on a fourth. First r3's host is cut off for longer
// than the launcher's hang limit (4 s here): its behavior is alive there, so it is not respawned
// (its host's watcher hears it; this machine's only reports it cannot), and the world's drop of
// r3 from lockstep shows in the launcher's report. Then r2's behavior is killed (-9) on its host
// mid-mission, the launcher respawns it there by the set's policy, it takes its robot back and
// every mission completes.
class HostsLaunchTest : public OnHosts<ProcessTest> {
 protected:
  // The launched set, stopped whatever happens (before the network goes: a member of this class
  // is destroyed before OnHosts' network).
  struct Launched {
    std::string run_dir;
    ~Launched() {
      const std::string cmd = "bash " + std::string(AUTONOMY_SOURCE_DIR) + "/deploy/launch.sh stop " + run_dir +
                              " >>" + run_dir + "/stop.out 2>&1";
      if (std::system(cmd.c_str()) != 0) std::fprintf(stderr, "launch.sh stop %s failed\n", run_dir.c_str());
    }
  };
  std::optional<Launched> launched_;
};

TEST_F(HostsLaunchTest, AServiceKilledOnARemoteHostIsRespawnedAndTheMissionCompletes) {
  const auto trimmed = [](std::string t) {
    while (!t.empty() && (t.back() == '\n' || t.back() == ' ')) t.pop_back();
    return t;
  };
  NEED_ROOT();
  make_hosts("h101", 101, {"world", "r1", "r2", "r3"});
  join(101);
  // The shipped set's behavior lines, each on its robot's host; the world in lockstep, held at
  // the test's will (test/hold) so that the kill lands mid-mission.
  std::string set = "simulator/main@world on-exit=ignore simulator --config {repo}/deploy/scenarios/recon.pbtxt "
                    "--without-robots --mode lockstep --stop-when-finished --max-ticks 200000 --metrics "
                    "{run}/metrics --wait-for behavior/r1 --wait-for behavior/r2 --wait-for behavior/r3 "
                    "--wait-for test/hold\n";
  std::istringstream shipped(read_file(std::string(AUTONOMY_SOURCE_DIR) + "/deploy/sets/recon-parallel.set"));
  for (std::string line; std::getline(shipped, line);) {
    if (line.rfind("behavior/", 0) != 0) continue;
    const std::string name = line.substr(0, line.find(' '));
    set += name + "@" + name.substr(9) + line.substr(name.size()) + "\n";
  }
  write_file(dir().file("recon-hosts.set"), set);
  const std::string bin = std::string(AUTONOMY_SIMULATOR_BIN).substr(0, std::string(AUTONOMY_SIMULATOR_BIN).rfind('/'));
  const std::string run = dir().file("run");
  Recorder<msg::SimClock> clock(participant(), dds::topics::clock);
  dds::Topic<msg::LockstepRegistration> registration_topic(participant(), dds::topics::lockstep_registration);
  dds::Writer<msg::LockstepRegistration> registration(participant(), registration_topic);
  dds::Topic<msg::TickAck> ack_topic(participant(), dds::topics::tick_ack);
  dds::Writer<msg::TickAck> ack(participant(), ack_topic);
  registration.write({"test/hold", true});
  launched_.emplace(Launched{run});
  const std::string launch = "bash " + std::string(AUTONOMY_SOURCE_DIR) + "/deploy/launch.sh --hosts h101 --domain 101 "
                             "--hang-after 4 --run-dir " + run + " --bin " + bin + " --detach " + dir().file("recon-hosts.set") +
                             " >" + dir().file("launch.out") + " 2>&1";
  ASSERT_EQ(std::system(launch.c_str()), 0) << read_file(dir().file("launch.out"));
  // The test acknowledges every tick it sees (the world waits for it like for any participant).
  int64_t latest = -1;
  const auto step = [&] {
    for (const auto& c : clock.poll()) latest = std::max(latest, c.tick);
    if (latest >= 0) ack.write({"test/hold", latest, 0});
  };
  ASSERT_TRUE(await("the mission at tick 300", [&] {
    step();
    return latest >= 300;
  }, 120s));
  // r3's host cut off for 7 s: longer than the hang limit (4 s) and the lease (3 s).
  const std::string r3_pid = read_file(run + "/behavior-r3.pid");
  ASSERT_TRUE(network().partition("r3"));
  const auto cut_until = std::chrono::steady_clock::now() + 7s;
  while (std::chrono::steady_clock::now() < cut_until) {
    step();
    std::this_thread::sleep_for(20ms);
  }
  ASSERT_TRUE(network().heal("r3"));
  const std::string r3_hung_here = "launch: behavior/r3 (pid " + trimmed(r3_pid) + ") on r3 has not been heard on this "
                                   "machine for its hang limit";
  ASSERT_TRUE(await("the launcher to report r3 unheard here and r3 back in lockstep", [&] {
    step();
    const std::string log = read_file(run + "/launch.log");
    return log.find(r3_hung_here) != std::string::npos &&
           log.find("launch: behavior/r3 is back in lockstep at tick") != std::string::npos;
  }, 60s)) << read_file(run + "/launch.log");
  {
    const std::string log = read_file(run + "/launch.log");
    EXPECT_NE(log.find("launch: the simulator dropped behavior/r3 from lockstep at tick"), std::string::npos) << log;
    EXPECT_EQ(log.find("behavior/r3 (pid " + trimmed(r3_pid) + ") is hung"), std::string::npos) << log;
    EXPECT_EQ(log.find("behavior/r3: on-exit=respawn"), std::string::npos) << log;
    EXPECT_EQ(log.find("respawning"), std::string::npos) << log;
    EXPECT_EQ(read_file(run + "/behavior-r3.pid"), r3_pid) << "r3's behavior was replaced";
    EXPECT_EQ(::kill(std::stoi(r3_pid), 0), 0) << "r3's behavior no longer runs";
  }
  const std::string pid_file = run + "/behavior-r2.pid";
  const pid_t killed = std::stoi(read_file(pid_file));
  ASSERT_EQ(::kill(killed, SIGKILL), 0);
  ASSERT_TRUE(await("r2 respawned on its host and the set ready again", [&] {
    step();
    return read_file(run + "/launch.log").find("set 'recon-hosts' ready again (behavior/r2 respawned") !=
           std::string::npos;
  }, 60s)) << read_file(run + "/launch.log");
  EXPECT_NE(read_file(run + "/launch.log").find("started behavior/r2 on r2"), std::string::npos);
  registration.write({"test/hold", false});
  ASSERT_TRUE(await("the world stopped with every mission finished", [&] {
    return !read_file(run + "/metrics.json").empty() &&
           read_file(run + "/launch.log").find("simulator/main (pid") != std::string::npos;
  }, 240s)) << read_file(run + "/launch.log");
  const auto metrics = nlohmann::json::parse(read_file(run + "/metrics.json"));
  EXPECT_TRUE(metrics.at("team").at("all_finished").get<bool>()) << metrics.at("team").dump();
  for (const auto& r : metrics.at("robots")) EXPECT_TRUE(r.at("finished").get<bool>()) << r.dump();
}

}  // namespace
}  // namespace autonomy::test
