#include "common/config/text_format.hpp"

#include <google/protobuf/io/tokenizer.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace autonomy::configfile {

namespace pb = google::protobuf;

Position Locator::at(const char* field, int index) const {
  const pb::FieldDescriptor* f = type_->FindFieldByName(field);
  if (tree_ == nullptr || f == nullptr) return self_;
  const pb::TextFormat::ParseLocation location = tree_->GetLocation(f, index);
  if (location.line < 0) return self_;
  return {location.line + 1, location.column + 1};
}

Locator Locator::nested(const char* field, int index) const {
  const pb::FieldDescriptor* f = type_->FindFieldByName(field);
  const ParseInfoTree* tree = tree_ != nullptr ? tree_->GetTreeForNested(f, index) : nullptr;
  return {tree, f->message_type(), at(field, index)};
}

namespace {

class SyntaxErrors : public pb::io::ErrorCollector {
 public:
  SyntaxErrors(const std::string& source, std::vector<FileError>& errors) : source_(source), errors_(errors) {}

  void AddError(int line, pb::io::ColumnNumber column, const std::string& message) override {
    errors_.push_back({source_, line + 1, column + 1, message});
  }

 private:
  const std::string& source_;
  std::vector<FileError>& errors_;
};

}  // namespace

bool parse_text_format(const std::string& text, const std::string& source, pb::Message& message,
                       Locator::ParseInfoTree& tree, std::vector<FileError>& errors) {
  const size_t before = errors.size();
  SyntaxErrors syntax(source, errors);
  pb::TextFormat::Parser parser;
  parser.RecordErrorsTo(&syntax);
  parser.WriteLocationsTo(&tree);
  if (parser.ParseFromString(text, &message)) return true;
  if (errors.size() == before) errors.push_back({source, 0, 0, "cannot parse"});
  return false;
}

std::optional<std::string> read_text_file(const std::string& path, std::vector<FileError>& errors) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    errors.push_back({path, 0, 0, std::string("cannot read file: ") + std::strerror(errno)});
    return std::nullopt;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace autonomy::configfile
