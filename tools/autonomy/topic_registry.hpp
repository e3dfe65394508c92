#pragma once
// The catalogue's topics by name (common/dds/topics.hpp, as tools/recording lists them: name,
// DDS type name, idlc descriptor, QoS class), for the commands' lookups and help texts. What a
// topic's samples look like as JSON is not here: it comes from the topic's type information and
// the walker (tools/xtypes), the same for the catalogue's topics and any other process's.
#include <string>
#include <string_view>
#include <vector>

#include "tools/recording/raw_topic.hpp"

namespace autonomy::tools {

using TopicEntry = recording::RecordableTopic;

class TopicRegistry {
 public:
  // Every topic of the catalogue, sorted by name.
  static TopicRegistry catalogue();

  const TopicEntry* find(std::string_view name) const;
  const std::vector<TopicEntry>& entries() const { return *entries_; }
  // "a, b, c": for help texts.
  std::string names() const;
  std::vector<std::string> name_list() const;

 private:
  explicit TopicRegistry(const std::vector<TopicEntry>& entries) : entries_(&entries) {}
  const std::vector<TopicEntry>* entries_;
};

}  // namespace autonomy::tools
