// The topic registry (tools/autonomy/topic_registry.hpp): built from the catalogue, no DDS traffic.
#include "tools/autonomy/topic_registry.hpp"

#include <gtest/gtest.h>

#include <cstring>

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
    // The descriptor idlc generated, whose type information gives the walker the type.
    ASSERT_NE(e->descriptor, nullptr) << spec.name;
    EXPECT_STREQ(e->descriptor->m_typename, e->type_name.c_str());
  });
  ASSERT_EQ(registry.entries().size(), catalogue_size);
  for (size_t i = 1; i < registry.entries().size(); ++i)
    EXPECT_LT(registry.entries()[i - 1].name, registry.entries()[i].name);
  EXPECT_EQ(registry.find("autonomy/no/such/topic"), nullptr);
}

TEST(TopicRegistry, NamesTheTopicsForHelpTexts) {
  const auto registry = TopicRegistry::catalogue();
  const auto list = registry.name_list();
  ASSERT_EQ(list.size(), registry.entries().size());
  EXPECT_EQ(list.front(), registry.entries().front().name);
  std::string joined;
  for (const auto& n : list) joined += (joined.empty() ? "" : ", ") + n;
  EXPECT_EQ(registry.names(), joined);
  const TopicEntry* goal = registry.find("autonomy/nav/goal");
  ASSERT_NE(goal, nullptr);
  EXPECT_EQ(goal->type_name, "autonomy::NavGoal");
  EXPECT_EQ(goal->qos, dds::QosClass::Command);
}

}  // namespace
}  // namespace autonomy::tools
