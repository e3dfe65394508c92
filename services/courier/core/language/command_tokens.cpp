#include "services/courier/core/language/command_tokens.hpp"

#include "services/courier/core/language/delivery_completion.hpp"

#include <cstdio>

namespace autonomy::courier {

namespace {

bool is_alnum(unsigned char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
}
bool is_digit(unsigned char c) {
  return c >= '0' && c <= '9';
}

// The typographic apostrophe U+2019 in UTF-8, which mail programs put into "librarian’s".
bool is_curly_apostrophe(std::string_view text, std::size_t i) {
  return text.substr(i, 3) == "\xE2\x80\x99";
}

std::string byte_name(unsigned char c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "0x%02X", c);
  return buf;
}

}  // namespace

std::vector<Token> tokenize_command(std::string_view text) {
  if (text.size() > kMaxCommandBytes)
    reject(RejectReason::too_long,
           "the command has " + std::to_string(text.size()) + " bytes; at most " +
               std::to_string(kMaxCommandBytes) + " are read",
           {std::string(text.substr(kMaxCommandBytes, 16)), static_cast<int>(kMaxCommandBytes) + 1,
            ""});
  std::vector<Token> tokens;
  Token current;
  auto finish = [&] {
    if (current.text.empty()) return;
    // A possessive ending: "librarian's", "James'".
    std::string& w = current.word;
    if (w.size() > 2 && w.compare(w.size() - 2, 2, "'s") == 0) {
      w.resize(w.size() - 2);
      current.possessive = true;
    } else if (w.size() > 1 && w.back() == '\'') {
      w.pop_back();
      current.possessive = true;
    }
    if (!w.empty() && w != "'") tokens.push_back(current);
    current = Token{};
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    const int column = static_cast<int>(i) + 1;
    const bool curly = is_curly_apostrophe(text, i);
    if (!curly && (c >= 0x80 || (c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7f)) {
      const char* what = c >= 0x80 ? " is not plain ASCII" : " is a control character";
      reject(RejectReason::bad_character,
             "the byte " + byte_name(c) + " at column " + std::to_string(column) + what +
                 "; commands are written in ASCII",
             {byte_name(c), column, ""});
    }
    const bool digit_dot = c == '.' && !current.word.empty() && is_digit(current.word.back()) &&
                           i + 1 < text.size() && is_digit(static_cast<unsigned char>(text[i + 1]));
    if (curly || is_alnum(c) || c == '-' || c == '_' || c == ':' || c == '\'' || digit_dot) {
      if (current.text.empty()) current.column = column;
      if (curly) {
        current.text += "\xE2\x80\x99";
        current.word += '\'';
        i += 2;
        continue;
      }
      current.text += static_cast<char>(c);
      current.word += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    } else {
      finish();
    }
  }
  finish();
  return tokens;
}

}  // namespace autonomy::courier
