// DDS Security (issue 22) with real processes: identities, governance and permissions are made at
// test time by deploy/security/security.sh into the test's folder (fresh dates every run), and
// every process gets its own identity through CYCLONEDDS_URI, as deploy/launch.sh --profile secure
// does. The test's own participant is the operator (it may command and hold a lockstep world).
//
// One DDS domain per test (ctest runs them in parallel); this file uses 125-139 only:
//
//   domain  test
//   ------  -----------------------------------------------------------------
//    125    SecurityTest.WithoutAnIdentityAParticipantDiscoversNothingAndReadsNothing
//    126    SecurityTest.ARobotIdentityCannotPublishCourierCommandsOrTheClock
//    127    SecurityTest.AParticipantSignedByAnotherCaIsRefused
//    128    SecurityTest.ATamperedPermissionsFileStopsTheServiceAtStartAndTheCheckerFindsAForeignKey
//    129    SecureCourierTest.ThePaperExampleCompletesSecured
//    130    SecurityTest.TheDs1DayCompletesSecured
//    131    SecurityTest.TheLauncherRunsASetSecuredAndRefusesTamperedPermissionsBeforeStarting
#include "tests/integration/courier_fixture.hpp"
#include "tests/support/executive_watch.hpp"
#include "tests/support/launched_set.hpp"
#include "tests/support/process_test.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace autonomy::test {
namespace {

const std::string kSecurity = std::string(AUTONOMY_SOURCE_DIR) + "/deploy/security/security.sh";

// Runs security.sh with `args`; its output goes to `log`. Returns the exit code.
int security(const std::string& args, const std::string& log) {
  const std::string cmd = "bash '" + kSecurity + "' " + args + " >>'" + log + "' 2>&1";
  const int rc = std::system(cmd.c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

// A folder of DDS Security material: CAs, governance, identities by NAME (service/instance).
class Keys {
 public:
  // Makes the CAs and the identities {name, kind} in dir; fails the test when it cannot.
  Keys(std::string dir, const std::vector<std::pair<std::string, std::string>>& identities)
      : dir_(std::move(dir)), log_(dir_ + ".log") {
    EXPECT_EQ(security("init '" + dir_ + "'", log_), 0) << read_file(log_);
    for (const auto& [name, kind] : identities)
      EXPECT_EQ(security("add '" + dir_ + "' " + name + " " + kind, log_), 0) << read_file(log_);
  }
  // CYCLONEDDS_URI for a process with NAME's identity: the loopback profile plus its section.
  std::string uri(const std::string& name) const { return dds_uri() + ",file://" + folder(name) + "/cyclone.xml"; }
  std::string folder(const std::string& name) const {
    std::string file = name;
    for (char& c : file)
      if (c == '/') c = '-';
    return dir_ + "/identities/" + file;
  }
  const std::string& dir() const { return dir_; }
  const std::string& log() const { return log_; }

 private:
  std::string dir_, log_;
};

class SecurityTest : public ProcessTest {
 protected:
  // The operator's identity for the test's participant, then join the domain. The keys live
  // outside the test's folder (join() makes that one), beside it in the temp dir.
  void join_secured(int domain, const std::vector<std::pair<std::string, std::string>>& identities) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string dir = (std::filesystem::temp_directory_path() /
                             ("autonomy-keys-" + std::to_string(::getpid()) + "-" + info->name()))
                                .string();
    std::filesystem::remove_all(dir);
    keys_.emplace(dir, identities);
    ASSERT_FALSE(HasFailure()) << "the keys could not be made: " << read_file(keys_->log());
    use_uri(keys_->uri("operator"));
    join(domain);
  }
  void TearDown() override {
    ProcessTest::TearDown();
    if (keys_) std::filesystem::remove_all(keys_->dir());
  }
  // Starts a child with `identity` (the plain loopback profile for ""), named `name`.
  ChildProcess& start_as(const std::string& identity, const std::string& name, const std::string& program,
                         std::vector<std::string> args, bool must_keep_running = true) {
    use_uri(identity.empty() ? dds_uri() : keys_->uri(identity));
    ChildProcess& child = start(name, program, std::move(args), must_keep_running);
    use_uri(keys_->uri("operator"));
    return child;
  }
  ChildProcess& cli(const std::string& identity, const std::string& name, std::vector<std::string> args) {
    args.insert(args.end(), {"--domain", std::to_string(domain_)});
    return start_as(identity, name, AUTONOMY_AUTONOMY_BIN, std::move(args), false);
  }
  // The demo world in real time with r1's behavior, each with its own identity.
  void start_demo_world() {
    const std::string domain = std::to_string(domain_);
    start_as("simulator/main", "simulator", AUTONOMY_SIMULATOR_BIN,
             {"--mode", "paced", "--domain", domain, "--log-dir", dir().path()});
    start_as("behavior/r1", "behavior-r1", AUTONOMY_BEHAVIOR_BIN,
             {"--robot", "r1", "--domain", domain, "--log-dir", dir().path()});
  }
  std::string out(const std::string& name) const { return read_file(dir().file(name + ".out")); }
  ::testing::AssertionResult ended(ChildProcess& child) {
    return await(child.name() + " ended", [&] { return !child.running(); });
  }
  // JSON samples printed by an `autonomy topic echo` child.
  size_t samples_of(const std::string& name) const {
    size_t n = 0;
    const std::string text = out(name);
    for (size_t at = 0; (at = text.find("\n{", at)) != std::string::npos; ++at) ++n;
    return n + (text.rfind('{', 0) == 0 ? 1 : 0);
  }

  std::optional<Keys> keys_;
};

const std::vector<std::pair<std::string, std::string>> kDemoIdentities = {
    {"operator", "operator"}, {"tools", "tools"}, {"simulator/main", "simulator"}, {"behavior/r1", "behavior"}};

TEST_F(SecurityTest, WithoutAnIdentityAParticipantDiscoversNothingAndReadsNothing) {
  join_secured(125, kDemoIdentities);
  start_demo_world();
  // The plain listener starts first: whatever the identified one gets, it had the time to get too.
  cli("", "echo-plain", {"topic", "echo", "autonomy/robot/state"});
  auto& list_plain = cli("", "list-plain", {"node", "list"});
  cli("tools", "echo-tools", {"topic", "echo", "autonomy/robot/state"});
  ASSERT_TRUE(await("the tools identity reads 20 robot states", [&] { return samples_of("echo-tools") >= 20; }));
  auto& list_tools = cli("tools", "list-tools", {"node", "list"});
  ASSERT_TRUE(ended(list_plain));
  ASSERT_TRUE(ended(list_tools));
  EXPECT_NE(out("list-tools").find("simulator"), std::string::npos) << out("list-tools");
  EXPECT_NE(out("list-tools").find("behavior"), std::string::npos) << out("list-tools");
  EXPECT_NE(out("list-plain").find("no autonomy processes seen"), std::string::npos) << out("list-plain");
  EXPECT_EQ(samples_of("echo-plain"), 0u) << out("echo-plain");
  EXPECT_EQ(out("echo-plain").find("\"robot_id\""), std::string::npos) << out("echo-plain");
}

TEST_F(SecurityTest, ARobotIdentityCannotPublishCourierCommandsOrTheClock) {
  join_secured(126, kDemoIdentities);
  Recorder<msg::CourierCommand> commands(participant(), dds::topics::courier_command);
  Recorder<msg::SimClock> clock(participant(), dds::topics::clock);
  start_demo_world();
  ASSERT_TRUE(await("the world's clock", [&] { return !clock.poll().empty() || !clock.all().empty(); }));

  auto& command = cli("behavior/r1", "pub-command",
                      {"topic", "pub", "autonomy/courier/command", R"({"command_id":"from-robot","text":"x"})"});
  constexpr int64_t kForged = std::numeric_limits<int64_t>::max();
  auto& forged = cli("behavior/r1", "pub-clock",
                     {"topic", "pub", "autonomy/clock", "{\"tick\":" + std::to_string(kForged) + "}"});
  ASSERT_TRUE(ended(command));
  ASSERT_TRUE(ended(forged));
  // Refused locally: the robot's process cannot even create the topics.
  for (auto* child : {&command, &forged}) {
    ASSERT_TRUE(child->status());
    EXPECT_FALSE(child->status()->exited && child->status()->code == 0) << out(child->name());
    EXPECT_NE(out(child->name()).find("Not Allowed By Security"), std::string::npos) << out(child->name());
  }
  // The operator's command, sent after them, arrives; theirs never did.
  auto& op = cli("operator", "pub-operator",
                 {"topic", "pub", "autonomy/courier/command", R"({"command_id":"from-operator","text":"x"})"});
  ASSERT_TRUE(await("the operator's command", [&] {
    commands.poll();
    return !commands.matching([](const auto& c) { return c.command_id == "from-operator"; }).empty();
  }));
  ASSERT_TRUE(ended(op));
  EXPECT_TRUE(op.status()->exited && op.status()->code == 0) << out("pub-operator");
  EXPECT_TRUE(commands.matching([](const auto& c) { return c.command_id == "from-robot"; }).empty());
  // The clock goes on from the world's ticks, never the forged one.
  clock.poll();
  const int64_t last = clock.all().back().tick;
  ASSERT_TRUE(await("later ticks", [&] {
    clock.poll();
    return clock.all().back().tick > last + 5;
  }));
  EXPECT_TRUE(clock.matching([](const auto& c) { return c.tick == kForged; }).empty());
}

TEST_F(SecurityTest, AParticipantSignedByAnotherCaIsRefused) {
  join_secured(127, kDemoIdentities);
  // Another authority's operator: its own CAs, governance and permissions, all well formed.
  const Keys foreign(dir().file("foreign"), {{"operator", "operator"}});
  ASSERT_FALSE(HasFailure()) << read_file(foreign.log());
  start_demo_world();
  use_uri(foreign.uri("operator"));
  auto& echo_foreign = start("echo-foreign", AUTONOMY_AUTONOMY_BIN,
                             {"topic", "echo", "autonomy/robot/state", "--domain", std::to_string(domain_)}, false);
  auto& goal_foreign = start("goal-foreign", AUTONOMY_AUTONOMY_BIN,
                             {"topic", "pub", "autonomy/nav/goal", R"({"robot_id":"r1","goal_id":"foreign","x":18,"y":2})",
                              "--wait", "3", "--domain", std::to_string(domain_)},
                             false);
  use_uri(keys_->uri("operator"));
  Recorder<msg::GoalStatus> statuses(participant(), dds::topics::goal_status);
  cli("tools", "echo-tools", {"topic", "echo", "autonomy/robot/state"});
  ASSERT_TRUE(await("the tools identity reads 20 robot states", [&] { return samples_of("echo-tools") >= 20; }));
  ASSERT_TRUE(ended(goal_foreign));
  // The foreign participant was created (its own material is valid) but nobody talks to it: it
  // sees no behavior to send a goal to and reads nothing.
  EXPECT_NE(out("goal-foreign").find("no behavior process serves robot \"r1\""), std::string::npos)
      << out("goal-foreign");
  EXPECT_TRUE(echo_foreign.running()) << out("echo-foreign");
  EXPECT_EQ(samples_of("echo-foreign"), 0u) << out("echo-foreign");
  statuses.poll();
  EXPECT_TRUE(statuses.matching([](const auto& s) { return s.goal_id == "foreign"; }).empty());
}

TEST_F(SecurityTest, ATamperedPermissionsFileStopsTheServiceAtStartAndTheCheckerFindsAForeignKey) {
  join_secured(128, kDemoIdentities);
  // One signed byte changed: "autonomy/clock" becomes "autonomy/clocj" in the simulator's grants.
  const std::string permissions = keys_->folder("simulator/main") + "/permissions.p7s";
  std::string text = read_file(permissions);
  const auto at = text.find("<topic>autonomy/clock</topic>");
  ASSERT_NE(at, std::string::npos);
  text[at + std::string("<topic>autonomy/cloc").size()] = 'j';
  write_file(permissions, text);
  auto& simulator = start_as("simulator/main", "simulator", AUTONOMY_SIMULATOR_BIN,
                             {"--mode", "paced", "--domain", std::to_string(domain_), "--log-dir", dir().path()}, false);
  ASSERT_TRUE(ended(simulator));
  EXPECT_TRUE(simulator.status()->exited && simulator.status()->code == 1) << simulator.status()->describe();
  const std::string said = out("simulator");
  EXPECT_NE(said.find("validating local permissions"), std::string::npos) << said;
  EXPECT_NE(said.find("signature failure"), std::string::npos) << said;
  EXPECT_NE(said.find("cannot run: dds_create_participant with DDS Security"), std::string::npos) << said;
  EXPECT_NE(said.find("security.sh check"), std::string::npos) << said;
  // The checker names the file and the reason before anything starts.
  const std::string log = dir().file("check.log");
  EXPECT_EQ(security("check '" + keys_->dir() + "' simulator/main", log), 1);
  EXPECT_NE(read_file(log).find("permissions.p7s is not signed by this permissions CA"), std::string::npos)
      << read_file(log);

  // The behavior's certificate with the tools identity's key. Cyclone does not compare them at
  // start (the process would run and fail every handshake: "Process handshake failed: Failed to
  // finalize digest context"), so the checker, which launch.sh runs first, must say it.
  std::filesystem::copy_file(keys_->folder("tools") + "/key.pem", keys_->folder("behavior/r1") + "/key.pem",
                             std::filesystem::copy_options::overwrite_existing);
  const std::string log2 = dir().file("check2.log");
  EXPECT_EQ(security("check '" + keys_->dir() + "' behavior/r1", log2), 1);
  EXPECT_NE(read_file(log2).find("does not match its key"), std::string::npos) << read_file(log2);
}

// The courier paper's example (Fig. 5: A-120 closes after the red letter is loaded and opens
// while the green book is fetched) with every process on its own identity and the test as the
// operator (commands, lockstep hold).
class SecureCourierTest : public CourierTest {
 protected:
  void TearDown() override {
    CourierTest::TearDown();
    if (keys_) std::filesystem::remove_all(keys_->dir());
  }
  std::optional<Keys> keys_;
};

TEST_F(SecureCourierTest, ThePaperExampleCompletesSecured) {
  const std::string dir = (std::filesystem::temp_directory_path() /
                           ("autonomy-keys-" + std::to_string(::getpid()) + "-courier"))
                              .string();
  std::filesystem::remove_all(dir);
  keys_.emplace(dir, std::vector<std::pair<std::string, std::string>>{{"operator", "operator"},
                                                                      {"simulator/main", "simulator"},
                                                                      {"behavior/rhino", "behavior"},
                                                                      {"courier/main", "courier"}});
  ASSERT_FALSE(HasFailure()) << read_file(keys_->log());
  use_uri(keys_->uri("operator"));
  setup_observers(129);
  // CourierTest::start_world, with one identity per process.
  scenario_ = this->dir().file("office.pbtxt");
  write_file(scenario_, office_scenario(kFig5Script));
  journal_ = this->dir().file("courier.db");
  use_uri(keys_->uri("simulator/main"));
  start_simulator({"--config", scenario_, "--mode", "lockstep", "--wait-for", "behavior/rhino", "--wait-for",
                   "courier/main", "--wait-for", "test/commands"});
  use_uri(keys_->uri("behavior/rhino"));
  behavior_ = &start_behavior("rhino", {"--config", scenario_});
  use_uri(keys_->uri("courier/main"));
  courier_ = &start_courier();
  use_uri(keys_->uri("operator"));
  send_paper_commands();
  ASSERT_TRUE(both_jobs_finished("both jobs finished"));
  expect_fig5_sequence();
}

TEST_F(SecurityTest, TheDs1DayCompletesSecured) {
  join_secured(130, {{"operator", "operator"},
                     {"simulator/main", "simulator"},
                     {"planner/main", "planner"},
                     {"executive/main", "executive"}});
  ExecutiveWatch watch(participant());
  const std::string domain = std::to_string(domain_);
  start_as("planner/main", "planner", AUTONOMY_PLANNER_BIN, {"--domain", domain, "--log-dir", dir().path()});
  start_as("executive/main", "executive", AUTONOMY_EXECUTIVE_BIN,
           {"--config", std::string(AUTONOMY_SOURCE_DIR) + "/services/executive/examples/ds1-4h.pbtxt", "--domain",
            domain, "--log-dir", dir().path(), "--report-dir", dir().file("report")});
  start_as("simulator/main", "simulator", AUTONOMY_SIMULATOR_BIN,
           {"--config", std::string(AUTONOMY_SOURCE_DIR) + "/deploy/scenarios/ds1.pbtxt", "--wait-for",
            "executive/main", "--domain", domain, "--log-dir", dir().path()});
  ASSERT_TRUE(await("the executive finished the four hours", [&] {
    watch.poll();
    return watch.finished();
  }, std::chrono::seconds(150))) << watch.story(false);
  EXPECT_EQ(watch.achieved().size(), 16u) << watch.story(false);
  EXPECT_TRUE(watch.lost().empty()) << watch.story(false);
  EXPECT_TRUE(watch.events("aborted").empty()) << watch.story(false);
}

// deploy/launch.sh --profile secure as a user runs it: the identities are made in
// AUTONOMY_SECURITY_DIR on the first run; a tools identity then sees the set. A permissions file
// changed by hand stops the next launch before any process starts, naming the file.
TEST_F(SecurityTest, TheLauncherRunsASetSecuredAndRefusesTamperedPermissionsBeforeStarting) {
  join_secured(131, {{"operator", "operator"}, {"tools", "tools"}});
  ASSERT_EQ(setenv("AUTONOMY_SECURITY_DIR", keys_->dir().c_str(), 1), 0);  // inherited by the launchers
  const LaunchedSet set(dir(), "demo", [](const std::string&, const std::string& line) { return line; });
  auto& launcher = start("launcher", "/bin/bash", set.launcher_args(domain_, {"--profile", "secure"}), false);
  ASSERT_TRUE(await("the set ready", [&] { return out("launcher").find("set 'demo' ready") != std::string::npos; },
                    std::chrono::seconds(60)))
      << out("launcher");
  EXPECT_TRUE(std::filesystem::exists(keys_->folder("simulator/main") + "/cert.pem"));
  EXPECT_TRUE(std::filesystem::exists(keys_->folder("behavior/r1") + "/cert.pem"));
  auto& list = cli("tools", "list-tools", {"node", "list"});
  ASSERT_TRUE(ended(list));
  EXPECT_NE(out("list-tools").find("simulator"), std::string::npos) << out("list-tools");
  EXPECT_NE(out("list-tools").find("behavior"), std::string::npos) << out("list-tools");
  launcher.signal(SIGINT);
  ASSERT_TRUE(ended(launcher));

  const std::string permissions = keys_->folder("behavior/r1") + "/permissions.p7s";
  std::string text = read_file(permissions);
  const auto at = text.find("<topic>autonomy/robot/cmd_vel</topic>");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, std::string("<topic>autonomy/robot/cmd_vel</topic>").size(), "<topic>autonomy/clock</topic>");
  write_file(permissions, text);
  const LaunchedSet again(dir(), "demo", [](const std::string&, const std::string& line) { return line; });
  auto& refused = start("launcher-again", "/bin/bash", again.launcher_args(domain_, {"--profile", "secure"}), false);
  ASSERT_TRUE(ended(refused));
  EXPECT_TRUE(refused.status()->exited && refused.status()->code == 2) << out("launcher-again");
  EXPECT_NE(out("launcher-again").find("behavior-r1/permissions.p7s is not signed by this permissions CA"),
            std::string::npos)
      << out("launcher-again");
  EXPECT_EQ(out("launcher-again").find("launch: started"), std::string::npos) << out("launcher-again");
}

}  // namespace
}  // namespace autonomy::test
