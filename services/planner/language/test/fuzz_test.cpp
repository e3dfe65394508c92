// The readers (model and problem text, the model manager's checks, job-shop instances) on
// thousands of mutated copies of the shipped files: every input is either read or refused with
// errors that name the file at fault, a line inside it and a column, in readable text. Run in
// the sanitizer build too, where any out-of-bounds read or undefined arithmetic fails the test.
// Deterministic: the mutations come from fixed seeds.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "domain_model.hpp"
#include "jobshop_instance.hpp"
#include "planner_language.hpp"

namespace autonomy::planner {
namespace {

std::string slurp(const std::string& path) {
  Diagnostics errors;
  auto text = read_text_file(path, &errors);
  EXPECT_TRUE(text) << to_string(errors);
  return text.value_or("");
}

// splitmix64: the same sequence on every standard library (std distributions are not).
struct Random {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  std::size_t below(std::size_t n) { return n ? std::size_t(next() % n) : 0; }
};

// Where tokens begin and end, roughly as the lexers see them (runs of word characters, runs of
// blanks, single punctuation).
int char_class(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (u == ' ' || u == '\t' || u == '\n' || u == '\r') return 0;
  if (std::isalnum(u) || u == '_' || u == '.' || u == '?' || u >= 0x80) return 1;
  return 2;
}
std::vector<std::size_t> token_boundaries(const std::string& s) {
  std::vector<std::size_t> out{0};
  for (std::size_t i = 1; i < s.size(); ++i)
    if (char_class(s[i]) != char_class(s[i - 1]) || char_class(s[i]) == 2) out.push_back(i);
  out.push_back(s.size());
  return out;
}

const char* const kBigNumbers[] = {"4503599627370496",     "4503599627370495",
                                   "-4503599627370496",    "9223372036854775807",
                                   "9223372036854775808",  "-9223372036854775809",
                                   "99999999999999999999", "1e300",
                                   "1e999",                "1e-320",
                                   "2147483648",           "0.5",
                                   "-0",                   "inf"};

// Every mutation of `text` the test tries, each with a short description for failures.
std::vector<std::pair<std::string, std::string>> mutations(const std::string& text,
                                                           std::uint64_t seed, int random_cases) {
  std::vector<std::pair<std::string, std::string>> out;
  const std::vector<std::size_t> cut = token_boundaries(text);
  for (std::size_t b : cut) out.push_back({text.substr(0, b), "truncated at " + std::to_string(b)});
  out.push_back({"\xEF\xBB\xBF" + text.substr(0, text.size() / 2), "BOM, first half"});
  out.push_back({"\xEF\xBB\xBF\xEF\xBB\xBF" + text, "two BOMs"});
  out.push_back({text + "\xEF\xBB\xBF", "BOM at the end"});
  Random r{seed};
  for (int k = 0; k < random_cases; ++k) {
    std::string m = text;
    const std::size_t t = 1 + r.below(cut.size() - 1);  // a token: [cut[t-1], cut[t])
    const std::size_t from = cut[t - 1], to = cut[t];
    std::string what;
    switch (r.below(7)) {
      case 0: {  // one byte becomes any byte
        const std::size_t at = r.below(m.size());
        m[at] = char(r.below(256));
        what = "byte " + std::to_string(at) + " changed";
        break;
      }
      case 1:  // a token twice
        m.insert(from, text.substr(from, to - from));
        what = "token at " + std::to_string(from) + " duplicated";
        break;
      case 2:  // a token left out
        m.erase(from, to - from);
        what = "token at " + std::to_string(from) + " deleted";
        break;
      case 3: {  // a token becomes a large or odd number
        const char* big = kBigNumbers[r.below(std::size(kBigNumbers))];
        m.replace(from, to - from, big);
        what = "token at " + std::to_string(from) + " replaced by " + big;
        break;
      }
      case 4: {  // random bytes inserted
        std::string junk;
        for (std::size_t n = 1 + r.below(8); n > 0; --n) junk += char(r.below(256));
        m.insert(r.below(m.size() + 1), junk);
        what = "random bytes inserted";
        break;
      }
      case 5: {  // a line moved elsewhere
        const std::size_t at = r.below(m.size());
        std::size_t b = m.rfind('\n', at), e = m.find('\n', at);
        b = b == std::string::npos ? 0 : b + 1;
        e = e == std::string::npos ? m.size() : e + 1;
        std::string line = m.substr(b, e - b);
        m.erase(b, e - b);
        m.insert(r.below(m.size() + 1), line);
        what = "a line moved";
        break;
      }
      default:  // a token swapped with another one
      {
        const std::size_t u = 1 + r.below(cut.size() - 1);
        const std::string a = text.substr(from, to - from);
        const std::string b = text.substr(cut[u - 1], cut[u] - cut[u - 1]);
        if (u == t) break;
        if (u < t) {
          m.replace(from, to - from, b);
          m.replace(cut[u - 1], b.size(), a);
        } else {
          m.replace(cut[u - 1], b.size(), a);
          m.replace(from, to - from, b);
        }
        what = "two tokens swapped";
        break;
      }
    }
    out.push_back({m, what + " (seed " + std::to_string(seed) + ", case " + std::to_string(k) + ")"});
  }
  return out;
}

unsigned line_count(const std::string& s) {
  unsigned n = 1;
  for (char c : s) n += c == '\n';
  return n;
}

// The reader refused `text` (of `file`): every error names that file, a line in it and a
// column, in printable ASCII.
void expect_located(const Diagnostics& errors, const std::string& file, const std::string& text,
                    const std::string& what) {
  ASSERT_FALSE(errors.empty()) << what;
  for (const Diagnostic& d : errors) {
    EXPECT_EQ(d.file, file) << what << ": " << d.to_string();
    EXPECT_GE(d.line, 1u) << what << ": " << d.to_string();
    EXPECT_LE(d.line, line_count(text)) << what << ": " << d.to_string();
    EXPECT_GE(d.column, 1u) << what << ": " << d.to_string();
    for (char c : d.message) {
      const auto u = static_cast<unsigned char>(c);
      ASSERT_TRUE(u >= 0x20 && u < 0x7f) << what << ": unprintable byte in " << d.to_string();
    }
  }
}

struct Pair {
  const char* model;
  const char* problem;
};
const Pair kExamples[] = {{"camera.model", "camera.problem"},
                          {"ds1.model", "ds1-4h.problem"},
                          {"rover.model", "rover.problem"},
                          {"field-rover.model", "field-rover.problem"}};

TEST(ReaderFuzz, MutatedModelsAreReadOrRefusedWithTheirLocation) {
  std::size_t cases = 0, read = 0;
  std::uint64_t seed = 1;
  for (const Pair& p : kExamples) {
    const std::string text = slurp(std::string(PLANNER_EXAMPLES_DIR "/") + p.model);
    const std::string problem_text = slurp(std::string(PLANNER_EXAMPLES_DIR "/") + p.problem);
    Diagnostics problem_errors;
    const auto pbp = parse_problem(problem_text, p.problem, &problem_errors);
    ASSERT_TRUE(pbp) << to_string(problem_errors);
    for (const auto& [m, what] : mutations(text, seed++, 300)) {
      ++cases;
      Diagnostics errors;
      auto pbm = parse_model(m, p.model, &errors);
      std::optional<DomainModel> model;
      if (pbm) model = build_domain_model(*pbm, &errors);
      if (!model) {
        expect_located(errors, p.model, m, std::string(p.model) + ", " + what);
        continue;
      }
      ++read;
      EXPECT_TRUE(errors.empty()) << what;
      // The original problem against the changed model: its errors are the problem's lines.
      problem_errors.clear();
      if (!build_problem(*model, *pbp, &problem_errors))
        expect_located(problem_errors, p.problem, problem_text, std::string(p.model) + ", " + what);
      if (HasFatalFailure()) return;
    }
  }
  // The mutations reach both outcomes (a mutation set that only breaks files tests little).
  EXPECT_GT(cases, 3000u);
  EXPECT_GT(read, cases / 20);
  EXPECT_LT(read, cases);
}

TEST(ReaderFuzz, MutatedProblemsAreReadOrRefusedWithTheirLocation) {
  std::size_t cases = 0, read = 0;
  std::uint64_t seed = 100;
  for (const Pair& p : kExamples) {
    Diagnostics model_errors;
    auto pbm = parse_model(slurp(std::string(PLANNER_EXAMPLES_DIR "/") + p.model), p.model,
                           &model_errors);
    ASSERT_TRUE(pbm) << to_string(model_errors);
    auto model = build_domain_model(*pbm, &model_errors);
    ASSERT_TRUE(model) << to_string(model_errors);
    const std::string text = slurp(std::string(PLANNER_EXAMPLES_DIR "/") + p.problem);
    for (const auto& [m, what] : mutations(text, seed++, 600)) {
      ++cases;
      Diagnostics errors;
      auto pbp = parse_problem(m, p.problem, &errors);
      if (pbp && build_problem(*model, *pbp, &errors)) {
        ++read;
        EXPECT_TRUE(errors.empty()) << what;
        continue;
      }
      expect_located(errors, p.problem, m, std::string(p.problem) + ", " + what);
      if (HasFatalFailure()) return;
    }
  }
  EXPECT_GT(cases, 2000u);
  EXPECT_GT(read, cases / 20);
  EXPECT_LT(read, cases);
}

TEST(ReaderFuzz, MutatedJobShopInstancesAreReadOrRefusedWithTheirLocation) {
  std::size_t cases = 0, read = 0;
  std::uint64_t seed = 200;
  for (const char* name : {"ft06", "la01", "la02", "la03", "la04", "la05"}) {
    const std::string text = slurp(std::string(JOBSHOP_DIR "/") + name);
    for (const auto& [m, what] : mutations(text, seed++, 300)) {
      ++cases;
      Diagnostics errors;
      auto inst = parse_jobshop(m, name, &errors);
      if (!inst) {
        expect_located(errors, name, m, std::string(name) + ", " + what);
        if (HasFatalFailure()) return;
        continue;
      }
      // What the reader accepts makes a model and problem the model manager accepts.
      auto model = build_domain_model(jobshop_model(*inst), &errors);
      ASSERT_TRUE(model) << what << "\n" << to_string(errors);
      auto problem = build_problem(*model, jobshop_problem(*inst), &errors);
      ASSERT_TRUE(problem) << what << "\n" << to_string(errors);
      EXPECT_GT(problem->horizon, 0);
      ++read;
    }
  }
  EXPECT_GT(cases, 1000u);
  EXPECT_GT(read, cases / 20);
  EXPECT_LT(read, cases);
}

// The known ones, each at its place.
TEST(ReaderFuzz, AProblemEndingInGoalIsAnErrorAtTheEnd) {
  for (const char* tail : {"goal", "optional goal", "goal g", "goal g:"}) {
    const std::string text = std::string("problem p\nhorizon 10\n") + tail;
    Diagnostics errors;
    EXPECT_FALSE(parse_problem(text, "p.problem", &errors)) << tail;
    ASSERT_EQ(errors.size(), 1u) << tail;
    EXPECT_EQ(errors[0].to_string().substr(0, 12), "p.problem:3:") << errors[0].to_string();
    EXPECT_NE(errors[0].message.find("end of file"), std::string::npos) << errors[0].to_string();
  }
}

TEST(ReaderFuzz, AByteOrderMarkIsSkippedAndOtherBytesAreNamed) {
  const std::string model = slurp(PLANNER_EXAMPLES_DIR "/camera.model");
  Diagnostics errors;
  auto with_bom = parse_model("\xEF\xBB\xBF" + model, "camera.model", &errors);
  ASSERT_TRUE(with_bom) << to_string(errors);
  auto without = parse_model(model, "camera.model", &errors);
  EXPECT_EQ(with_bom->SerializeAsString(), without->SerializeAsString());
  EXPECT_TRUE(parse_jobshop("\xEF\xBB\xBF" + slurp(JOBSHOP_DIR "/ft06"), "ft06", &errors));
  EXPECT_TRUE(errors.empty()) << to_string(errors);

  EXPECT_FALSE(parse_model("model m\npredicate a\xC3\xA9()\n", "m.model", &errors));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].line, 2u);
  EXPECT_EQ(errors[0].column, 12u);
  EXPECT_NE(errors[0].message.find("unexpected byte 0xC3"), std::string::npos)
      << errors[0].to_string();
}

