// QoS classes (common/dds/qos.hpp) and the topic catalogue (common/dds/topics.hpp), checked against
// the tables of docs/topics.md.
#include "common/dds/qos.hpp"
#include "common/dds/topics.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace autonomy::dds {
namespace {

struct ExpectedQos {
  QosClass cls;
  const char* name;
  dds_reliability_kind_t reliability;
  dds_durability_kind_t durability;
  int32_t depth;  // keep-last; 0: keep-all
};

// docs/topics.md, "QoS classes".
const ExpectedQos kExpected[] = {
    {QosClass::State, "state", DDS_RELIABILITY_RELIABLE, DDS_DURABILITY_TRANSIENT_LOCAL, 1},
    {QosClass::Stream, "stream", DDS_RELIABILITY_BEST_EFFORT, DDS_DURABILITY_VOLATILE, 4},
    {QosClass::Command, "command", DDS_RELIABILITY_RELIABLE, DDS_DURABILITY_VOLATILE, 32},
    {QosClass::Event, "event", DDS_RELIABILITY_RELIABLE, DDS_DURABILITY_VOLATILE, 256},
    {QosClass::Request, "request", DDS_RELIABILITY_RELIABLE, DDS_DURABILITY_VOLATILE, 64},
    {QosClass::Reply, "reply", DDS_RELIABILITY_RELIABLE, DDS_DURABILITY_VOLATILE, 64},
    {QosClass::Queue, "queue", DDS_RELIABILITY_RELIABLE, DDS_DURABILITY_VOLATILE, 0},
};

TEST(QosTest, EveryClassHasTheDocumentedPolicies) {
  for (const auto& e : kExpected) {
    SCOPED_TRACE(e.name);
    const Qos q = make_qos(e.cls);
    ASSERT_NE(q.get(), nullptr);

    dds_reliability_kind_t reliability{};
    dds_duration_t max_blocking = -1;
    ASSERT_TRUE(dds_qget_reliability(q.get(), &reliability, &max_blocking));
    EXPECT_EQ(reliability, e.reliability);
    if (e.reliability == DDS_RELIABILITY_RELIABLE) {
      EXPECT_GT(max_blocking, 0);
      EXPECT_LE(max_blocking, DDS_SECS(1));
    }

    dds_durability_kind_t durability{};
    ASSERT_TRUE(dds_qget_durability(q.get(), &durability));
    EXPECT_EQ(durability, e.durability);

    dds_history_kind_t history{};
    int32_t depth = 0;
    ASSERT_TRUE(dds_qget_history(q.get(), &history, &depth));
    EXPECT_EQ(history, e.depth > 0 ? DDS_HISTORY_KEEP_LAST : DDS_HISTORY_KEEP_ALL);
    if (e.depth > 0) {
      EXPECT_EQ(depth, e.depth);
    }
  }
}

TEST(QosTest, ToStringNamesEveryClass) {
  std::set<std::string> names;
  for (const auto& e : kExpected) {
    EXPECT_STREQ(to_string(e.cls), e.name);
    names.insert(to_string(e.cls));
  }
  EXPECT_EQ(names.size(), std::size(kExpected));
}

TEST(QosTest, ClassesAreIndependentObjects) {
  // Each call builds a fresh QoS: changing one must not affect the next.
  Qos a = make_qos(QosClass::State);
  dds_qset_history(a.get(), DDS_HISTORY_KEEP_ALL, 0);
  Qos b = make_qos(QosClass::State);
  dds_history_kind_t history{};
  int32_t depth = 0;
  ASSERT_TRUE(dds_qget_history(b.get(), &history, &depth));
  EXPECT_EQ(history, DDS_HISTORY_KEEP_LAST);
  EXPECT_EQ(depth, 1);
}

struct CatalogueEntry {
  std::string name;
  std::string type;
  std::string qos;
};

std::vector<CatalogueEntry> catalogue() {
  std::vector<CatalogueEntry> out;
  topics::for_each_topic([&](const auto& spec) {
    using T = typename std::decay_t<decltype(spec)>::Value;
    out.push_back({spec.name, DdsType<T>::type_name(), to_string(spec.qos)});
  });
  return out;
}

TEST(TopicsTest, ForEachTopicVisitsEveryTopic) {
  EXPECT_EQ(catalogue().size(), 46u);  // + 1 of fleet traffic (itinerary), + 9 of the simulator world v2, + 3 of the office, + 5 of the courier, + 6 of the spacecraft, + 5 of the planner, + 2 of the executive
}

TEST(TopicsTest, NamesAreUniqueAndPrefixed) {
  std::set<std::string> names;
  for (const auto& t : catalogue()) {
    EXPECT_EQ(t.name.rfind("autonomy/", 0), 0u) << t.name;
    EXPECT_GT(t.name.size(), std::string("autonomy/").size()) << t.name;
    EXPECT_TRUE(names.insert(t.name).second) << "duplicate topic " << t.name;
  }
}

TEST(TopicsTest, CatalogueEntriesHaveTheirTypeAndClass) {
  // A few entries pinned by hand; the docs table test below checks all of them.
  EXPECT_STREQ(topics::robot_state.name, "autonomy/robot/state");
  EXPECT_EQ(topics::robot_state.qos, QosClass::State);
  EXPECT_STREQ(topics::cmd_vel.name, "autonomy/robot/cmd_vel");
  EXPECT_EQ(topics::cmd_vel.qos, QosClass::Command);
  EXPECT_STREQ(topics::heartbeat.name, "autonomy/heartbeat");
  EXPECT_EQ(topics::heartbeat.qos, QosClass::State);
  EXPECT_EQ(topics::tick_ack.qos, QosClass::Event);
  EXPECT_EQ(topics::spawn_request.qos, QosClass::Request);
  EXPECT_EQ(topics::spawn_reply.qos, QosClass::Reply);
}

// "keep both in step": every catalogue topic is a row of docs/topics.md with the same type and
// class, and the docs list no topic the catalogue lacks.
TEST(TopicsTest, CatalogueMatchesDocsTable) {
  std::ifstream in(AUTONOMY_SOURCE_DIR "/docs/topics.md");
  ASSERT_TRUE(in) << "cannot open docs/topics.md";
  std::map<std::string, CatalogueEntry> documented;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("| `autonomy/", 0) != 0) continue;
    std::vector<std::string> cells;
    std::stringstream ss(line.substr(1));
    std::string cell;
    while (std::getline(ss, cell, '|')) {
      const auto b = cell.find_first_not_of(" `");
      const auto e = cell.find_last_not_of(" `");
      cells.push_back(b == std::string::npos ? "" : cell.substr(b, e - b + 1));
    }
    ASSERT_GE(cells.size(), 4u) << line;
    documented[cells[0]] = {cells[0], cells[1], cells[3]};
  }
  const auto entries = catalogue();
  EXPECT_EQ(documented.size(), entries.size());
  for (const auto& t : entries) {
    auto it = documented.find(t.name);
    ASSERT_NE(it, documented.end()) << t.name << " is not in docs/topics.md";
    EXPECT_EQ(it->second.type, t.type) << t.name;
    EXPECT_EQ(it->second.qos, t.qos) << t.name;
  }
}

}  // namespace
}  // namespace autonomy::dds
