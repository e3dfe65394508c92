// The Remote Agent Experiment of May 1999, reproduced over DDS: the planner, the executive and
// the simulator (deploy/scenarios/ds1.pbtxt) as separate processes, in lockstep, flying the first
// four hours of the DS1-like day (services/executive/examples/ds1-4h.pbtxt: two plans of two
// hours each). The five faults of the experiment are switched on in the scenario one at a time
// and all together; each test asserts the executive's response, what it did not do, and that
// every goal a fault did not make impossible is achieved. A last test kills the planner while
// a replan is owed and restarts it: the spacecraft stays safe and the executive asks again.
//
//   domain  test
//   ------  -----------------------------------------------------------
//    210    ExecutiveTest.WithoutFaultsEveryGoalIsAchievedAndTheHorizonsJoinWithoutAGap
//    211    ExecutiveTest.CameraStuckOnAbortsSafesAndTheNewPlanGoesOnWithoutTheCamera
//    212    ExecutiveTest.AFailedElectronicsUnitIsResetWithoutReplanning
//    213    ExecutiveTest.AFalsePowerSensorIsRecognisedAndIgnored
//    214    ExecutiveTest.AThrusterStuckClosedSwitchesTheAttitudeControlMode
//    215    ExecutiveTest.AnUnconfirmedEngineCommandStopsCommandingTheEngineOnly
//    216    ExecutiveTest.AllFiveFaultsTogetherEachGetTheirResponse
//    217    ExecutiveTest.APlannerKilledMidReplanIsAskedAgainAndTheSpacecraftStaysSafe
//    228    ExecutiveTest.AnExecutiveKilledWhileThrustingResumesFromItsJournalAndFinishesTheDay
//    229    ExecutiveTest.APlannerThatStaysAwayHoldsTheWorldTenSecondsInAllAndTheDayEndsSafe
// (ctest names them integration.<suite>.<test>.)
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <optional>
#include <fstream>
#include <regex>

#include "tests/support/executive_watch.hpp"
#include "tests/support/process_test.hpp"

namespace autonomy::test {
namespace {

const std::string kScenario = std::string(AUTONOMY_SOURCE_DIR) + "/deploy/scenarios/ds1.pbtxt";
const std::string kConfig = std::string(AUTONOMY_SOURCE_DIR) + "/services/executive/examples/ds1-4h.pbtxt";
constexpr const char* kExecutive = "executive/main";

// The sixteen goals of ds1-4h.problem by what they need.
const std::vector<std::string> kCameraGoals = {"nav1_1", "nav1_2", "nav1_3", "nav1_4",
                                               "nav2_1", "nav2_2", "nav2_3", "nav2_4"};
const std::vector<std::string> kThrustGoals = {"thrust1", "thrust2"};
const std::vector<std::string> kDownlinkGoals = {"down1", "down2"};
const std::vector<std::string> kScheduleGoals = {"hidden1", "pass1", "hidden2", "pass2"};

std::vector<std::string> all_of(std::initializer_list<std::vector<std::string>> parts) {
  std::vector<std::string> out;
  for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  return sorted(out);
}

class ExecutiveTest : public ProcessTest {
 protected:
  // The scenario with the named faults of its commented list switched on ("micas-stuck-on", ...).
  std::string scenario_with(const std::vector<std::string>& faults) {
    std::string text = read_file(kScenario);
    for (const std::string& id : faults) {
      const std::string line = "# faults { id: \"" + id + "\"";
      const auto at = text.find(line);
      EXPECT_NE(at, std::string::npos) << "no commented fault " << id << " in " << kScenario;
      if (at != std::string::npos) text.erase(at, 2);
    }
    const std::string file = dir().file("ds1.pbtxt");
    write_file(file, text);
    return file;
  }

