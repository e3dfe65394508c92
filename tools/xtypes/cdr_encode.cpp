#include "tools/xtypes/cdr_encode.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

namespace autonomy::xtypes {

namespace {

// "string \"abc\"", "number 7", "an array": what an error message says it found.
std::string describe(const Json& j) {
  switch (j.type()) {
    case Json::value_t::object: return "an object";
    case Json::value_t::array: return "an array";
    case Json::value_t::string: return "string " + j.dump();
    case Json::value_t::boolean: return "boolean " + j.dump();
    case Json::value_t::number_integer: case Json::value_t::number_unsigned: case Json::value_t::number_float:
      return "number " + j.dump();
    default: return j.dump();
  }
}

[[noreturn]] void bad(const std::string& path, const std::string& expected, const Json& got) {
  throw CdrError((path.empty() ? std::string("message") : path) + ": expected " + expected + ", got " + describe(got));
}

// A number written with a fraction that has none (12.0) is the integer: JSON from other tools
// (and JavaScript) does not tell 12 from 12.0. nullopt for anything else.
std::optional<Json> whole_number(const Json& j) {
  if (!j.is_number_float()) return std::nullopt;
  const double d = j.get<double>();
  if (!(std::trunc(d) == d) || std::fabs(d) >= 9.2e18) return std::nullopt;
  return d < 0 ? Json(static_cast<int64_t>(d)) : Json(static_cast<uint64_t>(d));
}

std::string decode_base64(const std::string& text, const std::string& path) {
  static const std::string table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  uint32_t acc = 0;
  int bits = 0;
  for (char c : text) {
    if (c == '=') break;
    const auto at = table.find(c);
    if (at == std::string::npos) throw CdrError(path + ": not base64 (character '" + std::string(1, c) + "')");
    acc = (acc << 6) | static_cast<uint32_t>(at);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<char>((acc >> bits) & 0xff));
    }
  }
  return out;
}

std::string decode_hex(const std::string& text, const std::string& path) {
  if (text.size() % 2) throw CdrError(path + ": odd number of hex digits");
  std::string out;
  for (size_t i = 0; i < text.size(); i += 2) {
    const std::string pair = text.substr(i, 2);
    if (pair.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos)
      throw CdrError(path + ": not hex (\"" + pair + "\")");
    out.push_back(static_cast<char>(std::stoul(pair, nullptr, 16)));
  }
  return out;
}

class CdrEncoder {
 public:
  std::string out;

  void put(uint64_t v, size_t n) {
    align(n);
    for (size_t i = 0; i < n; ++i) out.push_back(static_cast<char>(v >> (8 * i)));
  }
  void align(size_t n) {
    if (n > 4) n = 4;  // XCDR2
    while (out.size() % n) out.push_back(0);
  }
  size_t open_dheader() {
    put(0, 4);
    return out.size();
  }
  void close_dheader(size_t start) {
    const uint32_t size = static_cast<uint32_t>(out.size() - start);
    std::memcpy(&out[start - 4], &size, 4);  // little endian host (checked in json_to_cdr)
  }

