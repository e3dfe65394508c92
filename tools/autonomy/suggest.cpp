#include "tools/autonomy/suggest.hpp"

#include <algorithm>
#include <cctype>

namespace autonomy::tools {

namespace {

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) == std::tolower(static_cast<unsigned char>(b[j - 1]));
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (same ? 0 : 1)});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

// How far word is from candidate: the edit distance to the whole name, or to its last path
// segments (a topic given without its prefix), whichever is smaller.
size_t distance(const std::string& word, const std::string& candidate) {
  size_t best = edit_distance(word, candidate);
  for (size_t pos = candidate.find('/'); pos != std::string::npos; pos = candidate.find('/', pos + 1))
    best = std::min(best, edit_distance(word, candidate.substr(pos + 1)) + 1);
  return best;
}

}  // namespace

std::vector<std::string> nearest(const std::string& word, const std::vector<std::string>& candidates, size_t max) {
  std::vector<std::pair<size_t, std::string>> scored;
  // Close means: at most a third of the word's letters wrong (at least 2), as spell checkers do.
  const size_t limit = std::max<size_t>(2, word.size() / 3);
  for (const auto& c : candidates) {
    const size_t d = distance(word, c);
    if (d <= limit || c.find(word) != std::string::npos) scored.emplace_back(d, c);
  }
  std::stable_sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> out;
  for (const auto& [d, c] : scored) {
    if (out.size() == max) break;
    out.push_back(c);
  }
  return out;
}

std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates, size_t max) {
  const auto near = nearest(word, candidates, max);
  if (near.empty()) return "";
  std::string s = "did you mean ";
  for (size_t i = 0; i < near.size(); ++i) {
    if (i > 0) s += i + 1 == near.size() ? " or " : ", ";
    s += near[i];
  }
  return s + "?";
}

}  // namespace autonomy::tools

namespace autonomy::tools {

std::string unknown_topic_message(const std::string& who, const std::string& name,
                                  const std::vector<std::string>& topics) {
  const auto hint = did_you_mean(name, topics);
  return who + ": unknown topic \"" + name + "\"" + (hint.empty() ? "" : "; " + hint) + " (`autonomy topic list` shows " +
         std::to_string(topics.size()) + " topics)";
}

}  // namespace autonomy::tools
