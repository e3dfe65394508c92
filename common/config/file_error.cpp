#include "common/config/file_error.hpp"

#include <algorithm>
#include <tuple>

namespace autonomy::configfile {

std::string FileError::to_string() const {
  if (line <= 0) return source + ": " + message;
  return source + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message;
}

std::string error_text(const std::vector<FileError>& errors) {
  std::string text;
  for (const FileError& e : errors) text += e.to_string() + "\n";
  return text;
}

void sort_by_position(std::vector<FileError>& errors) {
  std::stable_sort(errors.begin(), errors.end(), [](const FileError& a, const FileError& b) {
    return std::tie(a.line, a.column) < std::tie(b.line, b.column);
  });
}

}  // namespace autonomy::configfile
