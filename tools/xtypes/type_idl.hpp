#pragma once
// A type tree as OMG IDL text (what `autonomy topic type` and `autonomy interface show` print):
// every named type it uses, each before its first use, in its modules.
#include <string>

#include "tools/xtypes/type_tree.hpp"

namespace autonomy::xtypes {

std::string to_idl(const TypePtr& type);

}  // namespace autonomy::xtypes
