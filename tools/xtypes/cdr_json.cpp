#include "tools/xtypes/cdr_json.hpp"

#include <cmath>
#include <cstring>

namespace autonomy::xtypes {

namespace {

// XCDR1 aligns 8-byte values to 8, XCDR2 to 4; offsets count from the end of the encapsulation
// header. A mutable XCDR1 type is a parameter list.
class CdrWalker {
 public:
  CdrWalker(const std::string& cdr, const WalkOptions& options) : options_(options) {
    if (cdr.size() < 4) throw CdrError("sample of " + std::to_string(cdr.size()) + " bytes: no encapsulation header");
    const unsigned id = (static_cast<unsigned char>(cdr[0]) << 8) | static_cast<unsigned char>(cdr[1]);
    if (id <= 0x0003) {
      xcdr2_ = false;
    } else if (id >= 0x0006 && id <= 0x000b) {
      xcdr2_ = true;
    } else {
      throw CdrError("unknown CDR encapsulation 0x" + std::to_string(id));
    }
    little_ = (id & 1u) != 0;
    data_ = reinterpret_cast<const unsigned char*>(cdr.data()) + 4;
    size_ = cdr.size() - 4;
  }

  Json walk(const Type& t, const std::string& path) {
    switch (t.kind) {
      case Kind::Bool: return read_uint(1, path) != 0;
      case Kind::Byte: case Kind::UInt8: return read_uint(1, path);
      case Kind::Int8: return static_cast<int8_t>(read_uint(1, path));
      case Kind::Int16: return static_cast<int16_t>(read_uint(2, path));
      case Kind::UInt16: return static_cast<uint16_t>(read_uint(2, path));
      case Kind::Int32: return static_cast<int32_t>(read_uint(4, path));
      case Kind::UInt32: return static_cast<uint32_t>(read_uint(4, path));
      case Kind::Int64: return static_cast<int64_t>(read_uint(8, path));
      case Kind::UInt64: return read_uint(8, path);
      case Kind::Float32: {
        const uint32_t bits = static_cast<uint32_t>(read_uint(4, path));
        float f;
        std::memcpy(&f, &bits, 4);
        return number(f);
      }
      case Kind::Float64: {
        const uint64_t bits = read_uint(8, path);
        double d;
        std::memcpy(&d, &bits, 8);
        return number(d);
      }
      case Kind::Char8: return std::string(1, static_cast<char>(read_uint(1, path)));
      case Kind::String: return read_string(path);
      case Kind::Enum: return enum_value(t, path);
      case Kind::Bitmask: return bitmask_value(t, path);
      case Kind::Struct: return walk_struct(t, path);
      case Kind::Union: return walk_union(t, path);
      case Kind::Sequence: {
        const size_t end = collection_end(*t.element, path);
        const uint32_t n = static_cast<uint32_t>(read_uint(4, path));
        Json j = walk_elements(*t.element, n, path);
        skip_to(end);
        return j;
      }
      case Kind::Array: {
        const size_t end = collection_end(*t.element, path);
        uint64_t n = 1;
        for (uint32_t d : t.dims) n *= d;
        Json flat = walk_elements(*t.element, n, path);
        skip_to(end);
        return shape(flat, t.dims, options_.bytes != BytesStyle::Numbers && t.element->kind == Kind::Byte);
      }
    }
    throw CdrError(path + ": unknown type kind");
  }

 private:
  static Json number(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    return v;
  }

  [[noreturn]] void short_of(size_t n, const std::string& path) const {
    throw CdrError((path.empty() ? std::string("sample") : path) + ": needs " + std::to_string(n) + " byte(s) at offset " +
                   std::to_string(pos_) + ", the sample has " + std::to_string(size_));
  }

  void align(size_t n) {
    if (xcdr2_ && n > 4) n = 4;
    pos_ = (pos_ + n - 1) / n * n;
  }

  uint64_t read_uint(size_t n, const std::string& path) {
    align(n);
    if (pos_ + n > size_) short_of(n, path);
    uint64_t v = 0;
    for (size_t i = 0; i < n; ++i) {
      const uint64_t b = data_[pos_ + i];
      v |= little_ ? b << (8 * i) : b << (8 * (n - 1 - i));
    }
    pos_ += n;
    return v;
  }

  std::string read_string(const std::string& path) {
    const uint32_t n = static_cast<uint32_t>(read_uint(4, path));
    if (n == 0) return {};  // some writers send a zero length for an empty string
    if (pos_ + n > size_) short_of(n, path);
    std::string s(reinterpret_cast<const char*>(data_ + pos_), n - 1);  // without the terminating NUL
    pos_ += n;
    return s;
  }

