#pragma once
// The walker's inverse, for `autonomy topic pub` on any topic: JSON (in the walker's
// conventions) checked against a type tree and serialized as XCDR2, little endian, with its
// encapsulation header. Members left out take zero, empty or the first enum literal; key members
// are required; unknown members, wrong JSON types, integers out of range and unknown enum names
// are errors naming the member path. Octet sequences: an array of numbers, {"base64": "..."}
// or {"hex": "..."}.
#include <string>

#include "tools/xtypes/cdr_json.hpp"

namespace autonomy::xtypes {

struct Encoded {
  std::string cdr;  // encapsulation header + payload
  Json complete;    // the JSON with every member (what the walker prints for cdr, octets as numbers)
};

// Throws CdrError. Numbers with a fraction of zero (12.0) are taken for integer members.
Encoded json_to_cdr(const Type& type, const Json& j);

// Text as JSON; throws CdrError("invalid JSON: <where and why>").
Json parse_json(const std::string& text);

}  // namespace autonomy::xtypes
