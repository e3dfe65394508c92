// The walker on the project's own types, with the type information idlc generated (what
// Cyclone's type library holds once the topic exists; xtypes::compiled_topic): typed C++
// messages are written through DDS (common/dds's conversions to the idlc C types), taken as CDR
// and walked; the JSON must hold the values written, field by field. And for every catalogue
// topic, the encoder (`topic pub`) makes bytes that Cyclone takes for the type.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"
#include "common/dds/waitset.hpp"
#include "tools/recording/raw_topic.hpp"
#include "tools/xtypes/cdr_encode.hpp"
#include "tools/xtypes/cdr_json.hpp"
#include "tools/xtypes/discovered_topic.hpp"
#include "tools/xtypes/json_reader.hpp"

namespace autonomy::xtypes {
namespace {

constexpr int kProjectTypesDomain = 136;

class ProjectTypesTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { ::setenv("CYCLONEDDS_URI", AUTONOMY_LOOPBACK_URI, 1); }

  // value written as a typed sample of spec's topic, taken raw and walked with the topic's type.
  template <typename T>
  Json walk(const dds::TopicSpec<T>& spec, const T& value) {
    const auto* ours = recording::find_recordable(spec.name);
    EXPECT_NE(ours, nullptr) << spec.name;
    if (!ours) return nullptr;
    const DiscoveredTopic topic = compiled_topic(participant_.handle(), spec.name, ours->descriptor);
    EXPECT_EQ(topic.type->name, ours->type_name);
    recording::RawReader raw(participant_, *ours);
    const dds::Topic<T> typed_topic(participant_, spec);
    dds::Writer<T> writer(participant_, typed_topic);
    writer.write(value);
    std::vector<recording::RawSample> got;
    dds::WaitSet waitset(participant_);
    waitset.attach(raw.data_condition(), 1);
    while (got.empty() && !waitset.wait(std::chrono::seconds(10)).empty()) raw.take(got);
    EXPECT_EQ(got.size(), 1u) << spec.name;
    if (got.size() != 1) return nullptr;
    Json j = cdr_to_json(*topic.type, got.front().cdr);
    key_ = key_of(*topic.type, j);
    return j;
  }