  Json enum_value(const Type& t, const std::string& path) {
    const size_t width = !xcdr2_ ? 4 : t.bit_bound <= 8 ? 1 : t.bit_bound <= 16 ? 2 : 4;
    const uint64_t raw = read_uint(width, path);
    const int64_t v = width == 1 ? static_cast<int8_t>(raw) : width == 2 ? static_cast<int16_t>(raw) : static_cast<int32_t>(raw);
    for (const auto& l : t.literals)
      if (l.value == v) return literal_json_name(t, l.name);
    return v;  // a value the type does not name: print the number
  }

  Json bitmask_value(const Type& t, const std::string& path) {
    const size_t width = t.bit_bound <= 8 ? 1 : t.bit_bound <= 16 ? 2 : t.bit_bound <= 32 ? 4 : 8;
    const uint64_t v = read_uint(width, path);
    Json names = Json::array();
    uint64_t named = 0;
    for (const auto& f : t.literals)
      if (f.value < 64 && (v >> f.value) & 1u) {
        names.push_back(f.name);
        named |= uint64_t{1} << f.value;
      }
    if (v & ~named) names.push_back(v & ~named);  // bits without a name
    return names;
  }

  // XCDR2 puts a size header (DHEADER) before a collection of non-primitive elements: the end
  // it gives lets the walker step over what it does not know.
  size_t collection_end(const Type& element, const std::string& path) {
    if (!xcdr2_ || is_primitive_or_enum(element.kind)) return 0;
    const uint32_t size = static_cast<uint32_t>(read_uint(4, path));
    if (pos_ + size > size_) short_of(size, path);
    return pos_ + size;
  }

  void skip_to(size_t end) {
    if (end > pos_) pos_ = end;
  }

  Json walk_elements(const Type& element, uint64_t n, const std::string& path) {
    if (element.kind == Kind::Byte && options_.bytes != BytesStyle::Numbers) {
      if (pos_ + n > size_) short_of(n, path);
      const unsigned char* p = data_ + pos_;
      pos_ += n;
      Json j = Json::object();
      j["length"] = n;
      if (options_.bytes == BytesStyle::Base64) {
        j["base64"] = base64(p, n);
      } else {
        static const char* digits = "0123456789abcdef";
        std::string hex;
        hex.reserve(2 * n);
        for (uint64_t i = 0; i < n; ++i) {
          hex += digits[p[i] >> 4];
          hex += digits[p[i] & 15];
        }
        j["hex"] = hex;
      }
      return j;
    }
    // A length beyond what is left cannot be real (every element takes at least one byte,
    // except empty structs): refuse before reserving memory for it.
    if (n > size_ - std::min(pos_, size_) && !(element.kind == Kind::Struct && element.members.empty()))
      short_of(n, path);
    Json j = Json::array();
    for (uint64_t i = 0; i < n; ++i) j.push_back(walk(element, path + "[" + std::to_string(i) + "]"));
    return j;
  }

  // Arrays of several dimensions nest: int32 m[2][3] prints [[a,b,c],[d,e,f]]. Bytes were read
  // as one block: only the last dimension nests there.
  static Json shape(const Json& flat, const std::vector<uint32_t>& dims, bool bytes_block) {
    if (dims.size() <= 1 || bytes_block) return flat;
    Json level = flat;
    for (size_t d = dims.size() - 1; d >= 1; --d) {
      Json next = Json::array();
      const uint32_t width = dims[d];
      for (size_t i = 0; i < level.size(); i += width) {
        Json group = Json::array();
        for (size_t k = 0; k < width; ++k) group.push_back(level[i + k]);
        next.push_back(group);
      }
      level = next;
    }
    return level;
  }

  Json walk_struct(const Type& t, const std::string& path) {
    const std::string prefix = path.empty() ? "" : path + ".";
    Json j = Json::object();
    if (t.extensibility == Extensibility::Mutable) {
      walk_mutable(t, prefix, j);
      return j;
    }
    const size_t end = xcdr2_ && t.extensibility == Extensibility::Appendable ? dheader_end(path) : 0;
    for (const auto& m : t.members) {
      if (end && pos_ >= end) break;  // an older writer's type: the later members are not there
      if (m.optional) {
        if (!xcdr2_) throw CdrError(prefix + m.name + ": optional members in XCDR1 are not supported");
        if (read_uint(1, prefix + m.name) == 0) continue;
      }
      j[m.name] = walk(*m.type, prefix + m.name);
    }
    skip_to(end);
    return j;
  }

  size_t dheader_end(const std::string& path) {
    const uint32_t size = static_cast<uint32_t>(read_uint(4, path));
    if (pos_ + size > size_) short_of(size, path);
    return pos_ + size;
  }

  const Member* member_by_id(const Type& t, uint32_t id) const {
    for (const auto& m : t.members)
      if (m.id == id) return &m;
    return nullptr;
  }

