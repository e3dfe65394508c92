#pragma once
// Restricted English commands for the office courier (the grammar, with examples and every
// rejection, is docs/courier-language.md):
//   put the red letter on the meeting table in room A-111 on the desk in room A-120
//   deliver the green book from the librarian's desk in room A-110 to the desk in room A-114
//   pick up the letter from Wolfram and deliver it by 10:30
//   cancel job j7 / change the destination of job j7 to Michael / deliver job j7 by 11:30
// Pure: the office knowledge and the current simulated time are arguments. Every text gets an
// answer (accepted with its interpretation, or rejected with a reason, the word and its column);
// nothing throws.
#include "services/courier/core/language/command_answer.hpp"

#include <string_view>

namespace autonomy::courier {

struct OfficeKnowledge;

// `now_sim_s` is simulated time; knowledge.clock turns it into the time of day deadlines are
// compared with.
CommandAnswer interpret_command(std::string_view text, const OfficeKnowledge& knowledge,
                                double now_sim_s);

}  // namespace autonomy::courier
