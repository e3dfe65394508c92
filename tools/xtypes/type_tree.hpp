#pragma once
// A DDS data type as the generic tools see it: what the XTypes type object of a topic says
// (tools/xtypes/type_lookup.hpp builds it), without DDS. One tree describes any type, ours or a
// foreign process's, so one CDR walker (cdr_json.hpp) prints every topic.
//
// Aliases are resolved away; a struct's base type's members come first in `members`.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace autonomy::xtypes {

enum class Kind {
  Bool, Byte, Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Float32, Float64, Char8,
  String, Enum, Bitmask, Struct, Union, Sequence, Array
};

// How a struct or union is laid out in XCDR2 (final: bare; appendable: a size header first;
// mutable: a size header and one header per member).
enum class Extensibility { Final, Appendable, Mutable };

struct Type;
using TypePtr = std::shared_ptr<Type>;

struct Member {
  std::string name;
  uint32_t id = 0;  // the member id of mutable types
  TypePtr type;
  bool key = false;
  bool optional = false;
  // Unions: the discriminator values of this case; is_default: the case of the other values.
  std::vector<int64_t> labels;
  bool is_default = false;
};

struct NamedValue {  // an enum literal (value) or a bitmask flag (value = bit position)
  std::string name;
  int64_t value = 0;
};

struct Type {
  Kind kind = Kind::Int32;
  std::string name;  // qualified, for structs, unions, enums, bitmasks: "autonomy::NavGoal"
  Extensibility extensibility = Extensibility::Final;
  std::vector<Member> members;  // struct members in order; union cases
  TypePtr discriminator;        // unions
  TypePtr element;              // sequences and arrays
  std::vector<uint32_t> dims;   // arrays: each dimension
  uint32_t bound = 0;           // strings and sequences: 0 unbounded
  std::vector<NamedValue> literals;  // enums and bitmasks
  uint16_t bit_bound = 32;           // enums and bitmasks: how many bits the value takes
};

TypePtr make_type(Kind kind);
bool is_primitive(Kind kind);  // fixed size, no header: bool, integers, floats, char (not enums)
// Primitive, enum or bitmask: the elements of a collection that XCDR2 writes without a size header.
bool is_primitive_or_enum(Kind kind);
const char* kind_name(Kind kind);  // IDL spelling of primitives: "int32", "float64", "string"

// The JSON name of an enum literal, as `autonomy topic echo` has always printed them: the first
// word that every literal shares removed, lower case (GOAL_ACCEPTED, GOAL_ACTIVE -> "accepted",
// "active"; PLANNING_PLAN_FOUND -> "plan_found"). Literals without such a shared word: as written.
std::string literal_json_name(const Type& enum_type, const std::string& literal);

}  // namespace autonomy::xtypes
