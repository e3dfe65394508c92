// The walker against the per-message tables of tools/json, for every topic of the catalogue:
// a sample with a value in every member (two elements in every sequence) is written through
// the tables (JSON -> C++ -> the idlc C type -> DDS), taken as CDR, and walked with the type
// that Cyclone's type library holds for the topic (the type information idlc generated). The
// walker's JSON must be what the tables make of the same sample.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "common/dds/topics.hpp"
#include "tools/autonomy/topic_registry.hpp"
#include "tools/recording/raw_topic.hpp"
#include "tools/xtypes/cdr_encode.hpp"
#include "tools/xtypes/cdr_json.hpp"
#include "tools/xtypes/type_lookup.hpp"

namespace autonomy::xtypes {
namespace {

constexpr int kProjectTypesDomain = 136;

// Types whose C++ form (what the tables print) is not their wire form: MapRaster's cells are
// `blocked` bytes in C++ and run lengths (`runs`) on the wire (common/dds converts). The walker
// prints the wire; these are left empty in the generated samples.
bool wire_differs_from_tables(const Type& t) { return t.name == "autonomy::MapRaster"; }

// A value for every member, in the tables' JSON conventions; counter makes values differ.
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
      const size_t n = t.kind == Kind::Array ? t.dims.at(0) : wire_differs_from_tables(*t.element) ? 0 : 2;
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

TEST(TopicTypeWalkerProjectTypes, PrintsWhatTheTablesPrintForEveryCatalogueTopic) {
  ::setenv("CYCLONEDDS_URI", AUTONOMY_LOOPBACK_URI, 1);
  dds::Participant participant(kProjectTypesDomain);
  const auto registry = tools::TopicRegistry::catalogue();
  TypeLookup lookup(participant.handle(), DDS_SECS(1));
  ASSERT_FALSE(registry.entries().empty());
  for (const auto& entry : registry.entries()) {
    SCOPED_TRACE(entry.name);
    const auto* recordable = recording::find_recordable(entry.name);
    ASSERT_NE(recordable, nullptr);
    recording::RawReader raw(participant, *recordable);
    const auto qos = dds::make_qos(entry.qos);
    const auto writer = entry.make_writer(participant, qos.get());
    const TypePtr type = lookup.resolve_entity(writer->handle());
    ASSERT_EQ(type->kind, Kind::Struct);
    EXPECT_EQ(type->name, entry.type_name);
    std::vector<std::string> names, keys;
    for (const auto& m : type->members) {
      names.push_back(m.name);
      if (m.key) keys.push_back(m.name);
    }
    EXPECT_EQ(names, entry.fields);
    EXPECT_EQ(keys, entry.key_fields);

    int counter = 0;
    const Json sample = sample_of(*type, counter);
    const json::Json expected = entry.normalize(json::Json::parse(sample.dump()));  // throws on a name the tables do not know
    writer->write(expected);
    std::vector<recording::RawSample> got;
    for (int i = 0; i < 200 && got.empty(); ++i) {
      raw.take(got);
      if (got.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ASSERT_EQ(got.size(), 1u);
    WalkOptions numbers;
    numbers.bytes = BytesStyle::Numbers;  // the tables print octets as numbers
    EXPECT_EQ(cdr_to_json(*type, got.front().cdr, numbers).dump(), expected.dump());

    // The encoder (topic pub for any topic) makes bytes that Cyclone accepts for the type and
    // that walk back to the same JSON.
    const Encoded encoded = json_to_cdr(*type, sample);
    EXPECT_EQ(encoded.complete.dump(), expected.dump());
    EXPECT_EQ(cdr_to_json(*type, encoded.cdr, numbers).dump(), expected.dump());
    EXPECT_NO_THROW(recording::DecodedSample(recordable->descriptor, encoded.cdr));
  }
}

TEST(TopicTypeEncoder, ChecksTheJsonAndFillsDefaults) {
  int counter = 0;
  auto e = make_type(Kind::Enum);
  e->name = "m::Mode";
  e->literals = {{"MODE_IDLE", 0}, {"MODE_BUSY", 1}};
  auto blob = make_type(Kind::Sequence);
  blob->element = make_type(Kind::Byte);
  auto t = make_type(Kind::Struct);
  t->name = "m::T";
  t->extensibility = Extensibility::Appendable;
  Member id{"id", 0, make_type(Kind::String), true};
  Member mode{"mode", 1, e};
  Member small{"small", 2, make_type(Kind::UInt8)};
  Member bytes{"bytes", 3, blob};
  t->members = {id, mode, small, bytes};
  (void)counter;
  const auto enc = json_to_cdr(*t, Json::parse(R"({"id":"a","bytes":{"base64":"AP8Q"}})"));
  EXPECT_EQ(enc.complete.dump(), R"({"id":"a","mode":"idle","small":0,"bytes":[0,255,16]})");
  EXPECT_EQ(cdr_to_json(*t, enc.cdr).dump(), R"({"id":"a","mode":"idle","small":0,"bytes":{"length":3,"base64":"AP8Q"}})");
  auto error_of = [&](const char* text) {
    try {
      json_to_cdr(*t, Json::parse(text));
    } catch (const CdrError& err) {
      return std::string(err.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error_of(R"({"mode":"busy"})").find("id: missing key member"), std::string::npos);
  EXPECT_NE(error_of(R"({"id":"a","small":300})").find("small: 300 is out of range"), std::string::npos);
  EXPECT_NE(error_of(R"({"id":"a","mode":"asleep"})").find("one of idle, busy"), std::string::npos);
  EXPECT_NE(error_of(R"({"id":"a","smal":1})").find("smal: m::T has no such member"), std::string::npos);
  EXPECT_NE(error_of(R"({"id":7})").find("id: expected a string"), std::string::npos);
}

}  // namespace
}  // namespace autonomy::xtypes
