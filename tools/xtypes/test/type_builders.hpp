#pragma once
// Type trees made by hand for the walker's and the encoder's tests (what type_lookup.cpp builds
// from type objects).
#include <string>
#include <utility>
#include <vector>

#include "tools/xtypes/type_tree.hpp"

namespace autonomy::xtypes::test {

inline TypePtr prim(Kind k) { return make_type(k); }
inline TypePtr seq(TypePtr e) {
  auto t = make_type(Kind::Sequence);
  t->element = std::move(e);
  return t;
}
inline TypePtr strukt(const std::string& name, std::vector<Member> members, Extensibility ext = Extensibility::Final) {
  auto t = make_type(Kind::Struct);
  t->name = name;
  t->members = std::move(members);
  t->extensibility = ext;
  return t;
}
inline Member mem(const std::string& name, TypePtr t, uint32_t id = 0, bool key = false) {
  Member m;
  m.name = name;
  m.type = std::move(t);
  m.id = id;
  m.key = key;
  return m;
}

}  // namespace autonomy::xtypes::test