  void fly(int domain, const std::vector<std::string>& faults, std::vector<std::string> executive_args = {}) {
    join(domain);
    watch_.emplace(participant());
    commands_.emplace(participant(), dds::topics::spacecraft_command);
    truth_.emplace(participant(), dds::topics::truth_spacecraft_fault);
    telemetry_.emplace(participant(), dds::topics::spacecraft_telemetry);
    const std::string scenario = scenario_with(faults);
    // "{dir}/name": a file in the test's folder (which join() made).
    for (std::string& a : executive_args)
      if (a.rfind("{dir}/", 0) == 0) a = dir().file(a.substr(6));
    planner_ = &start_planner();
    // Every flight writes its report (plan.svg, report.md) into the test's folder.
    executive_args.insert(executive_args.begin(), {"--config", kConfig, "--domain", std::to_string(domain),
                                                   "--log-dir", dir().path(), "--log-level", "debug",
                                                   "--report-dir", dir().file("report")});
    executive_ = &start("executive", AUTONOMY_EXECUTIVE_BIN, executive_args);
    start_simulator({"--config", scenario, "--wait-for", kExecutive});
  }
  ChildProcess& start_planner(const std::string& name = "planner") {
    return start(name, AUTONOMY_PLANNER_BIN,
                 {"--domain", std::to_string(domain_), "--log-dir", dir().path()}, false);
  }

  void poll() {
    watch_->poll();
    commands_->poll();
    truth_->poll();
    for (auto& t : telemetry_->poll()) last_telemetry_ = t;
  }
  ::testing::AssertionResult finished() {
    return await("the executive finished the four hours", [&] {
      poll();
      return watch_->finished();
    }, std::chrono::seconds(120));
  }
  msg::ExecutiveStatus final_status() const { return watch_->final_status(); }
  std::vector<std::string> achieved() const { return watch_->achieved(); }
  std::vector<std::string> lost() const { return watch_->lost(); }
  std::vector<msg::ExecutiveEvent> events(const std::string& kind) const { return watch_->events(kind); }
  std::string story() const { return watch_->story(false); }
  // Commands the executive sent to `device` at or after `tick`.
  std::vector<msg::SpacecraftCommand> commands_to(const std::string& device, int64_t tick = 0) const {
    return commands_->matching([&](const auto& c) {
      return c.source == kExecutive && c.device == device && c.tick >= tick;
    });
  }
  // The event numbers are 1, 2, ... without a gap: nothing the executive said was lost.
  void expect_every_event_seen() const {
    std::vector<uint64_t> numbers;
    for (const auto& e : watch_->all_events())
      if (e.number > 0) numbers.push_back(e.number);
    std::sort(numbers.begin(), numbers.end());
    ASSERT_FALSE(numbers.empty());
    EXPECT_EQ(numbers.front(), 1u);
    EXPECT_EQ(numbers.back(), numbers.size());
  }

  // Once the first plan executes: the planner is killed (not watched any more) and the camera
  // sticks at its next picture, so the executive aborts and owes a plan nobody makes.
  void kill_the_planner_then_stick_the_camera() {
    // The writer matched before the flight starts: the lockstep world runs a thousand seconds in
    // a fraction of a second, and a writer made after the first plan (discovery) injected the
    // fault after the camera's last picture of the horizon (no abort: seen in a CI run).
    dds::Topic<msg::SpacecraftFaultInjection> topic(participant(), dds::topics::spacecraft_fault_injection);
    dds::Writer<msg::SpacecraftFaultInjection> inject(participant(), topic);
    ASSERT_TRUE(inject.wait_for_readers(1, kDeadline));
    ASSERT_TRUE(await("the first plan executing", [&] {
      poll();
      return !events("plan_executing").empty();
    })) << story();
    planner_->signal(SIGKILL);
    stop_watching(*planner_);
    inject.write({"stuck", "test", "stuck_on", "camera", 0, false, false});
  }

