#pragma once
// Finding what a name in a command means, and what the user probably meant when it means nothing
// ("no place 'A-122'; did you mean ?"). Suggestions come from the optimal string
// alignment distance (Levenshtein with adjacent transpositions, so "A-112" is one edit from both
// "A-111" and "A-121"), case-insensitive.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace autonomy::courier {

struct OfficeKnowledge;
struct Place;
struct Person;

std::string lower_case(std::string_view text);
bool same_name(std::string_view a, std::string_view b);  // case-insensitive equality

// Edits (insert, delete, substitute, swap neighbours) between a and b, case-insensitive.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidates closest to `word` within a distance that grows with its length (1 for up to 4
// characters, then a third of the length, at most 3), nearest first, then in candidate order;
// at most `limit`, without duplicates. Empty when nothing is close.
std::vector<std::string> closest_names(std::string_view word,
                                       const std::vector<std::string>& candidates,
                                       std::size_t limit = 3);

// "did you mean ?" / "did you mean A, B or C?"; empty for no suggestions.
std::string did_you_mean(const std::vector<std::string>& suggestions);

// What a single name means in the office: a place (or alias), a room, a person by name, or the
// people having it as a role. A name may be a person and a place at once only if the knowledge
// allows it (knowledge_problems forbids it).
struct NameMeaning {
  const Place* place = nullptr;       // set for places and rooms (kind room)
  std::vector<const Person*> people;  // by name (one) or by role (one or more)
  bool empty() const { return place == nullptr && people.empty(); }
};
NameMeaning lookup_name(const OfficeKnowledge& knowledge, std::string_view name);

// Every name lookup_name understands (place names and aliases, person names, roles), for
// suggestions; `places_only` leaves people out.
std::vector<std::string> known_names(const OfficeKnowledge& knowledge, bool places_only = false);

}  // namespace autonomy::courier
