// The topic registry (tools/autonomy/topic_registry.hpp): built from the catalogue, no DDS traffic.
#include "tools/autonomy/topic_registry.hpp"

#include <gtest/gtest.h>

#include "common/dds/topics.hpp"

namespace autonomy::tools {
namespace {

TEST(TopicRegistry, HoldsEveryCatalogueTopicSortedByName) {
  const auto registry = TopicRegistry::catalogue();
  size_t catalogue_size = 0;
  dds::topics::for_each_topic([&](const auto& spec) {
    ++catalogue_size;
    const TopicEntry* e = registry.find(spec.name);
    ASSERT_NE(e, nullptr) << spec.name;
    EXPECT_EQ(e->qos, spec.qos) << spec.name;
    using T = typename std::decay_t<decltype(spec)>::Value;
    EXPECT_EQ(e->type_name, dds::DdsType<T>::type_name());
  });
  ASSERT_EQ(registry.entries().size(), catalogue_size);
  for (size_t i = 1; i < registry.entries().size(); ++i)
    EXPECT_LT(registry.entries()[i - 1].name, registry.entries()[i].name);
  EXPECT_EQ(registry.find("autonomy/no/such/topic"), nullptr);
}

TEST(TopicRegistry, DescribesTheMessage) {
  const auto registry = TopicRegistry::catalogue();
  const TopicEntry* goal = registry.find("autonomy/nav/goal");
  ASSERT_NE(goal, nullptr);
  EXPECT_EQ(goal->type_name, "autonomy::NavGoal");
  EXPECT_EQ(goal->message_name, "NavGoal");
  EXPECT_EQ(goal->key_fields, (std::vector<std::string>{"robot_id"}));
  EXPECT_EQ(goal->fields, (std::vector<std::string>{"robot_id", "goal_id", "x", "y", "tolerance", "constraint_set"}));
  const TopicEntry* heartbeat = registry.find("autonomy/heartbeat");
  ASSERT_NE(heartbeat, nullptr);
  EXPECT_EQ(heartbeat->key_fields, (std::vector<std::string>{"service", "instance"}));
}

TEST(TopicRegistry, NormalizeFillsDefaultsAndChecks) {
  const auto registry = TopicRegistry::catalogue();
  const TopicEntry* goal = registry.find("autonomy/nav/goal");
  ASSERT_NE(goal, nullptr);
  EXPECT_EQ(goal->normalize(json::parse(R"({"robot_id":"r1","goal_id":"g1","x":17,"y":9})")).dump(),
            R"({"robot_id":"r1","goal_id":"g1","x":17.0,"y":9.0,"tolerance":0.0,"constraint_set":""})");
  EXPECT_THROW(goal->normalize(json::parse(R"({"goal_id":"g1"})")), json::JsonError);
}

}  // namespace
}  // namespace autonomy::tools