  ChildProcess* planner_ = nullptr;
  ChildProcess* executive_ = nullptr;
  std::optional<ExecutiveWatch> watch_;
  std::optional<Recorder<msg::SpacecraftCommand>> commands_;
  std::optional<Recorder<msg::SpacecraftFaultState>> truth_;
  std::optional<Recorder<msg::SpacecraftTelemetry>> telemetry_;
  std::optional<msg::SpacecraftTelemetry> last_telemetry_;
};

#define FLY(domain, ...)    \
  fly(domain, __VA_ARGS__); \
  ASSERT_TRUE(finished()) << story()

TEST_F(ExecutiveTest, WithoutFaultsEveryGoalIsAchievedAndTheHorizonsJoinWithoutAGap) {
  FLY(210, {});
  EXPECT_EQ(achieved(), all_of({kCameraGoals, kThrustGoals, kDownlinkGoals, kScheduleGoals})) << story();
  EXPECT_TRUE(lost().empty()) << story();
  EXPECT_TRUE(events("aborted").empty()) << story();
  EXPECT_TRUE(events("violation").empty()) << story();
  // Two plans: the second asked for before the first ended and joined at its end, 7200 s.
  ASSERT_EQ(events("horizon_joined").size(), 1u) << story();
  EXPECT_EQ(events("horizon_joined")[0].tick, 7200);
  const auto asked = events("plan_requested");
  ASSERT_EQ(asked.size(), 2u) << story();
  EXPECT_LT(asked[1].tick, 7200);
  EXPECT_NE(asked[1].text.find("next horizon"), std::string::npos);
  EXPECT_EQ(final_status().horizons, 1u);
  // What the world shows: eight images on target, two thrust arcs, two downlinks, the engine
  // in standby at the end (never left thrusting).
  ASSERT_TRUE(last_telemetry_);
  EXPECT_GE(last_telemetry_->camera.images_on_target, 8u);
  EXPECT_GE(last_telemetry_->propulsion.thrust_time_s, 2 * 2400.0);
  EXPECT_GT(last_telemetry_->telecom.downlinked_mb, 0.0);
  EXPECT_EQ(last_telemetry_->propulsion.thrust_level, 0u);
  EXPECT_EQ(commands_to("ips").size(), 4u);  // thrust, standby, thrust, standby
  expect_every_event_seen();
  // The report: both plans' timelines drawn, every goal listed.
  const std::string md = read_file(dir().file("report/report.md")), svg = read_file(dir().file("report/plan.svg"));
  EXPECT_NE(md.find("16 goals achieved, 0 lost"), std::string::npos) << md;
  EXPECT_NE(md.find("- thrust2"), std::string::npos);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("dsone.attitude"), std::string::npos);
  EXPECT_NE(svg.find("horizon_joined"), std::string::npos);
}

TEST_F(ExecutiveTest, CameraStuckOnAbortsSafesAndTheNewPlanGoesOnWithoutTheCamera) {
  FLY(211, {"micas-stuck-on"});
  const auto aborted = events("aborted");
  ASSERT_EQ(aborted.size(), 1u) << story();
  EXPECT_NE(aborted[0].text.find("camera reports imaging but the plan expects ready"), std::string::npos);
  const int64_t t = aborted[0].tick;
  // Detected within one tick of the picture's end: the first picture ends at 285 s.
  EXPECT_LE(t, 287);
  // Safed at once (engine standby), then a plan from the current state, spliced in.
  EXPECT_FALSE(commands_->matching([&](const auto& c) {
    return c.source == kExecutive && c.tick == t && c.device == "ips" && c.command == "standby";
  }).empty());
  const auto replans = watch_->events_where([&](const auto& e) {
    return e.kind == "plan_requested" && e.text.rfind("replan", 0) == 0;
  });
  ASSERT_FALSE(replans.empty()) << story();
  const auto executing = watch_->events_where([&](const auto& e) {
    return e.kind == "plan_executing" && e.text.find("new plan") != std::string::npos;
  });
  ASSERT_EQ(executing.size(), 1u) << story();
  EXPECT_GE(executing[0].tick, t);
  EXPECT_EQ(final_status().replans, 1u);
  // The stuck camera is never commanded again; what needed it is lost, the rest achieved.
  EXPECT_TRUE(commands_to("camera", t).empty());
  EXPECT_EQ(lost(), all_of({{"nav1_2", "nav1_3", "nav1_4", "nav2_1", "nav2_2", "nav2_3", "nav2_4"}, kDownlinkGoals}))
      << story();
  EXPECT_EQ(achieved(), all_of({{"nav1_1"}, kThrustGoals, kScheduleGoals})) << story();
  // The new plan is carried out: the engine thrusts after the abort.
  EXPECT_FALSE(commands_->matching([&](const auto& c) {
    return c.source == kExecutive && c.tick > t && c.device == "ips" && c.command == "thrust";
  }).empty());
  EXPECT_EQ(final_status().disabled_devices, std::vector<std::string>{"camera"});
}

TEST_F(ExecutiveTest, AFailedElectronicsUnitIsResetWithoutReplanning) {
  FLY(212, {"lpe-failed"});
  const auto resets = events("fault reset");
  ASSERT_EQ(resets.size(), 1u) << story();
  EXPECT_NE(resets[0].text.find("lpe reports failed"), std::string::npos);
  EXPECT_LE(resets[0].tick, 1001);  // failed at 1000 s
  EXPECT_EQ(commands_to("lpe").size(), 1u);
  EXPECT_EQ(commands_to("lpe")[0].command, "reset");
  EXPECT_TRUE(events("aborted").empty()) << story();
  EXPECT_EQ(final_status().replans, 0u);
  const auto cured = truth_->matching([](const auto& f) { return f.fault_id == "lpe-failed" && !f.active; });
  ASSERT_FALSE(cured.empty());
  EXPECT_EQ(cured.back().ended_by, "reset");
  EXPECT_EQ(achieved(), all_of({kCameraGoals, kThrustGoals, kDownlinkGoals, kScheduleGoals})) << story();
}

TEST_F(ExecutiveTest, AFalsePowerSensorIsRecognisedAndIgnored) {
  FLY(213, {"power-sensor-false"});
  const auto ignored = events("fault ignore_sensor");
  ASSERT_EQ(ignored.size(), 1u) << story();
  EXPECT_NE(ignored[0].text.find("camera_switch_status"), std::string::npos);
  EXPECT_GE(ignored[0].tick, 10800);  // the sensor lies from 10800 s on
  EXPECT_LE(ignored[0].tick, 10805);
  EXPECT_EQ(final_status().ignored_sensors, std::vector<std::string>{"camera_switch_status"});
  // Told apart from a failed switch by the voltages: no abort, the camera still used after.
  EXPECT_TRUE(events("aborted").empty()) << story();
  EXPECT_TRUE(final_status().disabled_devices.empty());
  EXPECT_EQ(achieved(), all_of({kCameraGoals, kThrustGoals, kDownlinkGoals, kScheduleGoals})) << story();
}

TEST_F(ExecutiveTest, AThrusterStuckClosedSwitchesTheAttitudeControlMode) {
  FLY(214, {"thruster-x-stuck"});
  const auto switched = events("fault switch_control_mode");
  ASSERT_EQ(switched.size(), 1u) << story();
  EXPECT_NE(switched[0].text.find("thruster_x"), std::string::npos);
  const auto set_mode = commands_->matching([](const auto& c) { return c.device == "adcs" && c.command == "set_mode"; });
  ASSERT_EQ(set_mode.size(), 1u);
  EXPECT_EQ(set_mode[0].arguments, std::vector<std::string>{"wheels_and_other_thrusters"});
  ASSERT_TRUE(last_telemetry_);
  EXPECT_EQ(last_telemetry_->attitude.control_mode, "wheels_and_other_thrusters");
  // The turns after it are slower but within the plan's bounds: no abort, every goal.
  EXPECT_TRUE(events("aborted").empty()) << story();
  EXPECT_EQ(achieved(), all_of({kCameraGoals, kThrustGoals, kDownlinkGoals, kScheduleGoals})) << story();
  EXPECT_GE(commands_->matching([&](const auto& c) {
    return c.device == "adcs" && c.command == "turn" && c.tick > switched[0].tick;
  }).size(), 4u);
}

TEST_F(ExecutiveTest, AnUnconfirmedEngineCommandStopsCommandingTheEngineOnly) {
  FLY(215, {"ips-unconfirmed"});
  const auto stopped = events("fault stop_commanding");
  ASSERT_EQ(stopped.size(), 1u) << story();
  EXPECT_NE(stopped[0].text.find("ips"), std::string::npos);
  const int64_t t = stopped[0].tick;
  // The thrust at 1137 s, never confirmed: its 5 s timeout.
  EXPECT_TRUE(commands_to("ips", t).empty()) << "the engine was commanded after it was given up";
  EXPECT_TRUE(events("aborted").empty()) << story();
  EXPECT_EQ(final_status().disabled_devices, std::vector<std::string>{"ips"});
  EXPECT_EQ(lost(), sorted(kThrustGoals)) << story();
  EXPECT_EQ(achieved(), all_of({kCameraGoals, kDownlinkGoals, kScheduleGoals})) << story();
}

TEST_F(ExecutiveTest, AllFiveFaultsTogetherEachGetTheirResponse) {
  FLY(216, {"micas-stuck-on", "lpe-failed", "power-sensor-false", "thruster-x-stuck", "ips-unconfirmed"});
  EXPECT_EQ(events("aborted").size(), 1u) << story();
  EXPECT_EQ(events("fault reset").size(), 1u) << story();
  EXPECT_EQ(events("fault ignore_sensor").size(), 1u) << story();
  EXPECT_EQ(events("fault switch_control_mode").size(), 1u) << story();
  EXPECT_EQ(events("fault stop_commanding").size(), 1u) << story();
  EXPECT_EQ(sorted(final_status().disabled_devices), (std::vector<std::string>{"camera", "ips"}));
  // Only the goals the faults took are lost: the camera's (stuck), the downlinks (no images to
  // send), the thrust arcs (the engine no longer commanded).
  EXPECT_EQ(achieved(), all_of({{"nav1_1"}, kScheduleGoals})) << story();
  EXPECT_EQ(lost().size(), 11u) << story();
  expect_every_event_seen();
}

TEST_F(ExecutiveTest, APlannerKilledMidReplanIsAskedAgainAndTheSpacecraftStaysSafe) {
  fly(217, {});  // the shipped settings: requests asked again after 5 s, holds of 10 s per outage
  ASSERT_NO_FATAL_FAILURE(kill_the_planner_then_stick_the_camera());
  // Unanswered after 5 s: asked again, the tick still held (the hold lasts 10 s in all).
  ASSERT_TRUE(await("asked again after no reply", [&] {
    poll();
    return !events("plan_late").empty();
  })) << story();
  ASSERT_EQ(events("aborted").size(), 1u) << story();
  const int64_t t = events("aborted")[0].tick;
  start_planner("planner-again");
  ASSERT_TRUE(finished()) << story();
  const auto executing = watch_->events_where([&](const auto& e) {
    return e.kind == "plan_executing" && e.text.find("new plan") != std::string::npos;
  });
  ASSERT_EQ(executing.size(), 1u) << story();
  const int64_t resumed = executing[0].tick;
  EXPECT_GT(resumed, t);
  // Between the abort and the new plan only safing went out, and the engine stayed off.
  const auto between = commands_->matching([&](const auto& c) {
    return c.source == kExecutive && c.tick >= t && c.tick < resumed;
  });
  for (const auto& c : between) EXPECT_EQ(c.device + " " + c.command, "ips standby");
  const auto asked = watch_->events_where([&](const auto& e) {
    return e.kind == "plan_requested" && e.tick >= t && e.tick <= resumed;
  });
  EXPECT_GE(asked.size(), 2u) << story();
  EXPECT_TRUE(events("watchdog").empty()) << story();
}

// The planner killed for good, with the shipped settings: the world is held 10 s in all (not 10 s
// per request asked again), then it goes on with the spacecraft safe while the request is asked
// again every 5 s; the day ends all the same, with its report, the goals no plan had lost.
TEST_F(ExecutiveTest, APlannerThatStaysAwayHoldsTheWorldTenSecondsInAllAndTheDayEndsSafe) {
  fly(229, {});
  ASSERT_NO_FATAL_FAILURE(kill_the_planner_then_stick_the_camera());
  ASSERT_TRUE(finished()) << story();
  ASSERT_EQ(events("aborted").size(), 1u) << story();
  const int64_t aborted = events("aborted")[0].tick;
  const auto late = events("plan_late");
  const auto released = std::count_if(late.begin(), late.end(), [](const auto& e) {
    return e.text.find("no plan within 10.000000 s: the world goes on with the spacecraft safe") != std::string::npos;
  });
  EXPECT_EQ(released, 1) << story();
  // Asked again while held, at the tick it holds (the world did not move for the second ask).
  const auto asked_while_held = watch_->events_where([&](const auto& e) {
    return e.kind == "plan_requested" && e.text.find("replan") != std::string::npos;
  });
  ASSERT_GE(asked_while_held.size(), 2u) << story();
  EXPECT_EQ(asked_while_held[1].tick, asked_while_held[0].tick) << story();
  // The day ended anyway; nothing was commanded after the abort but safing.
  const auto after = commands_->matching([&](const auto& c) { return c.source == kExecutive && c.tick > aborted; });
  for (const auto& c : after) EXPECT_EQ(c.device + " " + c.command, "ips standby");
  // Every goal lost says why no plan had it: its window closed while the requests went
  // unanswered (how many depends on how fast the world runs), or the mission ended.
  for (const auto& why : final_status().goals_lost)
    if (why.find("camera") == std::string::npos)
      EXPECT_TRUE(why.find("the mission ended before a plan had it (safe_waiting_for_plan)") != std::string::npos ||
                  why.find("its window closed before") != std::string::npos)
          << why;
  // It ended at the mission's horizon, still safe and waiting.
  const auto ended = events("finished");
  ASSERT_EQ(ended.size(), 1u) << story();
  EXPECT_EQ(ended[0].tick, 14400) << story();
  EXPECT_TRUE(std::ifstream(dir().file("report/report.md")).good());
  ASSERT_TRUE(last_telemetry_);
  EXPECT_EQ(last_telemetry_->propulsion.thrust_level, 0u);
}

// The planner replaced, once the first plan executes, by one that refuses every request as busy
// (the test answers them): refusals do not renew the lockstep hold. Asked again after 1, 2, 4 s
// of back-off, four refusals fall within the outage's 10 s (at about 0, 1, 3 and 7 s), then the
// world goes on with the spacecraft safe; had each refusal renewed the hold, the world would
// wait for a fifth (at about 15 s) and ten seconds more.
TEST_F(ExecutiveTest, APlannerThatRefusesEveryRequestHoldsTheWorldTenSecondsInAll) {
  fly(48, {});
  ASSERT_NO_FATAL_FAILURE(kill_the_planner_then_stick_the_camera());
  dds::Topic<msg::PlanningRequest> request_topic(participant(), dds::topics::planner_request);
  dds::Topic<msg::PlanningReply> reply_topic(participant(), dds::topics::planner_reply);
  dds::Reader<msg::PlanningRequest> requests(participant(), request_topic);
  dds::Writer<msg::PlanningReply> replies(participant(), reply_topic);
  auto refuse_what_came = [&] {
    for (const auto& r : requests.take()) {
      if (!r.valid) continue;
      msg::PlanningReply no;
      no.request_id = r.value.request_id;
      no.requester = r.value.requester;
      no.status = msg::PlanningStatus::Rejected;
      no.reason = "busy";
      no.detail = "the test's planner refuses everything";
      replies.write(no);
    }
  };
  auto released = [&] {
    return !watch_->events_where([](const auto& e) {
      return e.kind == "plan_late" && e.text.find("the world goes on with the spacecraft safe") != std::string::npos;
    }).empty();
  };
  ASSERT_TRUE(await("the world released with the spacecraft safe", [&] {
    refuse_what_came();
    poll();
    return released();
  }, std::chrono::seconds(90))) << story();
  const auto release = events("plan_late").back();
  const auto refused_before = watch_->events_where([&](const auto& e) {
    return e.kind == "plan_refused" && e.number < release.number;
  });
  EXPECT_GE(refused_before.size(), 2u) << story();
  EXPECT_LE(refused_before.size(), 4u) << story();
  for (const auto& e : refused_before) EXPECT_NE(e.text.find("busy"), std::string::npos) << e.text;
  // Refused all day long, the day still ends at its horizon with its report.
  ASSERT_TRUE(await("the day finished", [&] {
    refuse_what_came();
    poll();
    return watch_->finished();
  }, std::chrono::seconds(120))) << story();
  EXPECT_EQ(events("finished").at(0).tick, 14400) << story();
  EXPECT_TRUE(std::ifstream(dir().file("report/report.md")).good());
}

// Killed -9 while the engine thrusts in the first horizon and started again at once on its
// journal: the spacecraft is safed first, nothing achieved is forgotten, the rest is planned from
// the journalled state on the horizons' grid, and the second horizon's goals are all achieved.
TEST_F(ExecutiveTest, AnExecutiveKilledWhileThrustingResumesFromItsJournalAndFinishesTheDay) {
  fly(228, {}, {"--journal", "{dir}/executive.db"});
  const std::string journal = dir().file("executive.db");
  ASSERT_TRUE(await("the engine thrusting", [&] {
    poll();
    return last_telemetry_ && last_telemetry_->propulsion.thrust_level > 0;
  }, std::chrono::seconds(60))) << story();
  poll();
  const std::vector<std::string> achieved_before = [&] {
    std::vector<std::string> labels;
    for (const auto& e : events("goal_achieved")) labels.push_back(e.text.substr(0, e.text.find(':')));
    return sorted(labels);
  }();
  stop_watching(*executive_);
  executive_->signal(SIGKILL);
  ASSERT_TRUE(executive_->wait_for_exit(std::chrono::seconds(10)));
  const int64_t killed_at = last_telemetry_->tick;
  executive_ = &start("executive-again", AUTONOMY_EXECUTIVE_BIN,
                      {"--config", kConfig, "--domain", std::to_string(domain_), "--log-dir", dir().path(),
                       "--log-level", "debug", "--report-dir", dir().file("report"), "--journal", journal});
  ASSERT_TRUE(finished()) << story();
  const auto resumed = events("resumed");
  ASSERT_EQ(resumed.size(), 1u) << story();
  EXPECT_GE(resumed[0].tick, killed_at);
  EXPECT_NE(resumed[0].text.find("executive down from"), std::string::npos) << resumed[0].text;
  // Safed first: the engine to standby at the resumption.
  const auto standby = commands_->matching([&](const auto& c) {
    return c.source == kExecutive && c.device == "ips" && c.command == "standby" && c.tick >= resumed[0].tick;
  });
  ASSERT_FALSE(standby.empty()) << story();
  EXPECT_EQ(standby.front().tick, resumed[0].tick);
  // Nothing achieved was forgotten, and the engine never disagreed with the plan.
  const auto final_achieved = achieved();
  for (const auto& label : achieved_before)
    EXPECT_TRUE(std::find(final_achieved.begin(), final_achieved.end(), label) != final_achieved.end()) << label;
  for (const auto& e : events("aborted")) EXPECT_EQ(e.text.find("ips"), std::string::npos) << e.text;
  // The second horizon was planned on the grid and flown in full.
  for (const auto& label : {"thrust2", "down2", "nav2_1", "nav2_2", "nav2_3", "nav2_4", "hidden2", "pass2"})
    EXPECT_TRUE(std::find(final_achieved.begin(), final_achieved.end(), label) != final_achieved.end())
        << label << "\n" << story();
  // A goal lost says why: its window closed while the executive was down, or it was cut off.
  for (const auto& why : final_status().goals_lost)
    EXPECT_TRUE(why.find("executive down from") != std::string::npos || why.find("window") != std::string::npos) << why;
  EXPECT_TRUE(std::ifstream(dir().file("report/report.md")).good());
}

}  // namespace
}  // namespace autonomy::test
