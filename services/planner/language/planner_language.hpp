#pragma once
// The planner's text language (docs/planner-language.md): models and problems written close to
// the paper's notation, parsed into the model manager's protobuf messages. Syntax errors stop at
// the first one, with file:line:column; meaning (unknown names, types, bounds) is checked by
// the model manager on the message, with the locations the parser put into it.
#include <optional>
#include <string>
#include <string_view>

#include "diagnostic.hpp"
#include "idl/planner_model.pb.h"

namespace autonomy::planner {

std::optional<pb::Model> parse_model(std::string_view text, const std::string& file,
                                     Diagnostics* errors);
std::optional<pb::Problem> parse_problem(std::string_view text, const std::string& file,
                                         Diagnostics* errors);

// The whole file, or an error naming it.
std::optional<std::string> read_text_file(const std::string& path, Diagnostics* errors);

}  // namespace autonomy::planner