  // Members in any order, each with its id and size; unknown ids are skipped.
  void walk_mutable(const Type& t, const std::string& prefix, Json& j) {
    if (xcdr2_) {
      const size_t end = dheader_end(prefix);
      while (pos_ < end) {
        const uint32_t em = static_cast<uint32_t>(read_uint(4, prefix));
        const uint32_t id = em & 0x0fffffffu;
        const uint32_t lc = (em >> 28) & 7u;
        size_t size;
        size_t start = pos_;
        if (lc <= 3) {
          size = size_t{1} << lc;
        } else {
          const uint32_t next = static_cast<uint32_t>(read_uint(4, prefix));
          if (lc == 4) {
            size = next;
            start = pos_;
          } else {  // 5..7: the length word is the member's own first word (a sequence's length)
            size = 4 + static_cast<size_t>(next) * (lc == 5 ? 1 : lc == 6 ? 4 : 8);
            start = pos_ - 4;
          }
        }
        pos_ = start;
        const Member* m = member_by_id(t, id);
        if (m) j[m->name] = walk(*m->type, prefix + m->name);
        pos_ = start + size;
      }
      pos_ = end;
      return;
    }
    for (;;) {  // XCDR1 parameter list
      align(4);
      uint32_t id = static_cast<uint32_t>(read_uint(2, prefix));
      uint32_t size = static_cast<uint32_t>(read_uint(2, prefix));
      if ((id & 0x3fffu) == 0x3f02u) return;  // sentinel
      if ((id & 0x3fffu) == 0x3f01u) {       // extended: a 32-bit id and size follow
        id = static_cast<uint32_t>(read_uint(4, prefix));
        size = static_cast<uint32_t>(read_uint(4, prefix));
      }
      id &= 0x0fffffffu;
      const size_t start = pos_;
      const Member* m = member_by_id(t, id & 0x3fffu) ? member_by_id(t, id & 0x3fffu) : member_by_id(t, id);
      if (m) {
        // The member is aligned as if it started a stream of its own at this parameter.
        j[m->name] = walk(*m->type, prefix + m->name);
      }
      pos_ = start + size;
    }
  }

  Json walk_union(const Type& t, const std::string& path) {
    const std::string prefix = path.empty() ? "" : path + ".";
    const size_t end = xcdr2_ && t.extensibility != Extensibility::Final ? dheader_end(path) : 0;
    if (xcdr2_ && t.extensibility == Extensibility::Mutable) {
      throw CdrError(prefix + ": mutable unions are not supported");
    }
    const Json d = walk(*t.discriminator, prefix + "_d");
    int64_t value = 0;
    if (t.discriminator->kind == Kind::Enum) {
      for (const auto& l : t.discriminator->literals)
        if (d.is_string() && literal_json_name(*t.discriminator, l.name) == d.get<std::string>()) value = l.value;
      if (d.is_number()) value = d.get<int64_t>();
    } else if (d.is_boolean()) {
      value = d.get<bool>() ? 1 : 0;
    } else if (d.is_string()) {
      value = static_cast<unsigned char>(d.get<std::string>()[0]);
    } else {
      value = d.is_number_unsigned() ? static_cast<int64_t>(d.get<uint64_t>()) : d.get<int64_t>();
    }
    Json j = Json::object();
    j["_d"] = d;
    const Member* chosen = nullptr;
    for (const auto& m : t.members)
      for (int64_t label : m.labels)
        if (label == value && !chosen) chosen = &m;
    if (!chosen)
      for (const auto& m : t.members)
        if (m.is_default) chosen = &m;
    if (chosen) j[chosen->name] = walk(*chosen->type, prefix + chosen->name);
    skip_to(end);
    return j;
  }

  const WalkOptions& options_;
  const unsigned char* data_ = nullptr;
  size_t size_ = 0;
  size_t pos_ = 0;
  bool xcdr2_ = false;
  bool little_ = true;
};

}  // namespace

std::string base64(const unsigned char* data, size_t size) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  for (size_t i = 0; i < size; i += 3) {
    const uint32_t b0 = data[i];
    const uint32_t b1 = i + 1 < size ? data[i + 1] : 0;
    const uint32_t b2 = i + 2 < size ? data[i + 2] : 0;
    const uint32_t triple = (b0 << 16) | (b1 << 8) | b2;
    out += table[(triple >> 18) & 63];
    out += table[(triple >> 12) & 63];
    out += i + 1 < size ? table[(triple >> 6) & 63] : '=';
    out += i + 2 < size ? table[triple & 63] : '=';
  }
  return out;
}

Json cdr_to_json(const Type& type, const std::string& cdr, const WalkOptions& options) {
  CdrWalker walker(cdr, options);
  return walker.walk(type, "");
}

Json key_of(const Type& type, const Json& sample) {
  Json key = Json::object();
  for (const auto& m : type.members)
    if (m.key && sample.contains(m.name)) key[m.name] = sample[m.name];
  return key;
}

}  // namespace autonomy::xtypes
