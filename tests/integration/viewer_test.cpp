// Integration tests of the viewer process: with the real simulator and a behavior, a WebSocket
// client (a page's stand-in) sees the robot move between two frames, a door the scenario closes
// drawn closed and a spacecraft fault in the side panels; a port in use is refused with a clear
// error; headless Chromium draws the page; a Foxglove client decodes robot states with the
// advertised IDL.
//
// One DDS domain per test; this file uses 55-58 and 189 only:
//
//   domain  test
//   ------  -----------------------------------------------
//     55    ViewerTest.PageFramesFollowTheRobotAndTheClosingDoor
//     56    ViewerTest.PortInUseIsAClearError
//     57    ViewerTest.PageInHeadlessChromiumDrawsTheMovingRobotTheClosedDoorAndAJobChange
//    189    ViewerTest.FoxgloveClientDecodesTheRobotStateWithTheAdvertisedSchema
#include "tests/support/process_test.hpp"
#include "tests/support/web_socket_client.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/stat.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <regex>
#include <sstream>

namespace autonomy::test {
namespace {

using namespace std::chrono_literals;
using nlohmann::json;

// A corridor split by a wall at x = 10 with door d1 (1.6 m, hinge at (10, 2.2)); the door starts
// open and the scenario closes it at t = 1.5 s. r1 starts at (2, 3) on the west side.
constexpr const char* kViewerScenario = R"pb(
name: "viewer-corridor"
world {
  width: 20.0
  height: 6.0
  obstacles { min_x: 9.9 min_y: 0.0 max_x: 10.1 max_y: 2.2 }
  obstacles { min_x: 9.9 min_y: 3.8 max_x: 10.1 max_y: 6.0 }
}
rooms { name: "west" }
rooms { name: "east" }
doors {
  id: "d1"
  position { x: 10.0 y: 3.0 }
  width: 1.6
  heading: 1.5707963267948966
  swing: CLOCKWISE
  rooms: "west"
  rooms: "east"
  script { events { time_s: 1.5 angle: 0.0 } }
}
robots {
  id: "r1"
  kinematics: HOLONOMIC
  radius: 0.3
  max_speed: 1.0
  max_omega: 2.0
  start { x: 2.0 y: 3.0 theta: 0.0 }
  spawn_at_start: true
}
simulation { mode: PACED step_s: 0.05 seed: 3 }
)pb";

class ViewerTest : public ProcessTest {
 protected:
  ChildProcess& start_viewer(std::vector<std::string> args, bool must_keep_running = true) {
    args.insert(args.end(), {"--domain", std::to_string(domain_), "--log-dir", dir().path()});
    return start("viewer", AUTONOMY_VIEWER_BIN, args, must_keep_running);
  }

  // The port the viewer printed ("viewer: open http://127.0.0.1:PORT/").
  uint16_t await_port(const ChildProcess& viewer) {
    uint16_t port = 0;
    const std::regex line(R"(viewer: open http://127\.0\.0\.1:(\d+)/)");
    EXPECT_TRUE(await("the viewer prints its address", [&] {
      std::smatch m;
      const std::string out = read_file(viewer.log_file());
      if (!std::regex_search(out, m, line)) return false;
      port = static_cast<uint16_t>(std::stoi(m[1]));
      return true;
    }));
    return port;
  }

  // The corridor world with r1 driving west-to-east towards (8, 3) and the viewer on a free
  // port; returns that port (0 after a failure, which is then recorded).
  uint16_t start_world_with_viewer() {
    Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
    goal_topic_.emplace(participant(), dds::topics::nav_goal);
    goal_writer_.emplace(participant(), *goal_topic_);
    const std::string scenario = dir().file("viewer.pbtxt");
    write_file(scenario, kViewerScenario);
    start_simulator({"--config", scenario});
    auto& behavior = start_behavior("r1");
    auto& viewer = start_viewer({"--port", "0"});
    const uint16_t port = await_port(viewer);
    if (port == 0) return 0;
    if (!await_ready(beats, viewer) || !await_ready(beats, behavior)) {
      ADD_FAILURE() << "viewer or behavior not ready";
      return 0;
    }
    // Two readers: the behavior drives to the goal, the viewer draws it.
    if (!goal_writer_->wait_for_readers(2, kDeadline)) {
      ADD_FAILURE() << "the behavior and the viewer do not both read goals";
      return 0;
    }
    goal_writer_->write({"r1", "west-end", 8.0, 3.0, 0.2, ""});
    return port;
  }

  // Another goal for r1 (after start_world_with_viewer).
  void send_goal(const std::string& id, double x, double y) { goal_writer_->write({"r1", id, x, y, 0.2, ""}); }