  dds::Participant participant_{kProjectTypesDomain};
  Json key_;  // the key members of the last sample walked
};

TEST_F(ProjectTypesTest, HeartbeatEnumsSequencesAndKeys) {
  const msg::Heartbeat beat{"simulator", "main", "host1", 4242, msg::ServiceState::Ready, 12.5, 500,
                            {"courier", "lockstep"}, 7, 3, "office.yaml"};
  const Json j = walk(dds::topics::heartbeat, beat);
  EXPECT_EQ(j.dump(),
            R"({"service":"simulator","instance":"main","host":"host1","pid":4242,"state":"ready","uptime_s":12.5,)"
            R"("period_ms":500,"capabilities":["courier","lockstep"],"world_id":7,"clock_samples_ignored":3,)"
            R"("detail":"office.yaml"})");
  EXPECT_TRUE(j["pid"].is_number_integer());
  EXPECT_EQ(key_.dump(), R"({"service":"simulator","instance":"main"})");
}

TEST_F(ProjectTypesTest, RobotStateKinematicsAndBooleans) {
  msg::RobotState s{"r1", 5, 500, 1.5, -2.25, 0.5, 0.1, -0.2, 0.3, msg::Kinematics::Unicycle, 0.3, 1.2, 2.0, true};
  const Json j = walk(dds::topics::robot_state, s);
  EXPECT_EQ(j["robot_id"], "r1");
  EXPECT_EQ(j["tick"], 5);
  EXPECT_EQ(j["sim_time_ns"], 500);
  EXPECT_EQ(j["x"], 1.5);
  EXPECT_EQ(j["y"], -2.25);
  EXPECT_EQ(j["omega"], 0.3);
  EXPECT_EQ(j["kinematics"], "unicycle");
  EXPECT_EQ(j["max_omega"], 2.0);
  EXPECT_EQ(j["in_collision"], true);
  EXPECT_EQ(key_.dump(), R"({"robot_id":"r1"})");
}

TEST_F(ProjectTypesTest, NonFiniteDoublesAreStrings) {
  msg::GoalStatus s{"r1", "g1", msg::GoalState::Preempted, "new goal", 44, std::numeric_limits<double>::infinity()};
  Json j = walk(dds::topics::goal_status, s);
  EXPECT_EQ(j.dump(), R"({"robot_id":"r1","goal_id":"g1","state":"preempted","reason":"new goal","tick":44,)"
                      R"("distance_to_goal":"inf"})");
  s.goal_id = "g2";
  s.distance_to_goal = -std::numeric_limits<double>::infinity();
  EXPECT_EQ(walk(dds::topics::goal_status, s)["distance_to_goal"], "-inf");
  s.goal_id = "g3";
  s.state = msg::GoalState::Cancelled;
  s.distance_to_goal = std::nan("");
  j = walk(dds::topics::goal_status, s);
  EXPECT_EQ(j["distance_to_goal"], "nan");
  EXPECT_EQ(j["state"], "cancelled");
}

TEST_F(ProjectTypesTest, WorldMapNestedStructsAndRasterRuns) {
  msg::WorldMap m{"office", 60.0, 20.0, {{0, 0, 1, 1}, {2.5, 3.5, 4.5, 5.5}}, {}, {}, {}};
  m.polygons = {{"hall", {{1.0, 2.0}, {3.0, 2.0}, {2.0, 4.5}}}};
  // 3 x 2 cells, row-major from the bottom row: on the wire as runs, free first (1 free, 2
  // blocked, 3 free).
  m.rasters = {{"floor.yaml", -1.0, 0.5, 0.25, 3, 2, {0, 1, 1, 0, 0, 0}}};
  m.doors = {{"d1", 4.0, 5.0, 0.9, 1.5, -0.5}};
  const Json j = walk(dds::topics::world_map, m);
  EXPECT_EQ(j["name"], "office");
  EXPECT_EQ(j["width"], 60.0);
  EXPECT_EQ(j["obstacles"].dump(),
            R"([{"min_x":0.0,"min_y":0.0,"max_x":1.0,"max_y":1.0},{"min_x":2.5,"min_y":3.5,"max_x":4.5,"max_y":5.5}])");
  EXPECT_EQ(j["polygons"][0]["name"], "hall");
  EXPECT_EQ(j["polygons"][0]["vertices"][2].dump(), R"({"x":2.0,"y":4.5})");
  EXPECT_EQ(j["rasters"].dump(),
            R"([{"name":"floor.yaml","origin_x":-1.0,"origin_y":0.5,"resolution":0.25,"cols":3,"rows":2,"runs":[1,2,3]}])");
  EXPECT_EQ(j["doors"].dump(),
            R"([{"id":"d1","x":4.0,"y":5.0,"width":0.9,"heading":1.5,"open_angle":-0.5}])");
}

TEST_F(ProjectTypesTest, SpacecraftTelemetryNestedStructs) {
  msg::SpacecraftTelemetry t;
  t.spacecraft = "ds1";
  t.tick = 3;
  t.devices = {{"adcs", "turning", "turn", "t-1", 2}};
  t.readings = {{"battery_soc", 0.75}};
  t.attitude.turn_target = "asteroid-1";
  t.propulsion.thrust_level = 6;
  t.camera.images_taken = 2;
  t.telecom.ground_station = "dss-14";
  t.storage.capacity_mb = 64;
  t.fault_protection = {true, "no command or heartbeat of executive for 600 s", 600, 1, 601.0, 600.0};
  t.commands_busy = 3;
  const Json j = walk(dds::topics::spacecraft_telemetry, t);
  EXPECT_EQ(j["spacecraft"], "ds1");
  EXPECT_EQ(j["devices"].dump(),
            R"([{"device":"adcs","mode":"turning","confirmed_command":"turn","confirmed_command_id":"t-1","confirmed_tick":2}])");
  EXPECT_EQ(j["readings"].dump(), R"([{"sensor":"battery_soc","value":0.75}])");
  EXPECT_EQ(j["attitude"]["qw"], 1.0);
  EXPECT_EQ(j["attitude"]["turn_target"], "asteroid-1");
  EXPECT_EQ(j["propulsion"]["thrust_level"], 6);
  EXPECT_EQ(j["camera"]["images_taken"], 2);
  EXPECT_EQ(j["telecom"]["ground_station"], "dss-14");
  EXPECT_EQ(j["storage"]["capacity_mb"], 64.0);
  EXPECT_EQ(j["fault_protection"]["safe_mode"], true);
  EXPECT_EQ(j["commands_busy"], 3);
  EXPECT_EQ(key_.dump(), R"({"spacecraft":"ds1"})");
}

TEST_F(ProjectTypesTest, LatestPlanStatusAndTokens) {
  msg::LatestPlan p;
  p.requester = "executive/test";
  p.request_id = "q-7";
  p.status = msg::PlanningStatus::PlanFound;
  p.engine = "europa";
  p.plan_origin = 120;
  p.plan.horizon = 50;
  p.plan.timelines = {{"camera.mode", {0, 1}}};
  msg::PlanToken token;
  token.id = 1;
  token.predicate = "take_image";
  token.parameters = {"asteroid-1"};
  token.start_lb = 4;
  token.end_ub = 9;
  p.plan.tokens = {msg::PlanToken{}, token};
  const Json j = walk(dds::topics::planner_plan, p);
  EXPECT_EQ(j["requester"], "executive/test");
  EXPECT_EQ(j["status"], "plan_found");
  EXPECT_EQ(j["plan_origin"], 120);
  EXPECT_EQ(j["plan"]["horizon"], 50);
  EXPECT_EQ(j["plan"]["timelines"].dump(), R"([{"name":"camera.mode","tokens":[0,1]}])");
  ASSERT_EQ(j["plan"]["tokens"].size(), 2u);
  EXPECT_EQ(j["plan"]["tokens"][0]["fact"], -1);
  EXPECT_EQ(j["plan"]["tokens"][1]["predicate"], "take_image");
  EXPECT_EQ(j["plan"]["tokens"][1]["parameters"].dump(), R"(["asteroid-1"])");
  EXPECT_EQ(j["plan"]["tokens"][1]["start_lb"], 4);
  EXPECT_EQ(j["plan"]["tokens"][1]["end_ub"], 9);
}

// A value for every member; counter makes values differ.
Json sample_of(const Type& t, int& counter) {
  ++counter;
  switch (t.kind) {
    case Kind::Bool: return counter % 2 == 0;
    case Kind::Byte: case Kind::UInt8: case Kind::Int8: return counter % 100;
    case Kind::Int16: case Kind::Int32: case Kind::Int64: return -counter;
    case Kind::UInt16: case Kind::UInt32: case Kind::UInt64: return counter;
    case Kind::Float32: return counter + 0.5;
    case Kind::Float64: return counter + 0.25;
    case Kind::Char8: return "c";
    case Kind::String: return "s" + std::to_string(counter);
    case Kind::Enum: return literal_json_name(t, t.literals[counter % t.literals.size()].name);
    case Kind::Sequence: case Kind::Array: {
      Json j = Json::array();
      const size_t n = t.kind == Kind::Array ? t.dims.at(0) : 2;
      for (size_t i = 0; i < n; ++i) j.push_back(sample_of(*t.element, counter));
      return j;
    }
    case Kind::Struct: {
      Json j = Json::object();
      for (const auto& m : t.members) j[m.name] = sample_of(*m.type, counter);
      return j;
    }
    default:
      ADD_FAILURE() << "the project's IDL has no " << kind_name(t.kind);
      return nullptr;
  }
}

TEST_F(ProjectTypesTest, EncoderMakesSamplesCycloneTakesForEveryCatalogueTopic) {
  ASSERT_FALSE(recording::recordable_topics().empty());
  for (const auto& ours : recording::recordable_topics()) {
    SCOPED_TRACE(ours.name);
    const DiscoveredTopic topic = compiled_topic(participant_.handle(), ours.name, ours.descriptor);
    ASSERT_EQ(topic.type->kind, Kind::Struct);
    EXPECT_EQ(topic.type->name, ours.type_name);
    int counter = 0;
    const Json sample = sample_of(*topic.type, counter);
    const Encoded encoded = json_to_cdr(*topic.type, sample);
    // Every member given: the completed JSON is the sample (octets as numbers either way).
    EXPECT_EQ(encoded.complete.dump(), sample.dump());
    WalkOptions numbers;
    numbers.bytes = BytesStyle::Numbers;
    EXPECT_EQ(cdr_to_json(*topic.type, encoded.cdr, numbers).dump(), sample.dump());
    EXPECT_NO_THROW(recording::DecodedSample(ours.descriptor, encoded.cdr));
  }
}

}  // namespace
}  // namespace autonomy::xtypes
