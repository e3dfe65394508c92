#pragma once
// `--field a.b`: one part of a printed sample. Paths are member names joined by dots, with
// [i] for an element of a sequence or array: "pose.x", "points[2].y".
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "tools/xtypes/type_tree.hpp"

namespace autonomy::xtypes {

class FieldPathError : public std::invalid_argument {
 public:
  FieldPathError(const std::string& what, std::string word, std::vector<std::string> candidates)
      : std::invalid_argument(what), word(std::move(word)), candidates(std::move(candidates)) {}
  std::string word;                     // the path element at fault
  std::vector<std::string> candidates;  // the member names at that place (for "did you mean")
};

// The part of j at path ("" is all of j). Throws FieldPathError.
const nlohmann::ordered_json& select_field(const nlohmann::ordered_json& j, const std::string& path);

// Checks path against the type before any sample arrives (indices are not checked against
// lengths); returns the type at path. Throws FieldPathError.
const Type& check_field_path(const Type& type, const std::string& path);

}  // namespace autonomy::xtypes
