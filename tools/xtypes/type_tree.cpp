#include "tools/xtypes/type_tree.hpp"

#include <cctype>

namespace autonomy::xtypes {

TypePtr make_type(Kind kind) {
  auto t = std::make_shared<Type>();
  t->kind = kind;
  return t;
}

bool is_primitive(Kind kind) {
  switch (kind) {
    case Kind::Bool: case Kind::Byte: case Kind::Int8: case Kind::UInt8: case Kind::Int16: case Kind::UInt16:
    case Kind::Int32: case Kind::UInt32: case Kind::Int64: case Kind::UInt64: case Kind::Float32:
    case Kind::Float64: case Kind::Char8:
      return true;
    default:
      return false;
  }
}

bool is_primitive_or_enum(Kind kind) { return is_primitive(kind) || kind == Kind::Enum || kind == Kind::Bitmask; }

const char* kind_name(Kind kind) {
  switch (kind) {
    case Kind::Bool: return "boolean";
    case Kind::Byte: return "octet";
    case Kind::Int8: return "int8";
    case Kind::UInt8: return "uint8";
    case Kind::Int16: return "int16";
    case Kind::UInt16: return "uint16";
    case Kind::Int32: return "int32";
    case Kind::UInt32: return "uint32";
    case Kind::Int64: return "int64";
    case Kind::UInt64: return "uint64";
    case Kind::Float32: return "float";
    case Kind::Float64: return "double";
    case Kind::Char8: return "char";
    case Kind::String: return "string";
    case Kind::Enum: return "enum";
    case Kind::Bitmask: return "bitmask";
    case Kind::Struct: return "struct";
    case Kind::Union: return "union";
    case Kind::Sequence: return "sequence";
    case Kind::Array: return "array";
  }
  return "?";
}

namespace {

// "GOAL_ACCEPTED" -> "GOAL_"; "" without an underscore.
std::string first_word_of(const std::string& literal) {
  const auto cut = literal.find('_');
  return cut == std::string::npos ? std::string() : literal.substr(0, cut + 1);
}

}  // namespace

std::string literal_json_name(const Type& enum_type, const std::string& literal) {
  const std::string prefix = first_word_of(literal);
  bool shared = enum_type.literals.size() >= 2 && !prefix.empty();
  for (const auto& l : enum_type.literals) shared = shared && l.name.rfind(prefix, 0) == 0 && l.name != prefix;
  if (!shared) return literal;
  std::string out = literal.substr(prefix.size());
  for (auto& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace autonomy::xtypes
