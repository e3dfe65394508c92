#include "tools/xtypes/field_path.hpp"

#include <cctype>

namespace autonomy::xtypes {

const nlohmann::ordered_json& select_field(const nlohmann::ordered_json& j, const std::string& path) {
  const nlohmann::ordered_json* at = &j;
  std::string walked;  // for messages: where the path got to
  size_t i = 0;
  while (i < path.size()) {
    if (path[i] == '[') {
      const size_t close = path.find(']', i);
      const std::string index = path.substr(i + 1, close == std::string::npos ? std::string::npos : close - i - 1);
      if (close == std::string::npos || index.empty() ||
          index.find_first_not_of("0123456789") != std::string::npos)
        throw FieldPathError("--field " + path + ": bad index \"[" + index + "\" after \"" + walked + "\"", index, {});
      if (!at->is_array())
        throw FieldPathError("--field " + path + ": \"" + walked + "\" is not a sequence or array", index, {});
      const size_t n = std::stoul(index);
      if (n >= at->size())
        throw FieldPathError("--field " + path + ": index " + index + " beyond \"" + walked + "\" (" +
                                 std::to_string(at->size()) + " element(s) in this sample)",
                             index, {});
      at = &(*at)[n];
      walked += "[" + index + "]";
      i = close + 1;
      continue;
    }
    if (path[i] == '.') {
      ++i;
      continue;
    }
    const size_t stop = path.find_first_of(".[", i);
    const std::string name = path.substr(i, stop == std::string::npos ? std::string::npos : stop - i);
    std::vector<std::string> members;
    if (at->is_object())
      for (const auto& item : at->items()) members.push_back(item.key());
    if (!at->is_object() || !at->contains(name))
      throw FieldPathError("--field " + path + ": no member \"" + name + "\"" +
                               (walked.empty() ? std::string() : " in \"" + walked + "\""),
                           name, members);
    at = &(*at)[name];
    walked += (walked.empty() ? "" : ".") + name;
    i = stop == std::string::npos ? path.size() : stop;
  }
  return *at;
}

const Type& check_field_path(const Type& type, const std::string& path) {
  const Type* at = &type;
  std::string walked;
  size_t i = 0;
  while (i < path.size()) {
    if (path[i] == '.') {
      ++i;
      continue;
    }
    if (path[i] == '[') {
      const size_t close = path.find(']', i);
      const std::string index = path.substr(i + 1, close == std::string::npos ? std::string::npos : close - i - 1);
      if (close == std::string::npos || index.empty() || index.find_first_not_of("0123456789") != std::string::npos)
        throw FieldPathError("--field " + path + ": bad index \"[" + index + "\" after \"" + walked + "\"", index, {});
      if (at->kind != Kind::Sequence && at->kind != Kind::Array)
        throw FieldPathError("--field " + path + ": \"" + walked + "\" is not a sequence or array", index, {});
      at = at->element.get();
      walked += "[" + index + "]";
      i = close + 1;
      continue;
    }
    const size_t stop = path.find_first_of(".[", i);
    const std::string name = path.substr(i, stop == std::string::npos ? std::string::npos : stop - i);
    std::vector<std::string> members;
    const Type* found = nullptr;
    if (at->kind == Kind::Struct || at->kind == Kind::Union) {
      if (at->kind == Kind::Union) members.push_back("_d");
      if (at->kind == Kind::Union && name == "_d") found = at->discriminator.get();
      for (const auto& m : at->members) {
        members.push_back(m.name);
        if (m.name == name) found = m.type.get();
      }
    }
    if (!found)
      throw FieldPathError("--field " + path + ": no member \"" + name + "\"" +
                               (walked.empty() ? " in " + at->name : " in \"" + walked + "\""),
                           name, members);
    at = found;
    walked += (walked.empty() ? "" : ".") + name;
    i = stop == std::string::npos ? path.size() : stop;
  }
  return *at;
}

}  // namespace autonomy::xtypes