TEST(ReaderFuzz, JobShopNumbersThatOverflowAreErrorsAtTheirField) {
  struct Case {
    const char* text;
    unsigned line, column;
    const char* words;
  };
  const Case cases[] = {
      {"2 1\n0 4503599627370495\n0 1\n", 3, 3, "2^52"},
      {"1 2\n0 4503599627370496 1 5\n", 2, 3, "2^52"},
      {"1 1\n0 99999999999999999999\n", 2, 3, "expected a duration"},
      {"99999999999999999999 1\n0 1\n", 1, 1, "jobs machines"},
      {"# c\n1 1 7\n0 1\n", 2, 5, "end of the header"},
      {"1 2\n0 1 1\n", 2, 6, "without a duration"},
      {"1 1\n0 -3\n", 2, 3, "negative duration"},
      {"1 1\n0 x\n", 2, 3, "expected a duration"},
  };
  for (const Case& c : cases) {
    Diagnostics errors;
    EXPECT_FALSE(parse_jobshop(c.text, "j.txt", &errors)) << c.text;
    ASSERT_EQ(errors.size(), 1u) << c.text;
    EXPECT_EQ(errors[0].file, "j.txt");
    EXPECT_EQ(errors[0].line, c.line) << errors[0].to_string();
    EXPECT_EQ(errors[0].column, c.column) << errors[0].to_string();
    EXPECT_NE(errors[0].message.find(c.words), std::string::npos) << errors[0].to_string();
  }
}

}  // namespace
}  // namespace autonomy::planner
