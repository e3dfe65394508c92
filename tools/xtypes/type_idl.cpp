#include "tools/xtypes/type_idl.hpp"

#include <set>
#include <sstream>
#include <vector>

namespace autonomy::xtypes {

namespace {

bool is_named(const Type& t) {
  return t.kind == Kind::Struct || t.kind == Kind::Union || t.kind == Kind::Enum || t.kind == Kind::Bitmask;
}

// The named types t uses, dependencies first (a type that contains itself is listed once).
void collect_named(const TypePtr& t, std::set<const Type*>& seen, std::vector<TypePtr>& out) {
  if (!t) return;
  if (is_named(*t)) {
    if (!seen.insert(t.get()).second) return;
  }
  collect_named(t->element, seen, out);
  collect_named(t->discriminator, seen, out);
  for (const auto& m : t->members) collect_named(m.type, seen, out);
  if (is_named(*t)) out.push_back(t);
}

std::string reference(const Type& t) {
  switch (t.kind) {
    case Kind::String: return t.bound ? "string<" + std::to_string(t.bound) + ">" : "string";
    case Kind::Sequence:
      return "sequence<" + reference(*t.element) + (t.bound ? ", " + std::to_string(t.bound) : "") + ">";
    case Kind::Array: return reference(*t.element);  // the dimensions follow the member name
    case Kind::Struct: case Kind::Union: case Kind::Enum: case Kind::Bitmask: return "::" + t.name;
    default: return kind_name(t.kind);
  }
}

std::string dims(const Type& t) {
  std::string s;
  if (t.kind == Kind::Array)
    for (uint32_t d : t.dims) s += "[" + std::to_string(d) + "]";
  return s;
}

const char* extensibility_annotation(Extensibility e) {
  return e == Extensibility::Mutable ? "@mutable" : e == Extensibility::Appendable ? "@appendable" : "@final";
}

void print_definition(const Type& t, std::ostream& os) {
  std::vector<std::string> modules;
  std::string rest = t.name;
  for (size_t cut; (cut = rest.find("::")) != std::string::npos; rest = rest.substr(cut + 2))
    modules.push_back(rest.substr(0, cut));
  std::string indent;
  for (const auto& m : modules) {
    os << indent << "module " << m << " {\n";
    indent += "  ";
  }
  switch (t.kind) {
    case Kind::Struct:
      os << indent << extensibility_annotation(t.extensibility) << "\n" << indent << "struct " << rest << " {\n";
      for (const auto& m : t.members)
        os << indent << "  " << (m.key ? "@key " : "") << (m.optional ? "@optional " : "") << reference(*m.type) << " "
           << m.name << dims(*m.type) << ";\n";
      os << indent << "};\n";
      break;
    case Kind::Union:
      os << indent << extensibility_annotation(t.extensibility) << "\n"
         << indent << "union " << rest << " switch (" << reference(*t.discriminator) << ") {\n";
      for (const auto& m : t.members) {
        for (int64_t label : m.labels) {
          std::string shown = std::to_string(label);
          if (t.discriminator->kind == Kind::Enum)
            for (const auto& l : t.discriminator->literals)
              if (l.value == label) shown = l.name;
          os << indent << "  case " << shown << ":\n";
        }
        if (m.is_default) os << indent << "  default:\n";
        os << indent << "    " << reference(*m.type) << " " << m.name << dims(*m.type) << ";\n";
      }
      os << indent << "};\n";
      break;
    case Kind::Enum:
      if (t.bit_bound != 32) os << indent << "@bit_bound(" << t.bit_bound << ")\n";
      os << indent << "enum " << rest << " {\n";
      for (size_t i = 0; i < t.literals.size(); ++i)
        os << indent << "  " << t.literals[i].name << (i + 1 < t.literals.size() ? "," : "") << "\n";
      os << indent << "};\n";
      break;
    case Kind::Bitmask:
      os << indent << "@bit_bound(" << t.bit_bound << ")\n" << indent << "bitmask " << rest << " {\n";
      for (size_t i = 0; i < t.literals.size(); ++i)
        os << indent << "  @position(" << t.literals[i].value << ") " << t.literals[i].name
           << (i + 1 < t.literals.size() ? "," : "") << "\n";
      os << indent << "};\n";
      break;
    default:
      break;
  }
  for (size_t i = modules.size(); i > 0; --i) {
    indent.resize(indent.size() - 2);
    os << indent << "};\n";
  }
}

}  // namespace

std::string to_idl(const TypePtr& type) {
  std::set<const Type*> seen;
  std::vector<TypePtr> named;
  collect_named(type, seen, named);
  std::ostringstream os;
  for (size_t i = 0; i < named.size(); ++i) {
    if (i) os << "\n";
    print_definition(*named[i], os);
  }
  if (named.empty() && type) os << reference(*type) << "\n";
  return os.str();
}

}  // namespace autonomy::xtypes
