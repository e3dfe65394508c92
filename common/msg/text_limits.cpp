#include "common/msg/text_limits.hpp"

namespace autonomy::msg {

std::optional<std::string> length_problem(const char* field, const std::string& value, std::size_t max) {
  if (value.size() <= max) return std::nullopt;
  return std::string(field) + " has " + std::to_string(value.size()) + " bytes, more than " + std::to_string(max);
}

std::optional<std::string> first_length_problem(std::initializer_list<FieldLimit> fields) {
  for (const FieldLimit& f : fields)
    if (auto problem = length_problem(f.field, f.value, f.max)) return problem;
  return std::nullopt;
}

std::string clipped_for_log(const std::string& value, std::size_t keep) {
  if (value.size() <= keep) return value;
  return value.substr(0, keep) + "...(" + std::to_string(value.size()) + " bytes)";
}

std::string clipped_id(const std::string& value, std::size_t max) { return value.substr(0, max); }

}  // namespace autonomy::msg
