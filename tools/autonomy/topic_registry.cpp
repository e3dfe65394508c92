#include "tools/autonomy/topic_registry.hpp"

namespace autonomy::tools {

TopicRegistry TopicRegistry::catalogue() { return TopicRegistry(recording::recordable_topics()); }

const TopicEntry* TopicRegistry::find(std::string_view name) const {
  for (const auto& e : *entries_)
    if (e.name == name) return &e;
  return nullptr;
}

std::string TopicRegistry::names() const {
  std::string out;
  for (const auto& e : *entries_) out += (out.empty() ? "" : ", ") + e.name;
  return out;
}

std::vector<std::string> TopicRegistry::name_list() const {
  std::vector<std::string> out;
  for (const auto& e : *entries_) out.push_back(e.name);
  return out;
}

}  // namespace autonomy::tools
