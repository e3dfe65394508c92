// The generic CDR walker (tools/xtypes/cdr_json.hpp) on hand-made samples: every construct of
// the project's IDL (structs, nested structs, strings, sequences of primitives, strings and
// structs, octets, enums, booleans, 64-bit integers, floats with NaN) and those of other
// processes' types (arrays of several dimensions, unions, appendable and mutable types in XCDR2,
// big-endian XCDR1); --field paths; the IDL text of a type.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "tools/xtypes/cdr_json.hpp"
#include "tools/xtypes/field_path.hpp"
#include "tools/xtypes/type_idl.hpp"
#include "tools/xtypes/test/type_builders.hpp"

namespace autonomy::xtypes {
namespace {
using namespace ::autonomy::xtypes::test;

// Builds a sample the way a CDR writer does: alignment from the end of the 4-byte header.
class CdrBytes {
 public:
  CdrBytes(bool xcdr2, bool little) : xcdr2_(xcdr2), little_(little) {
    const unsigned id = (xcdr2 ? 0x0006 : 0x0000) | (little ? 1 : 0);
    out_ = {0, static_cast<char>(id), 0, 0};
  }
  CdrBytes& u(uint64_t v, size_t n) {
    size_t a = xcdr2_ && n > 4 ? 4 : n;
    while ((out_.size() - 4) % a) out_.push_back(0);
    for (size_t i = 0; i < n; ++i) out_.push_back(static_cast<char>(little_ ? v >> (8 * i) : v >> (8 * (n - 1 - i))));
    return *this;
  }
  CdrBytes& str(const std::string& s) {
    u(s.size() + 1, 4);
    out_ += s;
    out_.push_back(0);
    return *this;
  }
  CdrBytes& f64(double d) {
    uint64_t bits;
    std::memcpy(&bits, &d, 8);
    return u(bits, 8);
  }
  CdrBytes& f32(float f) {
    uint32_t bits;
    std::memcpy(&bits, &f, 4);
    return u(bits, 4);
  }
  size_t size() const { return out_.size() - 4; }
  // Overwrites 4 bytes at payload offset at (a size header filled in once the size is known).
  void patch32(size_t at, uint32_t v) {
    for (size_t i = 0; i < 4; ++i) out_[4 + at + i] = static_cast<char>(little_ ? v >> (8 * i) : v >> (8 * (3 - i)));
  }
  const std::string& str() const { return out_; }

