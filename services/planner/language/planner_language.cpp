#include "planner_language.hpp"

#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "domain_model.hpp"

namespace autonomy::planner {

namespace {

struct Token {
  enum Kind { kIdent, kNumber, kVariable, kPunct, kEnd } kind = kEnd;
  std::string text;
  double number = 0;
  unsigned line = 1, column = 1;
};

struct SyntaxError {
  unsigned line, column;
  std::string message;
};

// What an unexpected byte is, readable whatever it is (a control or non-ASCII byte printed raw
// would garble the message).
std::string unexpected(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (u > 0x20 && u < 0x7f) return std::string("unexpected character '") + c + "'";
  static const char hex[] = "0123456789ABCDEF";
  std::string text = "unexpected byte 0x";
  text += hex[u >> 4];
  text += hex[u & 15];
  text += u >= 0x80 ? " (outside comments the language is ASCII)" : " (a control character)";
  return text;
}

std::vector<Token> lex(std::string_view s) {
  std::vector<Token> out;
  unsigned line = 1, column = 1;
  // A UTF-8 byte-order mark (editors on some systems write one) is not part of the text.
  std::size_t i = s.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
  auto advance = [&](std::size_t n) {
    for (std::size_t k = 0; k < n && i < s.size(); ++k, ++i) {
      if (s[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
  };
  while (i < s.size()) {
    char c = s[i];
    if (std::isspace(static_cast<unsigned char>(c))) {
      advance(1);
      continue;
    }
    if (c == '#' || (c == '/' && i + 1 < s.size() && s[i + 1] == '/')) {
      while (i < s.size() && s[i] != '\n') advance(1);
      continue;
    }
    Token t;
    t.line = line;
    t.column = column;
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == '?') {
      std::size_t j = i + (c == '?');
      while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_')) ++j;
      if (c == '?' && j == i + 1) throw SyntaxError{line, column, "'?' must start a variable name"};
      t.kind = c == '?' ? Token::kVariable : Token::kIdent;
      t.text = std::string(s.substr(i + (c == '?'), j - i - (c == '?')));
      advance(j - i);
    } else if (std::isdigit(static_cast<unsigned char>(c)) ||
               (c == '.' && i + 1 < s.size() &&
                std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
      std::size_t j = i;
      while (j < s.size() && (std::isdigit(static_cast<unsigned char>(s[j])) || s[j] == '.')) ++j;
      if (j < s.size() && (s[j] == 'e' || s[j] == 'E')) {
        ++j;
        if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
        while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
      }
      t.kind = Token::kNumber;
      t.text = std::string(s.substr(i, j - i));
      try {
        std::size_t used = 0;
        t.number = std::stod(t.text, &used);
        if (used != t.text.size()) throw std::invalid_argument("");
      } catch (const std::out_of_range&) {
        throw SyntaxError{line, column, "number '" + t.text + "' is out of range"};
      } catch (const std::exception&) {
        throw SyntaxError{line, column, "malformed number '" + t.text + "'"};
      }
      advance(j - i);
    } else {
      static const char* two[] = {"==", "!=", "<=", ">="};
      t.kind = Token::kPunct;
      for (const char* p : two)
        if (s.substr(i, 2) == p) t.text = p;
      if (t.text.empty()) {
        if (std::string_view("()[]{},:.|=<>+-*_").find(c) == std::string_view::npos)
          throw SyntaxError{line, column, unexpected(c)};
        t.text = std::string(1, c);
      }
      advance(t.text.size());
    }
    out.push_back(std::move(t));
  }
  Token end;
  end.line = line;
  end.column = column;
  out.push_back(end);
  return out;
}

const std::map<std::string, pb::TemporalRelation::Kind>& relations() {
  static const std::map<std::string, pb::TemporalRelation::Kind> names = [] {
    std::map<std::string, pb::TemporalRelation::Kind> m;
    for (int k = pb::TemporalRelation::Kind_MIN; k <= pb::TemporalRelation::Kind_MAX; ++k)
      m[relation_name(pb::TemporalRelation::Kind(k))] = pb::TemporalRelation::Kind(k);
    return m;
  }();
  return names;
}

class Parser {
 public:
  Parser(std::vector<Token> tokens, std::string file)
      : t_(std::move(tokens)), file_(std::move(file)) {}

  pb::Model model() {
    pb::Model m;
    expect_word("model");
    m.set_name(ident("a model name"));
    while (!at_end()) {
      if (is_word("enum")) {
        enumeration(m.add_enums());
      } else if (is_word("predicate")) {
        predicate(m.add_predicates());
      } else if (is_word("class")) {
        model_class(m.add_classes());
      } else if (is_punct("(")) {
        schema(m.add_configuration_constraints());
      } else {
        fail(
            "expected enum, predicate, class or a configuration constraint '(attribute == value)'");
      }
    }
    return m;
  }

  pb::Problem problem() {
    pb::Problem p;
    *p.mutable_location() = here();
    expect_word("problem");
    p.set_name(ident("a problem name"));
    while (!at_end()) {
      if (accept_word("horizon")) {
        *p.mutable_location() = here();
        p.set_horizon(integer("the horizon"));
      } else if (accept_word("object")) {
        std::vector<pb::ObjectDeclaration> names;
        do {
          pb::ObjectDeclaration o;
          *o.mutable_location() = here();
          o.set_name(ident("an object name"));
          names.push_back(o);
        } while (accept_punct(","));
        expect_punct(":");
        std::string cls = ident("a class name");
        for (auto& o : names) {
          o.set_class_name(cls);
          *p.add_objects() = o;
        }
      } else if (accept_word("initial")) {
        fact(p.add_initial(), false);
      } else if (is_word("optional") || is_word("goal")) {
        bool optional = accept_word("optional");
        expect_word("goal");
        pb::Fact* f = p.add_goals();
        f->set_optional(optional);
        fact(f, true);
      } else if (accept_word("minimize")) {
        if (accept_word("makespan")) {
          p.set_objective(pb::Problem::MAKESPAN);
        } else if (accept_word("penalty")) {
          p.set_objective(pb::Problem::PENALTY);
        } else {
          fail("expected 'makespan' or 'penalty' after 'minimize'");
        }
      } else if (peek().kind == Token::kIdent) {
        pb::FactRelation* r = p.add_relations();
        *r->mutable_location() = here();
        r->set_from(ident("a goal label"));
        relation(r->mutable_relation());
        r->set_to(ident("a goal label"));
      } else {
        fail(
            "expected horizon, object, initial, goal, optional goal, minimize or '<label> "
            "<relation> <label>'");
      }
    }
    return p;
  }

 private:
  // The token `ahead` places on; past the end it is the end token (the lexer always ends the
  // list with one), so no lookahead reads beyond the list.
  const Token& peek(std::size_t ahead = 0) const {
    return ahead < t_.size() - pos_ ? t_[pos_ + ahead] : t_.back();
  }
  bool at_end() const { return peek().kind == Token::kEnd; }
  pb::Location here() const {
    pb::Location l;
    l.set_file(file_);
    l.set_line(peek().line);
    l.set_column(peek().column);
    return l;
  }
  [[noreturn]] void fail(const std::string& message) const {
    std::string found = at_end() ? "end of file" : "'" + peek().text + "'";
    throw SyntaxError{peek().line, peek().column, message + " (found " + found + ")"};
  }
  bool is_word(const char* w) const { return peek().kind == Token::kIdent && peek().text == w; }
  bool is_punct(const char* p) const { return peek().kind == Token::kPunct && peek().text == p; }
  bool accept_word(const char* w) {
    if (!is_word(w)) return false;
    ++pos_;
    return true;
  }
  bool accept_punct(const char* p) {
    if (!is_punct(p)) return false;
    ++pos_;
    return true;
  }
  void expect_word(const char* w) {
    if (!accept_word(w)) fail(std::string("expected '") + w + "'");
  }
  void expect_punct(const char* p) {
    if (!accept_punct(p)) fail(std::string("expected '") + p + "'");
  }
  std::string ident(const char* what) {
    if (peek().kind != Token::kIdent) fail(std::string("expected ") + what);
    return t_[pos_++].text;
  }
  // A number, possibly signed, or inf.
  double number(const char* what) {
    double sign = 1;
    if (accept_punct("-"))
      sign = -1;
    else
      accept_punct("+");
    if (accept_word("inf")) return sign * HUGE_VAL;
    if (peek().kind != Token::kNumber) fail(std::string("expected ") + what);
    return sign * t_[pos_++].number;
  }
  std::int64_t integer(const char* what) {
    const Token at = peek();
    double v = number(what);
    if (std::isinf(v)) return v > 0 ? kNoBound : -kNoBound;
    if (v != std::floor(v))
      throw SyntaxError{at.line, at.column,
                        std::string(what) + " must be an integer (time is in ticks)"};
    if (std::abs(v) >= double(kNoBound))
      throw SyntaxError{at.line, at.column,
                        std::string(what) + " must lie within +-2^52 ticks ('inf' for none)"};
    return std::int64_t(v);
  }
  // '[' lb ',' ub ']' as time bounds.
  pb::Bounds time_range(const char* what) {
    expect_punct("[");
    pb::Bounds b;
    b.set_lb(integer(what));
    expect_punct(",");
    b.set_ub(integer(what));
    expect_punct("]");
    return b;
  }

  void enumeration(pb::EnumType* e) {
    *e->mutable_location() = here();
    expect_word("enum");
    e->set_name(ident("an enumeration name"));
    expect_punct("{");
    do {
      e->add_values(ident("an enumeration value"));
    } while (accept_punct(","));
    expect_punct("}");
  }

  void predicate(pb::Predicate* p) {
    *p->mutable_location() = here();
    expect_word("predicate");
    p->set_name(ident("a predicate name"));
    if (accept_punct("(")) {
      if (!accept_punct(")")) {
        do {
          pb::Parameter* param = p->add_parameters();
          *param->mutable_location() = here();
          param->set_name(ident("a parameter name"));
          expect_punct(":");
          pb::ParameterType* type = param->mutable_type();
          if (is_word("int") || is_word("real")) {
            const bool is_int = is_word("int");
            ++pos_;
            type->set_kind(is_int ? pb::ParameterType::INTEGER : pb::ParameterType::REAL);
            expect_punct("[");
            type->set_lb(number("a lower bound"));
            expect_punct(",");
            type->set_ub(number("an upper bound"));
            expect_punct("]");
          } else {
            type->set_kind(pb::ParameterType::ENUMERATION);  // or OBJECT: the model manager decides
            type->set_type_name(
                ident("a type (int[lb, ub], real[lb, ub], an enumeration or a class)"));
          }
        } while (accept_punct(","));
        expect_punct(")");
      }
    }
    while (true) {
      if (accept_word("duration")) {
        *p->mutable_duration() = time_range("a duration bound");
      } else if (accept_word("where")) {
        do {
          parameter_constraint(p->add_constraints());
        } while (accept_punct(","));
      } else if (is_word("uses") || is_word("produces") || is_word("consumes")) {
        double sign = is_word("consumes") ? -1 : 1;
        ++pos_;
        pb::ResourceEffect* e = p->add_effects();
        *e->mutable_location() = here();
        e->set_resource(ident("a resource name"));
        e->set_amount(sign * number("an amount"));
      } else {
        break;
      }
    }
  }

  pb::Term term() {
    pb::Term t;
    *t.mutable_location() = here();
    if (peek().kind == Token::kIdent && peek().text != "inf") {
      t.set_parameter(t_[pos_++].text);
    } else {
      t.set_number(number("a parameter, 'duration' or a number"));
    }
    return t;
  }

  void parameter_constraint(pb::ParameterConstraint* c) {
    *c->mutable_location() = here();
    if (accept_punct("(")) {  // (x, y, ...) in {(a, b, ...), ...}
      c->set_kind(pb::ParameterConstraint::TABLE);
      do {
        *c->add_terms() = term();
      } while (accept_punct(","));
      expect_punct(")");
      c->set_arity(std::uint32_t(c->terms_size()));
      expect_word("in");
      expect_punct("{");
      do {
        expect_punct("(");
        for (std::uint32_t i = 0; i < c->arity(); ++i) {
          if (i) expect_punct(",");
          *c->add_terms() = term();
        }
        expect_punct(")");
      } while (accept_punct(","));
      expect_punct("}");
      return;
    }
    pb::Term first = term();
    if (accept_word("in")) {
      c->set_kind(pb::ParameterConstraint::MEMBER);
      *c->add_terms() = first;
      expect_punct("{");
      do {
        *c->add_terms() = term();
      } while (accept_punct(","));
      expect_punct("}");
      return;
    }
    if (accept_punct("+")) {  // s + r * d == e
      pb::Term r = term();
      expect_punct("*");
      pb::Term d = term();
      expect_punct("==");
      c->set_kind(pb::ParameterConstraint::SUM_PRODUCT);
      *c->add_terms() = first;
      *c->add_terms() = r;
      *c->add_terms() = d;
      *c->add_terms() = term();
      return;
    }
    const std::string op = peek().text;
    if (peek().kind != Token::kPunct ||
        (op != "==" && op != "!=" && op != "<=" && op != "<" && op != ">=" && op != ">"))
      fail("expected ==, !=, <=, <, >=, >, 'in' or '+' in a parameter constraint");
    ++pos_;
    pb::Term second = term();
    bool swap = op == ">=" || op == ">";
    c->set_kind(op == "=="                   ? pb::ParameterConstraint::EQUAL
                : op == "!="                 ? pb::ParameterConstraint::NOT_EQUAL
                : (op == "<=" || op == ">=") ? pb::ParameterConstraint::LESS_EQUAL
                                             : pb::ParameterConstraint::LESS);
    *c->add_terms() = swap ? second : first;
    *c->add_terms() = swap ? first : second;
  }

  void model_class(pb::ModelClass* c) {
    *c->mutable_location() = here();
    expect_word("class");
    c->set_name(ident("a class name"));
    expect_punct("{");
    while (!accept_punct("}")) {
      if (accept_word("attribute")) {
        pb::Attribute* a = c->add_attributes();
        *a->mutable_location() = here();
        a->set_name(ident("an attribute name"));
        expect_punct("=");
        do {
          a->add_values(ident("a predicate name"));
        } while (accept_punct("|"));
      } else if (is_word("reusable") || is_word("reservoir")) {
        pb::Resource* r = c->add_resources();
        *r->mutable_location() = here();
        bool reusable = accept_word("reusable");
        if (!reusable) ++pos_;
        r->set_kind(reusable ? pb::Resource::REUSABLE : pb::Resource::RESERVOIR);
        r->set_name(ident("a resource name"));
        if (reusable) {
          expect_word("capacity");
          r->set_capacity(number("a capacity"));
        } else {
          expect_punct("[");
          r->set_min_level(number("a minimum level"));
          expect_punct(",");
          r->set_max_level(number("a maximum level"));
          expect_punct("]");
          r->set_initial_level(r->min_level());
          if (accept_word("initial")) r->set_initial_level(number("an initial level"));
        }
      } else {
        fail("expected 'attribute', 'reusable', 'reservoir' or '}'");
      }
    }
  }

  void arguments(google::protobuf::RepeatedPtrField<pb::Argument>* args) {
    if (!accept_punct("(")) return;
    if (accept_punct(")")) return;
    do {
      pb::Argument* a = args->Add();
      *a->mutable_location() = here();
      if (peek().kind == Token::kVariable) {
        a->set_variable(t_[pos_++].text);
      } else if (accept_punct("_") || accept_word("_")) {
        a->set_any(true);
      } else if (peek().kind == Token::kIdent && peek().text != "inf") {
        a->set_symbol(t_[pos_++].text);
      } else {
        a->set_number(number("an argument (?variable, a value, a number or _)"));
      }
    } while (accept_punct(","));
    expect_punct(")");
  }

  void pattern(pb::ValuePattern* v) {
    *v->mutable_location() = here();
    v->set_attribute(ident("an attribute name"));
    expect_punct("==");
    v->set_predicate(ident("a predicate name"));
    arguments(v->mutable_arguments());
  }

  void relation(pb::TemporalRelation* r) {
    const Token at = peek();
    if (at.kind != Token::kIdent || !relations().count(at.text))
      fail(
          "expected a temporal relation (before, after, startsBefore, startsAfter, endsBefore, "
          "endsAfter, startsBeforeEnd, endsAfterStart, contains, containedBy, parallels, "
          "paralleledBy)");
    ++pos_;
    r->set_kind(relations().at(at.text));
    r->mutable_bounds()->set_lb(0);
    r->mutable_bounds()->set_ub(kNoBound);
    if (is_punct("[")) *r->mutable_bounds() = time_range("a distance bound");
  }

  void schema(pb::ConfigurationConstraint* c) {
    *c->mutable_location() = here();
    expect_punct("(");
    pattern(c->mutable_master());
    expect_punct(")");
    while (peek().kind == Token::kIdent && relations().count(peek().text)) {
      pb::Requirement* rq = c->add_requirements();
      *rq->mutable_location() = here();
      relation(rq->mutable_relation());
      expect_punct("(");
      do {
        pattern(rq->add_alternatives());
      } while (accept_punct("|"));
      expect_punct(")");
    }
  }

  void fact(pb::Fact* f, bool goal) {
    *f->mutable_location() = here();
    if (goal && peek(1).kind == Token::kPunct && peek(1).text == ":") {
      f->set_label(ident("a goal label"));
      ++pos_;
    }
    f->set_object(ident("an object name"));
    expect_punct(".");
    f->set_attribute(ident("an attribute name"));
    expect_punct("==");
    f->set_predicate(ident("a predicate name"));
    arguments(f->mutable_arguments());
    while (true) {
      if (accept_word("start")) {
        *f->mutable_start() = time_range("a start bound");
      } else if (accept_word("end")) {
        *f->mutable_end() = time_range("an end bound");
      } else if (accept_word("duration")) {
        *f->mutable_duration() = time_range("a duration bound");
      } else if (goal && accept_word("penalty")) {
        f->set_penalty(number("a penalty"));
      } else {
        break;
      }
    }
  }

  std::vector<Token> t_;
  std::string file_;
  std::size_t pos_ = 0;
};

template <typename Message, typename Parse>
std::optional<Message> run(std::string_view text, const std::string& file, Diagnostics* errors,
                           Parse parse) {
  try {
    Parser parser(lex(text), file);
    return parse(parser);
  } catch (const SyntaxError& e) {
    errors->push_back({file, e.line, e.column, e.message});
    return std::nullopt;
  }
}

}  // namespace

std::optional<pb::Model> parse_model(std::string_view text, const std::string& file,
                                     Diagnostics* errors) {
  return run<pb::Model>(text, file, errors, [](Parser& p) { return p.model(); });
}

std::optional<pb::Problem> parse_problem(std::string_view text, const std::string& file,
                                         Diagnostics* errors) {
  return run<pb::Problem>(text, file, errors, [](Parser& p) { return p.problem(); });
}

std::optional<std::string> read_text_file(const std::string& path, Diagnostics* errors) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    errors->push_back({path, 0, 0, "cannot open the file"});
    return std::nullopt;
  }
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace autonomy::planner
