// The encoder (tools/xtypes/cdr_encode.hpp, `autonomy topic pub` for every topic) on hand-made
// type trees shaped like the project's: what it takes (enum names, non-finite doubles, numbers
// with a zero fraction, octets as base64 or hex), what it fills in, and its errors, which name
// the member path, what was expected and what was found.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "tools/xtypes/cdr_encode.hpp"
#include "tools/xtypes/test/type_builders.hpp"

namespace autonomy::xtypes {
namespace {
using namespace ::autonomy::xtypes::test;

TypePtr service_state() {
  auto e = make_type(Kind::Enum);
  e->name = "autonomy::ServiceState";
  e->literals = {{"SERVICE_STARTING", 0}, {"SERVICE_READY", 1}, {"SERVICE_STOPPING", 2}};
  return e;
}

TypePtr nav_goal() {
  return strukt("autonomy::NavGoal",
                {mem("robot_id", prim(Kind::String), 0, true), mem("goal_id", prim(Kind::String)),
                 mem("x", prim(Kind::Float64)), mem("y", prim(Kind::Float64)), mem("tolerance", prim(Kind::Float64)),
                 mem("constraint_set", prim(Kind::String))},
                Extensibility::Appendable);
}

TypePtr heartbeat() {
  return strukt("autonomy::Heartbeat",
                {mem("service", prim(Kind::String), 0, true), mem("instance", prim(Kind::String), 0, true),
                 mem("pid", prim(Kind::Int32)), mem("state", service_state()), mem("in_collision", prim(Kind::Bool)),
                 mem("commands_sent", prim(Kind::UInt32)), mem("tick", prim(Kind::Int64))},
                Extensibility::Appendable);
}

TypePtr world_map() {
  const auto rect = strukt("autonomy::Rect", {mem("min_x", prim(Kind::Float64)), mem("min_y", prim(Kind::Float64)),
                                              mem("max_x", prim(Kind::Float64)), mem("max_y", prim(Kind::Float64))});
  return strukt("autonomy::WorldMap",
                {mem("name", prim(Kind::String)), mem("obstacles", seq(rect)),
                 mem("lockstep_participants", seq(prim(Kind::String)))});
}

std::string error_of(const TypePtr& type, const std::string& text) {
  try {
    json_to_cdr(*type, parse_json(text));
  } catch (const CdrError& e) {
    return e.what();
  }
  return "(no error)";
}

// Encoded, then walked back: what `topic echo` prints of what `topic pub` wrote.
std::string round_trip(const TypePtr& type, const std::string& text) {
  const Encoded e = json_to_cdr(*type, parse_json(text));
  const std::string walked = cdr_to_json(*type, e.cdr).dump();
  EXPECT_EQ(walked, e.complete.dump());
  return walked;
}

TEST(TopicTypeEncoder, FillsLeftOutMembersAndKeepsTheTypesOrder) {
  EXPECT_EQ(round_trip(nav_goal(), R"({"y":9,"robot_id":"r1","goal_id":"g1","x":17})"),
            R"({"robot_id":"r1","goal_id":"g1","x":17.0,"y":9.0,"tolerance":0.0,"constraint_set":""})");
  EXPECT_EQ(round_trip(heartbeat(), R"({"service":"sim","instance":"main"})"),
            R"({"service":"sim","instance":"main","pid":0,"state":"starting","in_collision":false,"commands_sent":0,"tick":0})");
  EXPECT_EQ(round_trip(world_map(), "{}"), R"({"name":"","obstacles":[],"lockstep_participants":[]})");
}

TEST(TopicTypeEncoder, EnumsByLowerCaseOrIdlName) {
  EXPECT_NE(round_trip(heartbeat(), R"({"service":"a","instance":"b","state":"ready"})").find(R"("state":"ready")"),
            std::string::npos);
  const Encoded by_idl = json_to_cdr(*heartbeat(), parse_json(R"({"service":"a","instance":"b","state":"SERVICE_STOPPING"})"));
  EXPECT_EQ(by_idl.complete["state"], "stopping");
  EXPECT_EQ(error_of(heartbeat(), R"({"service":"a","instance":"b","state":"READY"})"),
            "state: expected one of starting, ready, stopping, got string \"READY\"");
}

TEST(TopicTypeEncoder, NonFiniteDoublesAsStrings) {
  const Encoded e = json_to_cdr(*nav_goal(), parse_json(R"({"robot_id":"r1","x":"inf","y":"-inf","tolerance":"nan"})"));
  EXPECT_EQ(e.complete["x"], "inf");
  EXPECT_EQ(e.complete["y"], "-inf");
  EXPECT_EQ(e.complete["tolerance"], "nan");
  // The bytes hold the IEEE values: robot_id "r1" (4 + 3 bytes) and goal_id "" (4 + 1) after
  // the appendable struct's size word, then x at the next multiple of 4 (XCDR2).
  double x = 0;
  std::memcpy(&x, e.cdr.data() + 4 + 4 + 8 + 8, 8);
  EXPECT_TRUE(std::isinf(x) && x > 0);
  EXPECT_EQ(cdr_to_json(*nav_goal(), e.cdr)["tolerance"], "nan");
}

TEST(TopicTypeEncoder, NumbersWithAZeroFractionAreIntegers) {
  const Encoded e = json_to_cdr(*heartbeat(), parse_json(R"({"service":"a","instance":"b","tick":12.0,"pid":-3.0})"));
  EXPECT_EQ(e.complete["tick"], 12);
  EXPECT_TRUE(e.complete["tick"].is_number_integer());
  EXPECT_EQ(e.complete["pid"], -3);
}

TEST(TopicTypeEncoder, ErrorsNameThePathTheExpectedAndTheFound) {
  EXPECT_EQ(error_of(nav_goal(), R"({"robot_id":"r1",)").rfind("invalid JSON: ", 0), 0u);
  EXPECT_EQ(error_of(nav_goal(), "[1,2]"), "message: expected an object, got an array");
  EXPECT_EQ(error_of(nav_goal(), R"({"goal_id":"g1","x":1})"), "robot_id: missing key member");
  EXPECT_EQ(error_of(heartbeat(), R"({"service":"simulator"})"), "instance: missing key member");
  EXPECT_EQ(error_of(nav_goal(), R"({"robot_id":"r1","x":"abc"})"),
            R"(x: expected a number (or "nan", "inf", "-inf"), got string "abc")");
  EXPECT_EQ(error_of(nav_goal(), R"({"robot_id":7})"), "robot_id: expected a string, got number 7");
  EXPECT_EQ(error_of(heartbeat(), R"({"service":"a","instance":"b","in_collision":1})"),
            "in_collision: expected true or false, got number 1");
  EXPECT_EQ(error_of(nav_goal(), R"({"robot_id":"r1","z":1})"),
            "z: autonomy::NavGoal has no such member (members: robot_id, goal_id, x, y, tolerance, constraint_set)");
}

TEST(TopicTypeEncoder, IntegersOutOfRangeOrWithAFraction) {
  EXPECT_EQ(error_of(heartbeat(), R"({"service":"a","instance":"b","commands_sent":-1})"),
            "commands_sent: -1 is out of range [0, 4294967295]");
  EXPECT_EQ(error_of(heartbeat(), R"({"service":"a","instance":"b","tick":1.5})"),
            "tick: expected an integer in [-9223372036854775808, 9223372036854775807], got number 1.5");
  EXPECT_EQ(error_of(heartbeat(), R"({"service":"a","instance":"b","pid":4294967296})"),
            "pid: 4294967296 is out of range [-2147483648, 2147483647]");
}

TEST(TopicTypeEncoder, NestedPaths) {
  EXPECT_EQ(error_of(world_map(), R"({"obstacles":[{"min_x":0},{"max_y":"x"}]})"),
            R"(obstacles[1].max_y: expected a number (or "nan", "inf", "-inf"), got string "x")");
  EXPECT_EQ(error_of(world_map(), R"({"lockstep_participants":["a",2]})"),
            "lockstep_participants[1]: expected a string, got number 2");
  EXPECT_EQ(error_of(world_map(), R"({"obstacles":{}})"), "obstacles: expected an array, got an object");
  EXPECT_EQ(round_trip(world_map(), R"({"obstacles":[{"max_x":1},{"min_y":2}]})"),
            R"({"name":"","obstacles":[{"min_x":0.0,"min_y":0.0,"max_x":1.0,"max_y":0.0},)"
            R"({"min_x":0.0,"min_y":2.0,"max_x":0.0,"max_y":0.0}],"lockstep_participants":[]})");
}

TEST(TopicTypeEncoder, OctetsAsNumbersBase64OrHex) {
  auto e = make_type(Kind::Enum);
  e->name = "m::Mode";
  e->literals = {{"MODE_IDLE", 0}, {"MODE_BUSY", 1}};
  const auto t = strukt("m::T",
                        {mem("id", prim(Kind::String), 0, true), mem("mode", e, 1), mem("small", prim(Kind::UInt8), 2),
                         mem("bytes", seq(prim(Kind::Byte)), 3)},
                        Extensibility::Appendable);
  const auto enc = json_to_cdr(*t, Json::parse(R"({"id":"a","bytes":{"base64":"AP8Q"}})"));
  EXPECT_EQ(enc.complete.dump(), R"({"id":"a","mode":"idle","small":0,"bytes":[0,255,16]})");
  EXPECT_EQ(cdr_to_json(*t, enc.cdr).dump(), R"({"id":"a","mode":"idle","small":0,"bytes":{"length":3,"base64":"AP8Q"}})");
  EXPECT_EQ(json_to_cdr(*t, Json::parse(R"({"id":"a","bytes":{"hex":"00ff10"}})")).cdr, enc.cdr);
  EXPECT_EQ(json_to_cdr(*t, Json::parse(R"({"id":"a","bytes":[0,255,16]})")).cdr, enc.cdr);
  EXPECT_EQ(error_of(t, R"({"id":"a","small":300})"), "small: 300 is out of range [0, 255]");
  EXPECT_EQ(error_of(t, R"({"id":"a","mode":"asleep"})"), "mode: expected one of idle, busy, got string \"asleep\"");
}

}  // namespace
}  // namespace autonomy::xtypes
