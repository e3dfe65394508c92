#pragma once
// The project's IDL files as text (embedded at build time), and a topic type's schema made from
// them: one self-contained OMG IDL text (MCAP schema encoding "omgidl"), includes inlined, so a
// reader elsewhere decodes a recording without the project's files.
#include <string>
#include <vector>

namespace autonomy::recording {

struct IdlFile {
  std::string name;  // "navigation.idl"
  std::string text;
};

// Every file of idl/, in the order CMake listed them.
const std::vector<IdlFile>& idl_files();

// The IDL text that declares type_name ("autonomy::NavGoal": module path and type), with each
// #include "x.idl" replaced by that file's text (once; other preprocessor lines dropped). Throws
// std::runtime_error when no embedded file declares the type.
std::string omgidl_schema(const std::string& type_name);

}  // namespace autonomy::recording
