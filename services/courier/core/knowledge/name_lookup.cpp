#include "services/courier/core/knowledge/name_lookup.hpp"

#include "services/courier/core/knowledge/office_knowledge.hpp"

#include <algorithm>
#include <numeric>

namespace autonomy::courier {

namespace {
char lower(char c) {
  return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}
}  // namespace

std::string lower_case(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = lower(c);
  return out;
}

bool same_name(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (lower(a[i]) != lower(b[i])) return false;
  return true;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Three rows of the optimal-string-alignment table suffice: row i needs rows i-1 and i-2.
  const std::size_t n = b.size();
  std::vector<std::size_t> before(n + 1), previous(n + 1), current(n + 1);
  std::iota(previous.begin(), previous.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= n; ++j) {
      const bool same = lower(a[i - 1]) == lower(b[j - 1]);
      current[j] =
          std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (same ? 0 : 1)});
      if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) &&
          lower(a[i - 2]) == lower(b[j - 1]))
        current[j] = std::min(current[j], before[j - 2] + 1);
    }
    std::swap(before, previous);
    std::swap(previous, current);
  }
  return previous[n];
}

std::vector<std::string> closest_names(std::string_view word,
                                       const std::vector<std::string>& candidates,
                                       std::size_t limit) {
  const std::size_t allowed = word.size() <= 4 ? 1 : std::min<std::size_t>(3, word.size() / 3);
  std::vector<std::pair<std::size_t, std::size_t>> scored;  // (distance, candidate index)
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const std::size_t d = edit_distance(word, candidates[i]);
    if (d <= allowed) scored.emplace_back(d, i);
  }
  std::stable_sort(scored.begin(), scored.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::string> out;
  for (const auto& [d, i] : scored) {
    if (out.size() == limit) break;
    const bool seen = std::any_of(
        out.begin(), out.end(), [&](const std::string& s) { return same_name(s, candidates[i]); });
    if (!seen) out.push_back(candidates[i]);
  }
  return out;
}

std::string did_you_mean(const std::vector<std::string>& suggestions) {
  if (suggestions.empty()) return {};
  std::string text = "did you mean ";
  for (std::size_t i = 0; i < suggestions.size(); ++i) {
    if (i > 0) text += i + 1 == suggestions.size() ? " or " : ", ";
    text += suggestions[i];
  }
  return text + "?";
}

NameMeaning lookup_name(const OfficeKnowledge& knowledge, std::string_view name) {
  NameMeaning meaning;
  meaning.place = knowledge.find_place(name);
  if (const Person* p = knowledge.find_person(name))
    meaning.people = {p};
  else
    meaning.people = knowledge.people_with_role(name);
  return meaning;
}

std::vector<std::string> known_names(const OfficeKnowledge& knowledge, bool places_only) {
  std::vector<std::string> names;
  for (const Place& p : knowledge.places) {
    names.push_back(p.name);
    names.insert(names.end(), p.aliases.begin(), p.aliases.end());
  }
  if (places_only) return names;
  for (const Person& p : knowledge.people) {
    names.push_back(p.name);
    names.insert(names.end(), p.roles.begin(), p.roles.end());
  }
  return names;
}

}  // namespace autonomy::courier