  // Writes j as t; returns j completed with defaults.
  Json encode(const Type& t, const Json* j, const std::string& path) {
    switch (t.kind) {
      case Kind::Bool: {
        if (j && !j->is_boolean()) bad(path, "true or false", *j);
        const bool v = j && j->get<bool>();
        put(v, 1);
        return v;
      }
      case Kind::Byte: case Kind::UInt8: return integer(j, path, 1, 0, 255);
      case Kind::Int8: return integer(j, path, 1, -128, 127);
      case Kind::Int16: return integer(j, path, 2, INT16_MIN, INT16_MAX);
      case Kind::UInt16: return integer(j, path, 2, 0, UINT16_MAX);
      case Kind::Int32: return integer(j, path, 4, INT32_MIN, INT32_MAX);
      case Kind::UInt32: return integer(j, path, 4, 0, UINT32_MAX);
      case Kind::Int64: return integer(j, path, 8, std::numeric_limits<int64_t>::min(), std::numeric_limits<int64_t>::max());
      case Kind::UInt64: {
        const std::optional<Json> whole = j ? whole_number(*j) : std::nullopt;
        const Json* given = whole ? &*whole : j;
        if (given && !given->is_number_unsigned() && !(given->is_number_integer() && given->get<int64_t>() >= 0))
          bad(path, "an unsigned integer", *given);
        const uint64_t v = given ? given->get<uint64_t>() : 0;
        put(v, 8);
        return v;
      }
      case Kind::Float32: case Kind::Float64: {
        double v = 0.0;
        if (j) {
          if (j->is_number()) v = j->get<double>();
          else if (*j == "nan") v = std::numeric_limits<double>::quiet_NaN();
          else if (*j == "inf") v = std::numeric_limits<double>::infinity();
          else if (*j == "-inf") v = -std::numeric_limits<double>::infinity();
          else bad(path, "a number (or \"nan\", \"inf\", \"-inf\")", *j);
        }
        if (t.kind == Kind::Float32) {
          const float f = static_cast<float>(v);
          uint32_t bits;
          std::memcpy(&bits, &f, 4);
          put(bits, 4);
          v = f;
        } else {
          uint64_t bits;
          std::memcpy(&bits, &v, 8);
          put(bits, 8);
        }
        if (std::isnan(v)) return "nan";
        if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
        return v;
      }
      case Kind::Char8: {
        if (j && !(j->is_string() && j->get<std::string>().size() == 1)) bad(path, "a string of one character", *j);
        const char c = j ? j->get<std::string>()[0] : '\0';
        put(static_cast<unsigned char>(c), 1);
        return std::string(1, c);
      }
      case Kind::String: {
        if (j && !j->is_string()) bad(path, "a string", *j);
        const std::string s = j ? j->get<std::string>() : "";
        if (t.bound && s.size() > t.bound)
          throw CdrError(path + ": " + std::to_string(s.size()) + " characters, the type allows " + std::to_string(t.bound));
        put(s.size() + 1, 4);
        out += s;
        out.push_back(0);
        return s;
      }
      case Kind::Enum: return enumerated(t, j, path);
      case Kind::Bitmask: return bitmask(t, j, path);
      case Kind::Struct: return structure(t, j, path);
      case Kind::Union: return choice(t, j, path);
      case Kind::Sequence: case Kind::Array: return collection(t, j, path);
    }
    throw CdrError(path + ": unknown type kind");
  }

