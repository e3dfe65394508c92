#pragma once
// Reading protobuf text format files with positions: syntax errors come from protobuf's parser,
// and a Locator finds where each field was written so that checks of meaning can point at the
// offending text too. Shared by every loader of files people write.
#include "common/config/file_error.hpp"

#include <google/protobuf/message.h>
#include <google/protobuf/text_format.h>

#include <optional>
#include <string>
#include <vector>

namespace autonomy::configfile {

struct Position {
  int line = 1;  // 1-based
  int column = 1;
};

// Where the parser saw each field of one message. A field that is absent has no position of its
// own: errors about it point at the enclosing message (the file's start for the top level).
class Locator {
 public:
  using ParseInfoTree = google::protobuf::TextFormat::ParseInfoTree;

  Locator(const ParseInfoTree* tree, const google::protobuf::Descriptor* type, Position self)
      : tree_(tree), type_(type), self_(self) {}

  Position self() const { return self_; }
  Position at(const char* field, int index = -1) const;
  Locator nested(const char* field, int index = -1) const;

 private:
  const ParseInfoTree* tree_;
  const google::protobuf::Descriptor* type_;
  Position self_;
};

// Parses text into message, recording field locations into tree. On a syntax error returns false
// with the error (protobuf stops at the first) appended to errors.
bool parse_text_format(const std::string& text, const std::string& source, google::protobuf::Message& message,
                       Locator::ParseInfoTree& tree, std::vector<FileError>& errors);

// The file's content, or nullopt with a "cannot read file" error appended.
std::optional<std::string> read_text_file(const std::string& path, std::vector<FileError>& errors);

}  // namespace autonomy::configfile