 private:
  bool xcdr2_, little_;
  std::string out_;
};

TypePtr goal_state() {
  auto e = make_type(Kind::Enum);
  e->name = "autonomy::GoalState";
  e->literals = {{"GOAL_ACCEPTED", 0}, {"GOAL_ACTIVE", 1}, {"GOAL_PLAN_FOUND", 2}};
  return e;
}

TEST(TopicTypeWalker, ProjectConstructsInXcdr1LittleEndian) {
  const auto point = strukt("autonomy::MapPoint", {mem("x", prim(Kind::Float64)), mem("y", prim(Kind::Float32))});
  const auto type = strukt("autonomy::Everything",
                           {mem("robot_id", prim(Kind::String), 0, true), mem("state", goal_state()),
                            mem("ok", prim(Kind::Bool)), mem("stamp", prim(Kind::Int64)),
                            mem("count", prim(Kind::UInt32)), mem("names", seq(prim(Kind::String))),
                            mem("points", seq(point)), mem("values", seq(prim(Kind::Float64))),
                            mem("blob", seq(prim(Kind::Byte))), mem("ratio", prim(Kind::Float64))});
  CdrBytes b(false, true);
  b.str("r1").u(2, 4).u(1, 1).u(static_cast<uint64_t>(-5), 8).u(7, 4);
  b.u(2, 4).str("a").str("bc");
  b.u(1, 4).f64(1.5).f32(-2.25f);
  b.u(2, 4).f64(std::numeric_limits<double>::quiet_NaN()).f64(-std::numeric_limits<double>::infinity());
  b.u(3, 4).u(0, 1).u(0xff, 1).u(0x10, 1);
  b.f64(0.125);
  WalkOptions numbers;
  numbers.bytes = BytesStyle::Numbers;
  EXPECT_EQ(cdr_to_json(*type, b.str(), numbers).dump(),
            R"({"robot_id":"r1","state":"plan_found","ok":true,"stamp":-5,"count":7,"names":["a","bc"],)"
            R"("points":[{"x":1.5,"y":-2.25}],"values":["nan","-inf"],"blob":[0,255,16],"ratio":0.125})");
  EXPECT_EQ(cdr_to_json(*type, b.str())["blob"].dump(), R"({"length":3,"base64":"AP8Q"})");
  WalkOptions hex;
  hex.bytes = BytesStyle::Hex;
  EXPECT_EQ(cdr_to_json(*type, b.str(), hex)["blob"].dump(), R"({"length":3,"hex":"00ff10"})");
}

TEST(TopicTypeWalker, BigEndianAndUnknownEnumValues) {
  const auto type = strukt("T", {mem("a", prim(Kind::Int16)), mem("b", prim(Kind::Float64)), mem("s", goal_state())});
  CdrBytes b(false, false);
  b.u(static_cast<uint16_t>(-3), 2).f64(2.5).u(9, 4);
  EXPECT_EQ(cdr_to_json(*type, b.str()).dump(), R"({"a":-3,"b":2.5,"s":9})");
}

TEST(TopicTypeWalker, ArraysOfSeveralDimensionsAndUnions) {
  auto matrix = make_type(Kind::Array);
  matrix->element = prim(Kind::Int32);
  matrix->dims = {2, 3};
  auto u = make_type(Kind::Union);
  u->name = "m::Choice";
  u->discriminator = prim(Kind::Int32);
  Member small = mem("small", prim(Kind::Int16));
  small.labels = {1, 2};
  Member text = mem("text", prim(Kind::String));
  text.is_default = true;
  u->members = {small, text};
  const auto type = strukt("m::Holder", {mem("m", matrix), mem("c1", u), mem("c2", u)});
  CdrBytes b(false, true);
  for (int i = 1; i <= 6; ++i) b.u(i, 4);
  b.u(2, 4).u(44, 2);
  b.u(7, 4).str("other");
  EXPECT_EQ(cdr_to_json(*type, b.str()).dump(),
            R"({"m":[[1,2,3],[4,5,6]],"c1":{"_d":2,"small":44},"c2":{"_d":7,"text":"other"}})");
}

TEST(TopicTypeWalker, AppendableInXcdr2SkipsMembersItDoesNotKnow) {
  const auto inner = strukt("m::Inner", {mem("v", prim(Kind::Int64))}, Extensibility::Appendable);
  const auto type = strukt("m::Outer", {mem("a", prim(Kind::Int32)), mem("list", seq(inner)), mem("z", prim(Kind::Bool))},
                           Extensibility::Appendable);
  CdrBytes b(true, true);
  b.u(0, 4);  // DHEADER of Outer, patched below
  b.u(5, 4);
  const size_t list_header = b.size();
  b.u(0, 4).u(1, 4);  // DHEADER of the sequence (its elements are not primitive), length 1
  const size_t inner_header = b.size();
  b.u(0, 4).u(9, 8).u(0xdead, 4);  // Inner with a member this reader does not know
  b.patch32(inner_header, static_cast<uint32_t>(b.size() - inner_header - 4));
  b.patch32(list_header, static_cast<uint32_t>(b.size() - list_header - 4));
  b.u(1, 1);
  b.patch32(0, static_cast<uint32_t>(b.size() - 4));
  EXPECT_EQ(cdr_to_json(*type, b.str()).dump(), R"({"a":5,"list":[{"v":9}],"z":true})");
}

TEST(TopicTypeWalker, MutableInXcdr2FindsMembersById) {
  const auto type = strukt("m::Mut", {mem("first", prim(Kind::Int32), 1), mem("name", prim(Kind::String), 2)},
                           Extensibility::Mutable);
  CdrBytes b(true, true);
  b.u(0, 4);
  b.u((4u << 28) | 2u, 4).u(8, 4).str("abc");  // name: LC 4, NEXTINT size 8
  b.u((2u << 28) | 77u, 4).u(1, 4);          // unknown member 77: skipped
  b.u((2u << 28) | 1u, 4).u(42, 4);          // first: LC 2, 4 bytes
  b.patch32(0, static_cast<uint32_t>(b.size() - 4));
  EXPECT_EQ(cdr_to_json(*type, b.str()).dump(), R"({"name":"abc","first":42})");
}

TEST(TopicTypeWalker, ShortOrForeignBytesAreErrorsNamingTheMember) {
  const auto type = strukt("T", {mem("a", prim(Kind::Int32)), mem("names", seq(prim(Kind::String)))});
  CdrBytes b(false, true);
  b.u(1, 4).u(1000000, 4);
  try {
    cdr_to_json(*type, b.str());
    FAIL() << "no error";
  } catch (const CdrError& e) {
    EXPECT_NE(std::string(e.what()).find("names"), std::string::npos) << e.what();
  }
  EXPECT_THROW(cdr_to_json(*type, std::string("\x00\x01", 2)), CdrError);
  EXPECT_THROW(cdr_to_json(*type, std::string("\x12\x34\x00\x00", 4)), CdrError);
}

TEST(TopicTypeWalker, FieldPathsSelectAndNameTheWordAtFault) {
  const auto j = Json::parse(R"({"pose":{"x":1,"y":2},"points":[{"x":5},{"x":6}]})");
  EXPECT_EQ(select_field(j, "pose.y").dump(), "2");
  EXPECT_EQ(select_field(j, "points[1].x").dump(), "6");
  EXPECT_EQ(select_field(j, "").dump(), j.dump());
  try {
    select_field(j, "pose.z");
    FAIL() << "no error";
  } catch (const FieldPathError& e) {
    EXPECT_EQ(e.word, "z");
    EXPECT_EQ(e.candidates, (std::vector<std::string>{"x", "y"}));
    EXPECT_NE(std::string(e.what()).find("\"pose\""), std::string::npos) << e.what();
  }
  EXPECT_THROW(select_field(j, "points[7].x"), FieldPathError);
  EXPECT_THROW(select_field(j, "pose[0]"), FieldPathError);
}

TEST(TopicTypeWalker, IdlTextListsUsedTypesFirst) {
  const auto point = strukt("autonomy::MapPoint", {mem("x", prim(Kind::Float64))});
  auto bounded = make_type(Kind::String);
  bounded->bound = 8;
  const auto type = strukt("autonomy::Map",
                           {mem("id", bounded, 0, true), mem("points", seq(point)), mem("state", goal_state())});
  EXPECT_EQ(to_idl(type),
            "module autonomy {\n  @final\n  struct MapPoint {\n    double x;\n  };\n};\n\n"
            "module autonomy {\n  enum GoalState {\n    GOAL_ACCEPTED,\n    GOAL_ACTIVE,\n    GOAL_PLAN_FOUND\n  };\n};\n\n"
            "module autonomy {\n  @final\n  struct Map {\n    @key string<8> id;\n"
            "    sequence<::autonomy::MapPoint> points;\n    ::autonomy::GoalState state;\n  };\n};\n");
}

}  // namespace
}  // namespace autonomy::xtypes
