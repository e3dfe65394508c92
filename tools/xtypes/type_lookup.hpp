#pragma once
// The type of a topic from the XTypes type information Cyclone DDS exchanges in discovery:
// the complete type object (names included) of the topic's type and of every type it uses,
// asked of the domain's type library with dds_get_typeobj, which sends a type lookup request to
// the process that has the type when this one does not know it yet.
//
// Works for the project's own types (registered in the domain by creating the topic) and for any
// other process's types (from the type information in its DCPSPublication / DCPSSubscription).
#include <dds/dds.h>

#include <map>
#include <stdexcept>
#include <string>

#include "tools/xtypes/type_tree.hpp"

struct DDS_XTypes_TypeIdentifier;
struct DDS_XTypes_CompleteTypeObject;

namespace autonomy::xtypes {

class TypeLookupError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class TypeLookup {
 public:
  // entity: a participant (or any entity of the domain); timeout: how long one type may take
  // to arrive from another process.
  TypeLookup(dds_entity_t entity, dds_duration_t timeout) : entity_(entity), timeout_(timeout) {}

  // The type that type_info describes (its complete type identifier). Throws TypeLookupError.
  TypePtr resolve(const dds_typeinfo_t* type_info);
  // The type of a topic, reader or writer entity.
  TypePtr resolve_entity(dds_entity_t entity);

 private:
  TypePtr from_identifier(const DDS_XTypes_TypeIdentifier& id);
  TypePtr from_object(const DDS_XTypes_CompleteTypeObject& object, TypePtr into);

  dds_entity_t entity_;
  dds_duration_t timeout_;
  std::map<std::string, TypePtr> by_hash_;  // also breaks recursion: a type is cached before its members
};

}  // namespace autonomy::xtypes
