#pragma once
// JSON for the message value types, without DDS: what `autonomy topic echo` prints and
// `autonomy topic pub` parses.
//
//   to_json(value)   every field, in IDL order; enums as lower-case names ("ready", "unicycle");
//                    non-finite doubles as the strings "nan", "inf", "-inf" (JSON has no such numbers).
//   key_json(value)  the key fields only (what a disposed-instance report carries).
//   from_json<T>(j)  checked: j must be an object; key fields are required; other fields may be
//                    omitted and keep T's defaults; unknown fields, wrong types, integers out of
//                    range and unknown enum names throw JsonError naming the field
//                    ("NavGoal.x: expected a number, got string \"abc\"").
#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "tools/json/fields.hpp"

namespace autonomy::json {

using Json = nlohmann::ordered_json;  // keeps fields in IDL order

class JsonError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "a string \"abc\"", "an object", "a number 3.5": how an error message names what it found.
std::string describe(const Json& j);

namespace detail {

template <typename T, typename = void>
struct HasFields : std::false_type {};
template <typename T>
struct HasFields<T, std::void_t<decltype(Fields<T>::name)>> : std::true_type {};

template <typename T>
struct IsVector : std::false_type {};
template <typename T>
struct IsVector<std::vector<T>> : std::true_type {};

template <typename E>
std::string enum_names() {
  std::string out;
  for (E e : EnumValues<E>::values) out += std::string(out.empty() ? "" : ", ") + msg::to_string(e);
  return out;
}

template <typename T>
Json encode(const T& v);

struct Encoder {
  Json& out;
  bool keys_only = false;
  template <typename F>
  void key(const char* name, const F& f) {
    out[name] = encode(f);
  }
  template <typename F>
  void field(const char* name, const F& f) {
    if (!keys_only) out[name] = encode(f);
  }
};

template <typename T>
Json encode(const T& v) {
  if constexpr (HasFields<T>::value) {
    Json j = Json::object();
    Encoder e{j};
    Fields<T>::visit(e, v);
    return j;
  } else if constexpr (IsVector<T>::value) {
    Json j = Json::array();
    for (const auto& x : v) j.push_back(encode(x));
    return j;
  } else if constexpr (std::is_enum_v<T>) {
    return msg::to_string(v);
  } else if constexpr (std::is_floating_point_v<T>) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    return v;
  } else {
    return v;  // strings, bool, integers
  }
}

[[noreturn]] inline void fail(const std::string& path, const std::string& expected, const Json& got) {
  throw JsonError(path + ": expected " + expected + ", got " + describe(got));
}

template <typename T>
void decode(const Json& j, T& out, const std::string& path);

struct NameCollector {
  std::vector<std::string> names;
  template <typename F>
  void key(const char* n, F&) {
    names.emplace_back(n);
  }
  template <typename F>
  void field(const char* n, F&) {
    names.emplace_back(n);
  }
};

struct KeyCollector {
  std::vector<std::string> names;
  template <typename F>
  void key(const char* n, F&) {
    names.emplace_back(n);
  }
  template <typename F>
  void field(const char*, F&) {}
};

struct Decoder {
  const Json& in;
  const std::string& path;
  template <typename F>
  void key(const char* name, F& f) {
    if (!in.contains(name)) throw JsonError(path + ": missing key field \"" + name + "\"");
    decode(in.at(name), f, path + "." + name);
  }
  template <typename F>
  void field(const char* name, F& f) {
    if (in.contains(name)) decode(in.at(name), f, path + "." + name);
  }
};

template <typename T>
void decode(const Json& j, T& out, const std::string& path) {
  if constexpr (HasFields<T>::value) {
    if (!j.is_object()) fail(path, "an object", j);
    T fresh{};  // fields left out keep the type's defaults
    NameCollector names;
    Fields<T>::visit(names, fresh);
    for (const auto& item : j.items()) {
      bool known = false;
      for (const auto& n : names.names) known = known || n == item.key();
      if (!known) {
        std::string list;
        for (const auto& n : names.names) list += (list.empty() ? "" : ", ") + n;
        throw JsonError(path + ": unknown field \"" + item.key() + "\" (fields of " + Fields<T>::name + ": " + list +
                        ")");
      }
    }
    Decoder d{j, path};
    Fields<T>::visit(d, fresh);
    out = std::move(fresh);
  } else if constexpr (IsVector<T>::value) {
    if (!j.is_array()) fail(path, "an array", j);
    T v;
    v.resize(j.size());
    for (size_t i = 0; i < j.size(); ++i) decode(j[i], v[i], path + "[" + std::to_string(i) + "]");
    out = std::move(v);
  } else if constexpr (std::is_enum_v<T>) {
    const std::string expected = "one of " + enum_names<T>();
    if (!j.is_string()) fail(path, expected, j);
    const auto& s = j.get_ref<const std::string&>();
    for (T e : EnumValues<T>::values) {
      if (s == msg::to_string(e)) {
        out = e;
        return;
      }
    }
    fail(path, expected, j);
  } else if constexpr (std::is_same_v<T, std::string>) {
    if (!j.is_string()) fail(path, "a string", j);
    out = j.get<std::string>();
  } else if constexpr (std::is_same_v<T, bool>) {
    if (!j.is_boolean()) fail(path, "true or false", j);
    out = j.get<bool>();
  } else if constexpr (std::is_floating_point_v<T>) {
    if (j.is_number()) {
      out = j.get<T>();
    } else if (j.is_string() && (j == "nan" || j == "inf" || j == "-inf")) {
      out = j == "nan" ? std::numeric_limits<T>::quiet_NaN()
                       : (j == "inf" ? std::numeric_limits<T>::infinity() : -std::numeric_limits<T>::infinity());
    } else {
      fail(path, "a number", j);
    }
  } else {
    static_assert(std::is_integral_v<T>, "no JSON mapping for this field type");
    const std::string expected = std::string("an integer in [") + std::to_string(std::numeric_limits<T>::min()) + ", " +
                                 std::to_string(std::numeric_limits<T>::max()) + "]";
    if (j.is_number_unsigned()) {
      const auto u = j.get<uint64_t>();
      if (u > static_cast<uint64_t>(std::numeric_limits<T>::max())) fail(path, expected, j);
      out = static_cast<T>(u);
    } else if (j.is_number_integer()) {
      const auto i = j.get<int64_t>();
      if constexpr (std::is_unsigned_v<T>) {
        if (i < 0 || static_cast<uint64_t>(i) > static_cast<uint64_t>(std::numeric_limits<T>::max()))
          fail(path, expected, j);
      } else {
        if (i < static_cast<int64_t>(std::numeric_limits<T>::min()) ||
            i > static_cast<int64_t>(std::numeric_limits<T>::max()))
          fail(path, expected, j);
      }
      out = static_cast<T>(i);
    } else if (j.is_number_float()) {
      // 17.0 is an integer to a person; 17.5 is not, nor is anything out of range.
      const double d = j.get<double>();
      if (std::trunc(d) != d || d < static_cast<double>(std::numeric_limits<T>::min()) ||
          d >= std::ldexp(1.0, std::numeric_limits<T>::digits))
        fail(path, expected, j);
      out = static_cast<T>(d);
    } else {
      fail(path, expected, j);
    }
  }
}

}  // namespace detail

template <typename T>
Json to_json(const T& value) {
  return detail::encode(value);
}

template <typename T>
Json key_json(const T& value) {
  Json j = Json::object();
  detail::Encoder e{j, /*keys_only=*/true};
  Fields<T>::visit(e, value);
  return j;
}

template <typename T>
T from_json(const Json& j) {
  T out{};
  detail::decode(j, out, Fields<T>::name);
  return out;
}

// The JSON name of a message type ("NavGoal") and its key fields, for help and error texts.
template <typename T>
const char* message_name() {
  return Fields<T>::name;
}

template <typename T>
std::vector<std::string> field_names() {
  detail::NameCollector c;
  T probe{};
  Fields<T>::visit(c, probe);
  return c.names;
}

template <typename T>
std::vector<std::string> key_names() {
  detail::KeyCollector c;
  T probe{};
  Fields<T>::visit(c, probe);
  return c.names;
}

// Parses text as JSON; throws JsonError("invalid JSON: ... at byte N") otherwise.
Json parse(const std::string& text);

}  // namespace autonomy::json
