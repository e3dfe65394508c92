#pragma once
// A problem in a scenario file, located like a compiler diagnostic so editors can jump to it.
#include <string>

namespace autonomy::sim {

struct ScenarioError {
  std::string source;  // file path, or "builtin:demo.pbtxt"
  int line = 0;        // 1-based; 0 when the problem concerns the whole file (cannot read it)
  int column = 0;      // 1-based
  std::string message;

  // "source:line:column: message", or "source: message" without a position.
  std::string to_string() const;
};

}  // namespace autonomy::sim