 private:
  Json integer(const Json* given, const std::string& path, size_t n, int64_t lo, int64_t hi) {
    int64_t v = 0;
    const std::optional<Json> whole = given ? whole_number(*given) : std::nullopt;
    const Json* j = whole ? &*whole : given;
    if (j) {
      if (!j->is_number_integer()) bad(path, "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]", *j);
      if (j->is_number_unsigned() && j->get<uint64_t>() > static_cast<uint64_t>(hi))
        throw CdrError(path + ": " + j->dump() + " is out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
      v = j->get<int64_t>();
      if (v < lo || v > hi)
        throw CdrError(path + ": " + j->dump() + " is out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    }
    put(static_cast<uint64_t>(v), n);
    return v;
  }

  Json enumerated(const Type& t, const Json* j, const std::string& path) {
    if (t.literals.empty()) throw CdrError(path + ": enum without literals");
    const NamedValue* chosen = &t.literals.front();
    if (j) {
      chosen = nullptr;
      for (const auto& l : t.literals)
        if ((j->is_string() && (*j == literal_json_name(t, l.name) || *j == l.name)) ||
            (j->is_number_integer() && j->get<int64_t>() == l.value))
          chosen = &l;
      if (!chosen) {
        std::string names;
        for (const auto& l : t.literals) names += (names.empty() ? "" : ", ") + literal_json_name(t, l.name);
        bad(path, "one of " + names, *j);
      }
    }
    put(static_cast<uint64_t>(chosen->value), t.bit_bound <= 8 ? 1 : t.bit_bound <= 16 ? 2 : 4);
    return literal_json_name(t, chosen->name);
  }

  Json bitmask(const Type& t, const Json* j, const std::string& path) {
    uint64_t v = 0;
    Json names = Json::array();
    if (j) {
      if (!j->is_array()) bad(path, "a list of flag names", *j);
      for (const auto& f : *j) {
        bool known = false;
        for (const auto& l : t.literals)
          if (f == l.name) {
            v |= uint64_t{1} << l.value;
            known = true;
          }
        if (!known) bad(path, "a flag name of " + t.name, f);
        names.push_back(f);
      }
    }
    put(v, t.bit_bound <= 8 ? 1 : t.bit_bound <= 16 ? 2 : t.bit_bound <= 32 ? 4 : 8);
    return names;
  }

  Json structure(const Type& t, const Json* j, const std::string& path) {
    const std::string prefix = path.empty() ? "" : path + ".";
    if (j && !j->is_object()) bad(path, "an object", *j);
    if (j)
      for (const auto& item : j->items()) {
        bool known = false;
        for (const auto& m : t.members) known = known || m.name == item.key();
        if (!known) {
          std::string names;
          for (const auto& m : t.members) names += (names.empty() ? "" : ", ") + m.name;
          throw CdrError(prefix + item.key() + ": " + t.name + " has no such member (members: " + names + ")");
        }
      }
    const bool mutable_type = t.extensibility == Extensibility::Mutable;
    const size_t start = t.extensibility != Extensibility::Final ? open_dheader() : 0;
    Json done = Json::object();
    for (const auto& m : t.members) {
      const Json* given = j && j->contains(m.name) ? &(*j)[m.name] : nullptr;
      if (m.key && !given && path.empty()) throw CdrError(prefix + m.name + ": missing key member");
      if (mutable_type) {
        if (m.optional && !given) continue;
        put((4u << 28) | (m.key ? 0x80000000u : 0u) | (m.id & 0x0fffffffu), 4);  // LC 4: a size word follows
        const size_t member_start = open_dheader();
        done[m.name] = encode(*m.type, given, prefix + m.name);
        close_dheader(member_start);
        continue;
      }
      if (m.optional) {
        put(given ? 1 : 0, 1);
        if (!given) continue;
      }
      done[m.name] = encode(*m.type, given, prefix + m.name);
    }
    if (start) close_dheader(start);
    return done;
  }

  Json choice(const Type& t, const Json* j, const std::string& path) {
    const std::string prefix = path.empty() ? "" : path + ".";
    if (j && !j->is_object()) bad(path, "an object {\"_d\": discriminator, \"<case>\": value}", *j);
    // The case: named in j, else the one of the discriminator given, else the first.
    const Member* chosen = nullptr;
    if (j)
      for (const auto& m : t.members)
        if (j->contains(m.name)) chosen = &m;
    if (!chosen && !t.members.empty()) chosen = &t.members.front();
    if (!chosen) throw CdrError(path + ": union without cases");
    const size_t start = t.extensibility != Extensibility::Final ? open_dheader() : 0;
    Json d;
    if (j && j->contains("_d")) {
      d = (*j)["_d"];
    } else if (!chosen->labels.empty()) {
      d = chosen->labels.front();
      if (t.discriminator->kind == Kind::Enum)
        for (const auto& l : t.discriminator->literals)
          if (l.value == chosen->labels.front()) d = literal_json_name(*t.discriminator, l.name);
      if (t.discriminator->kind == Kind::Bool) d = chosen->labels.front() != 0;
    } else {
      throw CdrError(prefix + "_d: needed for the default case " + chosen->name);
    }
    Json done = Json::object();
    done["_d"] = encode(*t.discriminator, &d, prefix + "_d");
    const Json* given = j && j->contains(chosen->name) ? &(*j)[chosen->name] : nullptr;
    done[chosen->name] = encode(*chosen->type, given, prefix + chosen->name);
    if (start) close_dheader(start);
    return done;
  }

  Json collection(const Type& t, const Json* j, const std::string& path) {
    uint64_t expected = 1;
    for (uint32_t d : t.dims) expected *= d;
    Json items = Json::array();
    if (j && t.element->kind == Kind::Byte && j->is_object()) {
      std::string bytes;
      if (j->contains("base64") && (*j)["base64"].is_string()) bytes = decode_base64((*j)["base64"], path);
      else if (j->contains("hex") && (*j)["hex"].is_string()) bytes = decode_hex((*j)["hex"], path);
      else bad(path, "an array of numbers, {\"base64\": ...} or {\"hex\": ...}", *j);
      for (unsigned char c : bytes) items.push_back(c);
    } else if (j) {
      if (!j->is_array()) bad(path, "an array", *j);
      items = *j;
    }
    if (t.kind == Kind::Array) {
      // Arrays of several dimensions are given nested, as the walker prints them: flatten.
      for (size_t d = 1; d < t.dims.size(); ++d) {
        Json flat = Json::array();
        for (const auto& row : items) {
          if (!row.is_array()) bad(path, "nested arrays", row);
          for (const auto& x : row) flat.push_back(x);
        }
        items = flat;
      }
      if (j && items.size() != expected)
        throw CdrError(path + ": " + std::to_string(items.size()) + " elements, the array has " + std::to_string(expected));
    } else if (t.bound && items.size() > t.bound) {
      throw CdrError(path + ": " + std::to_string(items.size()) + " elements, the sequence allows " + std::to_string(t.bound));
    }
    const size_t start = is_primitive_or_enum(t.element->kind) ? 0 : open_dheader();
    if (t.kind == Kind::Sequence) put(items.size(), 4);
    Json done = Json::array();
    const uint64_t n = t.kind == Kind::Array ? expected : items.size();
    for (uint64_t i = 0; i < n; ++i)
      done.push_back(encode(*t.element, i < items.size() ? &items[i] : nullptr, path + "[" + std::to_string(i) + "]"));
    if (start) close_dheader(start);
    if (t.kind == Kind::Array && t.dims.size() > 1) {  // back to the nested form
      Json level = done;
      for (size_t d = t.dims.size() - 1; d >= 1; --d) {
        Json next = Json::array();
        for (size_t i = 0; i < level.size(); i += t.dims[d]) {
          Json group = Json::array();
          for (size_t k = 0; k < t.dims[d]; ++k) group.push_back(level[i + k]);
          next.push_back(group);
        }
        level = next;
      }
      return level;
    }
    return done;
  }
};

}  // namespace

Json parse_json(const std::string& text) {
  try {
    return Json::parse(text);
  } catch (const Json::parse_error& e) {
    // nlohmann's text starts with "[json.exception.parse_error.101] parse error at line 1, ...".
    std::string what = e.what();
    if (const auto p = what.find("] "); p != std::string::npos) what = what.substr(p + 2);
    throw CdrError("invalid JSON: " + what);
  }
}

Encoded json_to_cdr(const Type& type, const Json& j) {
  static_assert(sizeof(uint32_t) == 4);
  const uint16_t probe = 1;
  if (*reinterpret_cast<const unsigned char*>(&probe) != 1) throw CdrError("json_to_cdr: big-endian hosts are not supported");
  CdrEncoder enc;
  Encoded e;
  e.complete = enc.encode(type, &j, "");
  // XCDR2 little endian: CDR2_LE for final types, D_CDR2_LE (appendable) or PL_CDR2_LE (mutable).
  const char id = type.extensibility == Extensibility::Mutable ? 0x0b : type.extensibility == Extensibility::Appendable ? 0x09 : 0x07;
  e.cdr = std::string{0, id, 0, 0} + enc.out;
  return e;
}

}  // namespace autonomy::xtypes
