#include "tools/xtypes/type_lookup.hpp"

#include <dds/ddsi/ddsi_xt_typeinfo.h>

#include <cstring>

namespace autonomy::xtypes {

namespace {

// Cyclone's dds_typeid_t, dds_typeinfo_t and dds_typeobj_t wrap the XTypes structs as their only
// member (struct ddsi_typeid { DDS_XTypes_TypeIdentifier x; } in dds/ddsi/ddsi_xt_impl.h, a
// header that does not compile as C++), so a pointer to one is a pointer to the other.
const DDS_XTypes_TypeInformation& information_of(const dds_typeinfo_t* info) {
  return *reinterpret_cast<const DDS_XTypes_TypeInformation*>(info);
}
const dds_typeid_t* as_typeid(const DDS_XTypes_TypeIdentifier& id) { return reinterpret_cast<const dds_typeid_t*>(&id); }

std::string hash_key(const DDS_XTypes_TypeIdentifier& id) {
  return std::string(reinterpret_cast<const char*>(id._u.equivalence_hash), sizeof(id._u.equivalence_hash));
}

Extensibility extensibility_of(uint16_t flags) {
  if (flags & DDS_XTypes_IS_MUTABLE) return Extensibility::Mutable;
  if (flags & DDS_XTypes_IS_APPENDABLE) return Extensibility::Appendable;
  return Extensibility::Final;
}

TypePtr primitive(uint8_t d) {
  switch (d) {
    case DDS_XTypes_TK_BOOLEAN: return make_type(Kind::Bool);
    case DDS_XTypes_TK_BYTE: return make_type(Kind::Byte);
    case DDS_XTypes_TK_INT16: return make_type(Kind::Int16);
    case DDS_XTypes_TK_INT32: return make_type(Kind::Int32);
    case DDS_XTypes_TK_INT64: return make_type(Kind::Int64);
    case DDS_XTypes_TK_UINT16: return make_type(Kind::UInt16);
    case DDS_XTypes_TK_UINT32: return make_type(Kind::UInt32);
    case DDS_XTypes_TK_UINT64: return make_type(Kind::UInt64);
    case DDS_XTypes_TK_FLOAT32: return make_type(Kind::Float32);
    case DDS_XTypes_TK_FLOAT64: return make_type(Kind::Float64);
    case DDS_XTypes_TK_CHAR8: return make_type(Kind::Char8);
    case 12: return make_type(Kind::Int8);   // TK_INT8 (XTypes 1.3)
    case 13: return make_type(Kind::UInt8);  // TK_UINT8
    default: return nullptr;
  }
}

}  // namespace

TypePtr TypeLookup::resolve(const dds_typeinfo_t* type_info) {
  if (!type_info) throw TypeLookupError("no type information (the writer's DDS sends none)");
  const auto& complete = information_of(type_info).complete.typeid_with_size.type_id;
  if (complete._d != DDS_XTypes_EK_COMPLETE)
    throw TypeLookupError("the type information has no complete type (member names): only a minimal one");
  return from_identifier(complete);
}

TypePtr TypeLookup::resolve_entity(dds_entity_t entity) {
  dds_typeinfo_t* info = nullptr;
  const dds_return_t rc = dds_get_typeinfo(entity, &info);
  if (rc != DDS_RETCODE_OK) throw TypeLookupError(std::string("dds_get_typeinfo: ") + dds_strretcode(rc));
  try {
    TypePtr t = resolve(info);
    dds_free_typeinfo(info);
    return t;
  } catch (...) {
    dds_free_typeinfo(info);
    throw;
  }
}

TypePtr TypeLookup::from_identifier(const DDS_XTypes_TypeIdentifier& id) {
  if (TypePtr p = primitive(id._d)) return p;
  switch (id._d) {
    case DDS_XTypes_TI_STRING8_SMALL: {
      auto t = make_type(Kind::String);
      t->bound = id._u.string_sdefn.bound;
      return t;
    }
    case DDS_XTypes_TI_STRING8_LARGE: {
      auto t = make_type(Kind::String);
      t->bound = id._u.string_ldefn.bound;
      return t;
    }
    case DDS_XTypes_TI_PLAIN_SEQUENCE_SMALL: {
      auto t = make_type(Kind::Sequence);
      t->bound = id._u.seq_sdefn.bound;
      t->element = from_identifier(*id._u.seq_sdefn.element_identifier);
      return t;
    }
    case DDS_XTypes_TI_PLAIN_SEQUENCE_LARGE: {
      auto t = make_type(Kind::Sequence);
      t->bound = id._u.seq_ldefn.bound;
      t->element = from_identifier(*id._u.seq_ldefn.element_identifier);
      return t;
    }
    case DDS_XTypes_TI_PLAIN_ARRAY_SMALL: {
      auto t = make_type(Kind::Array);
      const auto& b = id._u.array_sdefn.array_bound_seq;
      for (uint32_t i = 0; i < b._length; ++i) t->dims.push_back(b._buffer[i]);
      t->element = from_identifier(*id._u.array_sdefn.element_identifier);
      return t;
    }
    case DDS_XTypes_TI_PLAIN_ARRAY_LARGE: {
      auto t = make_type(Kind::Array);
      const auto& b = id._u.array_ldefn.array_bound_seq;
      for (uint32_t i = 0; i < b._length; ++i) t->dims.push_back(b._buffer[i]);
      t->element = from_identifier(*id._u.array_ldefn.element_identifier);
      return t;
    }
    case DDS_XTypes_EK_COMPLETE: {
      const std::string key = hash_key(id);
      if (auto it = by_hash_.find(key); it != by_hash_.end()) return it->second;
      dds_typeobj_t* obj = nullptr;
      const dds_return_t rc = dds_get_typeobj(entity_, as_typeid(id), timeout_, &obj);
      if (rc != DDS_RETCODE_OK)
        throw TypeLookupError(std::string("type object not available (dds_get_typeobj: ") + dds_strretcode(rc) + ")");
      const auto* object = reinterpret_cast<const DDS_XTypes_TypeObject*>(obj);
      try {
        if (object->_d != DDS_XTypes_EK_COMPLETE) throw TypeLookupError("got a minimal type object, not a complete one");
        auto t = std::make_shared<Type>();
        by_hash_[key] = t;  // before the members: a type may contain itself (a sequence of itself)
        TypePtr done = from_object(object->_u.complete, t);
        if (done != t) by_hash_[key] = done;  // an alias stands for another type
        dds_free_typeobj(obj);
        return done;
      } catch (...) {
        dds_free_typeobj(obj);
        throw;
      }
    }
    case DDS_XTypes_EK_MINIMAL:
      throw TypeLookupError("only a minimal type identifier (no member names)");
    case DDS_XTypes_TI_STRING16_SMALL:
    case DDS_XTypes_TI_STRING16_LARGE:
    case DDS_XTypes_TK_CHAR16:
      throw TypeLookupError("wide characters and wide strings are not supported");
    default:
      throw TypeLookupError("unsupported type identifier kind " + std::to_string(id._d));
  }
}

TypePtr TypeLookup::from_object(const DDS_XTypes_CompleteTypeObject& o, TypePtr t) {
  switch (o._d) {
    case DDS_XTypes_TK_ALIAS:
      return from_identifier(o._u.alias_type.body.common.related_type);
    case DDS_XTypes_TK_STRUCTURE: {
      const auto& s = o._u.struct_type;
      t->kind = Kind::Struct;
      t->name = s.header.detail.type_name;
      t->extensibility = extensibility_of(s.struct_flags);
      if (s.header.base_type._d != DDS_XTypes_TK_NONE) {
        const TypePtr base = from_identifier(s.header.base_type);
        t->members = base->members;
      }
      for (uint32_t i = 0; i < s.member_seq._length; ++i) {
        const auto& m = s.member_seq._buffer[i];
        Member member;
        member.name = m.detail.name;
        member.id = m.common.member_id;
        member.key = (m.common.member_flags & DDS_XTypes_IS_KEY) != 0;
        member.optional = (m.common.member_flags & DDS_XTypes_IS_OPTIONAL) != 0;
        member.type = from_identifier(m.common.member_type_id);
        t->members.push_back(std::move(member));
      }
      return t;
    }
    case DDS_XTypes_TK_UNION: {
      const auto& u = o._u.union_type;
      t->kind = Kind::Union;
      t->name = u.header.detail.type_name;
      t->extensibility = extensibility_of(u.union_flags);
      t->discriminator = from_identifier(u.discriminator.common.type_id);
      for (uint32_t i = 0; i < u.member_seq._length; ++i) {
        const auto& m = u.member_seq._buffer[i];
        Member member;
        member.name = m.detail.name;
        member.id = m.common.member_id;
        member.is_default = (m.common.member_flags & DDS_XTypes_IS_DEFAULT) != 0;
        for (uint32_t k = 0; k < m.common.label_seq._length; ++k) member.labels.push_back(m.common.label_seq._buffer[k]);
        member.type = from_identifier(m.common.type_id);
        t->members.push_back(std::move(member));
      }
      return t;
    }
    case DDS_XTypes_TK_ENUM: {
      const auto& e = o._u.enumerated_type;
      t->kind = Kind::Enum;
      t->name = e.header.detail.type_name;
      t->bit_bound = e.header.common.bit_bound;
      for (uint32_t i = 0; i < e.literal_seq._length; ++i)
        t->literals.push_back({e.literal_seq._buffer[i].detail.name, e.literal_seq._buffer[i].common.value});
      return t;
    }
    case DDS_XTypes_TK_BITMASK: {
      const auto& b = o._u.bitmask_type;
      t->kind = Kind::Bitmask;
      t->name = b.header.detail.type_name;
      t->bit_bound = b.header.common.bit_bound;
      for (uint32_t i = 0; i < b.flag_seq._length; ++i)
        t->literals.push_back({b.flag_seq._buffer[i].detail.name, b.flag_seq._buffer[i].common.position});
      return t;
    }
    case DDS_XTypes_TK_SEQUENCE: {
      const auto& s = o._u.sequence_type;
      t->kind = Kind::Sequence;
      t->bound = s.header.common.bound;
      t->element = from_identifier(s.element.common.type);
      return t;
    }
    case DDS_XTypes_TK_ARRAY: {
      const auto& a = o._u.array_type;
      t->kind = Kind::Array;
      for (uint32_t i = 0; i < a.header.common.bound_seq._length; ++i) t->dims.push_back(a.header.common.bound_seq._buffer[i]);
      t->element = from_identifier(a.element.common.type);
      return t;
    }
    default:
      throw TypeLookupError("unsupported type kind " + std::to_string(o._d) + " (maps, bitsets and annotations are not)");
  }
}

}  // namespace autonomy::xtypes
