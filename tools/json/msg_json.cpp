#include "tools/json/msg_json.hpp"

namespace autonomy::json {

std::string describe(const Json& j) {
  switch (j.type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::object:
      return "an object";
    case Json::value_t::array:
      return "an array";
    case Json::value_t::string:
      return "string " + j.dump();
    case Json::value_t::boolean:
      return "boolean " + j.dump();
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float:
      return "number " + j.dump();
    default:
      return "a " + std::string(j.type_name());
  }
}

Json parse(const std::string& text) {
  try {
    return Json::parse(text);
  } catch (const Json::parse_error& e) {
    // nlohmann's text starts with "[json.exception.parse_error.101] parse error at line 1, ...".
    std::string what = e.what();
    if (const auto p = what.find("] "); p != std::string::npos) what = what.substr(p + 2);
    throw JsonError("invalid JSON: " + what);
  }
}

}  // namespace autonomy::json