  void TearDown() override {
    goal_writer_.reset();  // before the participant goes
    goal_topic_.reset();
    ProcessTest::TearDown();
  }

 private:
  std::optional<dds::Topic<msg::NavGoal>> goal_topic_;
  std::optional<dds::Writer<msg::NavGoal>> goal_writer_;
};

std::string viewer_find_program(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/usr/local/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':'))
    if (!dir.empty() && ::access((dir + "/" + name).c_str(), X_OK) == 0) return dir + "/" + name;
  return "";
}

const json* robot_in(const json& frame, const std::string& id) {
  for (const auto& r : frame["robots"])
    if (r["id"] == id) return &r;
  return nullptr;
}

const json* door_in(const json& frame, const std::string& id) {
  for (const auto& d : frame["doors"])
    if (d["id"] == id) return &d;
  return nullptr;
}

TEST_F(ViewerTest, PageFramesFollowTheRobotAndTheClosingDoor) {
  join(55);
  // A spacecraft fault as the simulator's ground truth would say it: for the side panels.
  dds::Topic<msg::SpacecraftFaultState> fault_topic(participant(), dds::topics::truth_spacecraft_fault);
  dds::Writer<msg::SpacecraftFaultState> fault_writer(participant(), fault_topic);
  msg::SpacecraftFaultState fault;
  fault.fault_id = "camera-stuck";
  fault.kind = "stuck_on";
  fault.subject = "camera";
  fault.active = true;
  fault_writer.write(fault);
  const uint16_t port = start_world_with_viewer();
  ASSERT_NE(port, 0);

  // The page itself: served by the viewer, with its script inline.
  const std::string page = WebSocketClient::http_get(port, "/");
  EXPECT_NE(page.find("HTTP/1.1 200"), std::string::npos) << page.substr(0, 200);
  EXPECT_NE(page.find("new WebSocket("), std::string::npos);

  WebSocketClient ws(port, "/ws");
  std::optional<json> map, panels;
  std::optional<std::pair<double, double>> first_position;
  bool moved = false, door_closed_drawn = false, goal_drawn = false;
  ASSERT_TRUE(await("frames with r1 moving and door d1 drawn closed", [&] {
    while (auto text = ws.next(200ms)) {
      const json frame = json::parse(*text);
      if (frame["type"] == "map") {
        map = frame;
        continue;
      }
      if (frame["type"] == "panels") {
        panels = frame;
        continue;
      }
      if (const json* r = robot_in(frame, "r1")) {
        const std::pair<double, double> p{(*r)["x"].get<double>(), (*r)["y"].get<double>()};
        if (!first_position) first_position = p;
        if (std::hypot(p.first - first_position->first, p.second - first_position->second) > 0.2) moved = true;
        if (r->contains("goal") && (*r)["goal"]["id"] == "west-end" && (*r)["goal"].contains("x")) goal_drawn = true;
      }
      if (const json* d = door_in(frame, "d1"); d && (*d)["closed"].get<bool>() && d->contains("leaf")) {
        // Closed: the leaf lies in the doorway, from the hinge (10, 2.2) to the latch (10, 3.8).
        const json& leaf = (*d)["leaf"];
        door_closed_drawn = std::abs(leaf[0].get<double>() - 10.0) < 1e-3 && std::abs(leaf[1].get<double>() - 2.2) < 1e-3 &&
                            std::abs(leaf[2].get<double>() - 10.0) < 1e-3 && std::abs(leaf[3].get<double>() - 3.8) < 1e-3;
      }
      if (moved && door_closed_drawn && goal_drawn && map && panels) return true;
    }
    return moved && door_closed_drawn && goal_drawn && map.has_value() && panels.has_value();
  })) << "moved " << moved << ", door closed drawn " << door_closed_drawn << ", goal drawn " << goal_drawn
      << ", map " << map.has_value() << ", panels " << panels.has_value();
  EXPECT_TRUE((*panels)["faults"]["camera-stuck"]["active"].get<bool>()) << panels->dump();
  EXPECT_EQ((*panels)["faults"]["camera-stuck"]["subject"], "camera");
  EXPECT_EQ((*map)["name"], "viewer-corridor");
  ASSERT_EQ((*map)["doors"].size(), 1u);
  EXPECT_EQ((*map)["doors"][0]["id"], "d1");
  EXPECT_EQ((*map)["obstacles"].size(), 2u);

  // The same state as plain JSON for scripts.
  const std::string state = WebSocketClient::http_get(port, "/state.json");
  EXPECT_NE(state.find("\"type\":\"state\""), std::string::npos) << state.substr(0, 300);
}

