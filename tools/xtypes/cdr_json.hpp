#pragma once
// One walker for every type: a serialized sample (CDR as on the wire, with its 4-byte
// encapsulation header; XCDR1 or XCDR2, either byte order; final, appendable and mutable types)
// printed as JSON by its type tree (type_tree.hpp), for every topic (`autonomy topic echo`, the
// viewer's panels): members in order, enums as lower-case names, non-finite floats as the strings
// "nan", "inf", "-inf"; unions as {"_d": discriminator, "<case name>": value}; absent
// optional members left out; bitmasks as the list of set flag names.
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "tools/xtypes/type_tree.hpp"

namespace autonomy::xtypes {

using Json = nlohmann::ordered_json;

class CdrError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// How sequences and arrays of octets print: {"length": n, "base64": "..."} (default),
// {"length": n, "hex": "0a1b..."}, or an array of numbers.
enum class BytesStyle { Base64, Hex, Numbers };

struct WalkOptions {
  BytesStyle bytes = BytesStyle::Base64;
};

// Throws CdrError naming the member path where the bytes ran out or made no sense.
Json cdr_to_json(const Type& type, const std::string& cdr, const WalkOptions& options = {});

// The key members of a walked sample (top-level members marked @key), in type order.
Json key_of(const Type& type, const Json& sample);

std::string base64(const unsigned char* data, size_t size);

}  // namespace autonomy::xtypes
