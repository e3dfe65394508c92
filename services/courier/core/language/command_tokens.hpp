#pragma once
// Splitting command text into words. Case-insensitive and punctuation tolerant: letters are
// lower-cased, spaces, tabs, line breaks and punctuation other than - _ : ' separate words, a
// trailing "'s" (or "'" and the typographic ’) marks a possessive, and a dot between digits stays
// in the word ("10.30"). Control characters and bytes outside ASCII are rejected with their
// column (the typographic apostrophe ’ excepted), as is text longer than kMaxCommandBytes.
#include "services/courier/core/language/command_answer.hpp"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace autonomy::courier {

inline constexpr std::size_t kMaxCommandBytes = 512;

struct Token {
  std::string word;  // lower-case, without the possessive ending
  std::string text;  // as written, with the possessive ending
  int column = 0;    // 1-based byte column of the first character
  bool possessive = false;
};

// The words of `text`; throws RejectionError (too_long, bad_character) for unusable text.
std::vector<Token> tokenize_command(std::string_view text);

}  // namespace autonomy::courier