TEST_F(ViewerTest, PortInUseIsAClearError) {
  join(56);
  // Hold a port: the viewer must refuse it, name it and exit 1.
  const int holder = ::socket(AF_INET, SOCK_STREAM, 0);
  ASSERT_GE(holder, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::bind(holder, reinterpret_cast<const sockaddr*>(&addr), sizeof addr), 0);
  ASSERT_EQ(::listen(holder, 1), 0);
  socklen_t len = sizeof addr;
  ASSERT_EQ(::getsockname(holder, reinterpret_cast<sockaddr*>(&addr), &len), 0);
  const std::string port = std::to_string(ntohs(addr.sin_port));

  auto& viewer = start_viewer({"--port", port}, false);
  const auto status = viewer.wait_for_exit(kDeadline);
  ::close(holder);
  ASSERT_TRUE(status) << "the viewer kept running on a port in use";
  EXPECT_TRUE(status->exited);
  EXPECT_EQ(status->code, 1);
  const std::string out = read_file(viewer.log_file());
  EXPECT_NE(out.find("port " + port + " on 127.0.0.1 is in use"), std::string::npos) << out;
}

// The page in a real browser (Debian's chromium, headless, driven by tests/node/viewer_page_check.js
// over the DevTools pipe): no console errors, r1 drawn at a new position between two reads, d1
// drawn closed, a courier job's state change shown in the jobs table (the test writes the job's
// states as the courier would: queued, then underway once the page shows it queued), a
// planner's latest plan drawn as a timeline with a bar per token, and the executive's events
// drawn against that plan (a bar per executed token).
// Skipped where node or chromium is missing (deploy/test.sh installs both).
TEST_F(ViewerTest, PageInHeadlessChromiumDrawsTheMovingRobotTheClosedDoorAndAJobChange) {
  const std::string node = viewer_find_program("node");
  const std::string chromium = viewer_find_program("chromium");
  if (node.empty() || chromium.empty())
    GTEST_SKIP() << "node or chromium is not installed (deploy/test.sh installs them): the page check was skipped";
  join(57);
  dds::Topic<msg::CourierJobStatus> job_topic(participant(), dds::topics::courier_job_status);
  dds::Writer<msg::CourierJobStatus> job_writer(participant(), job_topic);
  msg::CourierJobStatus job;
  job.job_id = "job-1";
  job.state = msg::JobState::Queued;
  job.object_id = "red-letter";
  job.from = "A-111";
  job.to = "A-120";
  job_writer.write(job);
  // A planner's latest plan (transient-local, as the planner keeps it): two timelines, three tokens.
  dds::Topic<msg::LatestPlan> plan_topic(participant(), dds::topics::planner_plan);
  dds::Writer<msg::LatestPlan> plan_writer(participant(), plan_topic);
  msg::LatestPlan latest;
  latest.requester = "executive/test";
  latest.request_id = "req-1";
  latest.engine = "chronological";
  latest.plan.horizon = 100;
  latest.plan.makespan = 60;
  auto token = [](uint32_t id, const std::string& object, const std::string& predicate, int64_t start, int64_t end,
                  int64_t end_ub) {
    msg::PlanToken t;
    t.id = id;
    t.object = object;
    t.attribute = "mode";
    t.predicate = predicate;
    t.start_lb = t.start_ub = start;
    t.end_lb = end;
    t.end_ub = end_ub;
    return t;
  };
  latest.plan.tokens = {token(0, "camera", "ready", 0, 10, 20), token(1, "camera", "imaging", 10, 40, 50),
                        token(2, "engine", "thrusting", 5, 60, 60)};
  latest.plan.timelines = {{"camera.mode", {0, 1}}, {"engine.mode", {2}}};
  plan_writer.write(latest);
  const uint16_t port = start_world_with_viewer();
  ASSERT_NE(port, 0);
  // The executive running req-1 (events are volatile: written once the viewer reads them): the
  // camera ready from 0 to 1 s, imaging from 1 s on, the engine thrusting from 1 s on, a violation
  // at 2 s; three executed tokens, two of them running.
  dds::Topic<msg::ExecutiveEvent> event_topic(participant(), dds::topics::executive_event);
  dds::Writer<msg::ExecutiveEvent> event_writer(participant(), event_topic);
  ASSERT_TRUE(event_writer.wait_for_readers(1, kDeadline)) << "the viewer does not read executive events";
  uint64_t number = 0;
  auto executive_event = [&](int64_t t_s, const std::string& kind, const std::string& text) {
    event_writer.write({"executive/test", ++number, t_s, t_s * 1000000000LL, kind, text, "req-1"});
  };
  executive_event(0, "plan_executing", "req-1: plan for [0, 100) s executing");
  executive_event(0, "started", "camera.mode == ready() #0");
  executive_event(1, "ended", "camera.mode == ready() #0");
  executive_event(1, "started", "camera.mode == imaging() #1");
  executive_event(1, "started", "engine.mode == thrusting() #2");
  executive_event(2, "violation", "engine.mode: thrusting ended early");
  std::vector<std::string> args = {std::string(AUTONOMY_SOURCE_DIR) + "/tests/node/viewer_page_check.js", "--url",
                                    "http://127.0.0.1:" + std::to_string(port) + "/", "--chromium", chromium, "--door",
                                    "d1", "--job", "job-1", "--plan", "executive/test:3", "--executed",
                                    "executive/test:3", "--screenshot", dir().file("viewer.png")};
  auto& check = start("viewer_page_check", node, args, false);
  // r1 keeps driving while Chromium starts (under load that takes longer than the 6 m drive to the
  // first goal, and the page must see it move): a new goal every 4 s, west and east in turn.
  auto last_goal = std::chrono::steady_clock::now();
  int leg = 0;
  ASSERT_TRUE(await("the page shows job-1", [&] {
    if (std::chrono::steady_clock::now() - last_goal > 4s) {
      ++leg;
      send_goal("leg-" + std::to_string(leg), leg % 2 == 1 ? 3.0 : 8.0, 3.0);
      last_goal = std::chrono::steady_clock::now();
    }
    return read_file(check.log_file()).find("job job-1 seen: queued") != std::string::npos || !check.running();
  })) << check.log_tail();
  job.state = msg::JobState::Underway;
  job.phase = "to pickup";
  job.robot_id = "r1";
  job_writer.write(job);
  const auto status = check.wait_for_exit(120s);
  ASSERT_TRUE(status.has_value()) << "viewer_page_check.js did not finish\n" << check.log_tail();
  EXPECT_TRUE(status->exited && status->code == 0) << status->describe() << "\n" << check.log_tail();
}

