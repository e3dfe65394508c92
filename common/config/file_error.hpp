#pragma once
// A problem in a file people write (scenarios, missions), located like a compiler diagnostic so
// editors can jump to it.
#include <string>
#include <vector>

namespace autonomy::configfile {

struct FileError {
  std::string source;  // file path, or a name such as "builtin:demo.pbtxt"
  int line = 0;        // 1-based; 0 when the problem concerns the whole file (cannot read it)
  int column = 0;      // 1-based
  std::string message;

  // "source:line:column: message", or "source: message" without a position.
  std::string to_string() const;
};

// One error per line, for logs and stderr.
std::string error_text(const std::vector<FileError>& errors);

// Orders errors by position, keeping the order of errors at the same position.
void sort_by_position(std::vector<FileError>& errors);

}  // namespace autonomy::configfile
