#pragma once
// Checking office knowledge before the courier interprets commands against it: names are matched
// case-insensitively and across kinds (a word in a command may name a place, a person or a role),
// so every name must mean one thing.
#include <string>
#include <vector>

namespace autonomy::courier {

struct OfficeKnowledge;

// Every problem, one sentence each, in a stable order; empty when usable. Checks: non-empty names
// of printable ASCII without spaces at either end; place names and aliases unique among
// themselves and not equal to a person's name; rooms naming room places (rooms are in no room);
// finite positions; people unique, at known places, presence intervals ordered, non-overlapping and
// within the day, handover times finite and >= 0; roles non-empty; stations at known places, once
// each, with usable handover times; objects with unique ids and a kind, lying at known places,
// not both lying somewhere and carried, addressed to known people; day start in [0, 86400).
std::vector<std::string> knowledge_problems(const OfficeKnowledge& knowledge);

}  // namespace autonomy::courier
