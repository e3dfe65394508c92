#pragma once
// "Did you mean": the candidates nearest to a mistyped word (edit distance, with a bonus for a
// shared tail so that "goal" finds "autonomy/nav/goal"), for error messages that name the word
// at fault and what was probably meant instead of listing every name.
#include <string>
#include <vector>

namespace autonomy::tools {

// Up to max candidates, nearest first; empty when none is reasonably close.
std::vector<std::string> nearest(const std::string& word, const std::vector<std::string>& candidates, size_t max = 3);

// "did you mean a, b or c?" or "" when nothing is close.
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates, size_t max = 3);

}  // namespace autonomy::tools

namespace autonomy::tools {

// "<who>: unknown topic \"<name>\"; did you mean ...? (`autonomy topic list` shows every topic)"
std::string unknown_topic_message(const std::string& who, const std::string& name,
                                  const std::vector<std::string>& topics);

}  // namespace autonomy::tools
