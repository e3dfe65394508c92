#pragma once
// One mistake in a model or problem, at the place it was written.
#include <string>
#include <vector>

namespace autonomy::planner {

struct Diagnostic {
  std::string file;
  unsigned line = 0, column = 0;
  std::string message;
  // "file:line:column: message" (the form compilers use, so editors can jump to it).
  std::string to_string() const;
};

using Diagnostics = std::vector<Diagnostic>;
std::string to_string(const Diagnostics& diagnostics);

}  // namespace autonomy::planner
