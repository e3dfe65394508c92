#pragma once
// The structured delivery request, for programs: the same checks and the same completion from
// knowledge as the text command (delivery_completion), so that "deliver the green book from the
// librarian to Anna" and {kind: book, colour: green, from: librarian, to: Anna} get identical
// interpretations. Rejections name the field at fault instead of a column.
#include "services/courier/core/language/command_answer.hpp"

#include <cstddef>
#include <optional>
#include <string>

namespace autonomy::courier {

struct OfficeKnowledge;

inline constexpr std::size_t kMaxFieldBytes = 128;

// Every field is optional, but what is given is checked, and what is missing must follow from
// knowledge: an object (object_id, or kind with an optional colour), where from and where to.
struct StructuredRequest {
  std::string object_id;  // a known object's id
  std::string kind;       // "letter"
  std::string colour;     // "red"
  std::string from;       // a place name or alias, a room, a person's name or role
  std::string to;         // the same
  std::string deadline;   // "HH:MM" or "HH:MM:SS", a time of the current day; empty for none
  std::optional<double> deadline_s;  // seconds of the day instead of `deadline` (not both)
};

// `now_sim_s` is simulated time, as for interpret_command. Never throws.
CommandAnswer interpret_request(const StructuredRequest& request, const OfficeKnowledge& knowledge,
                                double now_sim_s);

}  // namespace autonomy::courier
