#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

#include "tools/recording/idl_text.hpp"

namespace autonomy::recording {

namespace {

const IdlFile* file_named(const std::string& name) {
  for (const auto& f : idl_files())
    if (f.name == name) return &f;
  return nullptr;
}

// The file's text with includes inlined (each file at most once: include guards are not needed).
void inline_file(const IdlFile& f, std::set<std::string>& done, std::string& out) {
  if (!done.insert(f.name).second) return;
  static const std::regex include(R"(^\s*#\s*include\s*["<]([^">]+)[">])");
  std::istringstream in(f.text);
  std::string line;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_search(line, m, include)) {
      const std::string target = m[1].str().substr(m[1].str().find_last_of('/') + 1);
      const IdlFile* inc = file_named(target);
      if (!inc) throw std::runtime_error(f.name + ": #include \"" + m[1].str() + "\" is not among the embedded IDL files");
      inline_file(*inc, done, out);
      continue;
    }
    if (line.find_first_not_of(" \t") != std::string::npos && line[line.find_first_not_of(" \t")] == '#')
      continue;  // #pragma, include guards: a schema is one plain text
    out += line;
    out += '\n';
  }
}

}  // namespace

std::string omgidl_schema(const std::string& type_name) {
  const auto sep = type_name.rfind("::");
  const std::string simple = sep == std::string::npos ? type_name : type_name.substr(sep + 2);
  const std::regex declares("\\b(struct|union|enum|bitmask)\\s+" + simple + "\\b|\\btypedef\\b[^;]*\\b" + simple +
                            "\\s*(\\[[^;]*)?;");
  for (const auto& f : idl_files()) {
    if (!std::regex_search(f.text, declares)) continue;
    std::set<std::string> done;
    std::string out;
    inline_file(f, done, out);
    return out;
  }
  throw std::runtime_error("no IDL file of this build declares " + type_name);
}

}  // namespace autonomy::recording