// The Foxglove WebSocket protocol, checked by npm's client (tests/node/viewer_foxglove_check.js:
// @foxglove/ws-protocol's FoxgloveClient, decoding with @foxglove/omgidl-serialization and the
// advertised IDL only): serverInfo and the channels advertised, r1's states decoded inside the
// map at two positions, the map's transient-local state on a later subscription, and a new
// subscription after an unsubscribe. Skipped where node is missing (deploy/test.sh installs it
// and the npm packages).
TEST_F(ViewerTest, FoxgloveClientDecodesTheRobotStateWithTheAdvertisedSchema) {
  const std::string node = viewer_find_program("node");
  if (node.empty()) GTEST_SKIP() << "node is not installed (deploy/test.sh installs it): the Foxglove check was skipped";
  const std::string modules = std::string(AUTONOMY_SOURCE_DIR) + "/tests/node/node_modules/@foxglove/ws-protocol";
  struct stat st {};
  ASSERT_EQ(::stat(modules.c_str(), &st), 0)
      << "the npm packages are missing: npm ci --prefix " << AUTONOMY_SOURCE_DIR << "/tests/node (deploy/test.sh does this)";
  join(189);
  const uint16_t port = start_world_with_viewer();
  ASSERT_NE(port, 0);
  auto& check = start("viewer_foxglove_check", node,
                      {std::string(AUTONOMY_SOURCE_DIR) + "/tests/node/viewer_foxglove_check.js", "--url",
                       "ws://127.0.0.1:" + std::to_string(port) + "/", "--robot", "r1", "--width", "20", "--height", "6",
                       "--map", "viewer-corridor"},
                      false);
  // Once the client has decoded r1, send it back west: it moves whether or not it had arrived.
  ASSERT_TRUE(await("the Foxglove client decodes r1", [&] {
    return read_file(check.log_file()).find("r1 decoded at") != std::string::npos || !check.running();
  })) << check.log_tail();
  send_goal("back-west", 3.0, 3.0);
  const auto status = check.wait_for_exit(120s);
  ASSERT_TRUE(status.has_value()) << "viewer_foxglove_check.js did not finish\n" << check.log_tail();
  EXPECT_TRUE(status->exited && status->code == 0) << status->describe() << "\n" << check.log_tail();
  std::fprintf(stderr, "%s\n", check.log_tail(1500).c_str());
}

}  // namespace
}  // namespace autonomy::test
