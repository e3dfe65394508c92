#include <gtest/gtest.h>

#include <sstream>

#include "domain_model.hpp"
#include "jobshop_instance.hpp"
#include "planner_language.hpp"

namespace autonomy::planner {
namespace {

std::string slurp_example(const std::string& path) {
  Diagnostics errors;
  return read_text_file(path, &errors).value_or("");
}

TEST(PlannerLanguage, TheCameraExampleReadsAsInThePaper) {
  Diagnostics errors;
  auto pbm = parse_model(slurp_example(PLANNER_EXAMPLES_DIR "/camera.model"), "camera.model", &errors);
  ASSERT_TRUE(pbm) << to_string(errors);
  auto model = build_domain_model(*pbm, &errors);
  ASSERT_TRUE(model) << to_string(errors);
  EXPECT_EQ(model->classes.size(), 1u);
  EXPECT_EQ(model->classes[0].attributes.size(), 3u);
  ASSERT_EQ(model->schemata.size(), 3u);  // picture, pointAt (reached by a turn), turning
  const ConfigurationSchema& picture = model->schemata[0];
  EXPECT_EQ(model->predicates[picture.master.predicate].name, "picture");
  ASSERT_EQ(picture.requirements.size(), 4u);
  EXPECT_EQ(picture.requirements[0].relation, pb::TemporalRelation::CONTAINED_BY);
  EXPECT_EQ(picture.requirements[0].ub, kNoBound);
  EXPECT_EQ(picture.requirements[2].relation, pb::TemporalRelation::BEFORE);
  EXPECT_EQ(picture.requirements[2].ub, 0);
  // ?target is shared between the master and the pointAt slave.
  EXPECT_EQ(picture.requirements[1].alternatives[0].arguments[0].kind,
            PatternArgument::Kind::kVariable);
  EXPECT_EQ(picture.requirements[1].alternatives[0].arguments[0].variable,
            picture.master.arguments[0].variable);
  EXPECT_EQ(model->predicates[model->predicate("turning")].constraints.size(), 1u);

  auto pbp =
      parse_problem(slurp_example(PLANNER_EXAMPLES_DIR "/camera.problem"), "camera.problem", &errors);
  ASSERT_TRUE(pbp) << to_string(errors);
  auto problem = build_problem(*model, *pbp, &errors);
  ASSERT_TRUE(problem) << to_string(errors);
  EXPECT_EQ(problem->horizon, 200);
  ASSERT_EQ(problem->facts.size(), 4u);
  EXPECT_TRUE(problem->facts[0].initial);
  EXPECT_EQ(problem->facts[3].label, "shot");
  EXPECT_EQ(problem->facts[3].end_ub, 150);
}

TEST(PlannerLanguage, AllTwelveRelationsDisjunctionsAndResourcesParse) {
  const char* text = R"(model all
predicate a() duration [1, 5] uses power 3 consumes store 2
predicate b(x: real[0, 10], r: real[0, 1], d: real[0, 10], y: real[0, 20]) where x + r * d == y, x <= y
class C { attribute p = a | b  reusable power capacity 10  reservoir store [0, 100] initial 50 }
(p == a) before(p == b(_, _, _, _)) after[1, 2](p == a) startsBefore(p == a) startsAfter(p == a)
  endsBefore(p == a) endsAfter(p == a) startsBeforeEnd(p == a) endsAfterStart(p == a)
  contains(p == a) containedBy(p == a | p == b(1, _, _, _)) parallels(p == a) paralleledBy(p == a)
)";
  Diagnostics errors;
  auto pbm = parse_model(text, "all.model", &errors);
  ASSERT_TRUE(pbm) << to_string(errors);
  auto model = build_domain_model(*pbm, &errors);
  ASSERT_TRUE(model) << to_string(errors);
  ASSERT_EQ(model->schemata[0].requirements.size(), 12u);
  for (int i = 0; i < 12; ++i) EXPECT_EQ(int(model->schemata[0].requirements[i].relation), i);
  EXPECT_EQ(model->schemata[0].requirements[1].lb, 1);
  EXPECT_EQ(model->schemata[0].requirements[9].alternatives.size(), 2u);
  EXPECT_EQ(model->classes[0].resources.size(), 2u);
  EXPECT_EQ(model->classes[0].resources[1].initial_level, 50);
  EXPECT_EQ(model->predicates[0].effects[1].amount, -2);
  EXPECT_EQ(model->predicates[1].constraints[0].kind, pb::ParameterConstraint::SUM_PRODUCT);
}

// Each malformed model is reported at the line and column of the mistake.
struct BadCase {
  const char* text;
  unsigned line, column;
  const char* words;
};

TEST(PlannerLanguage, MistakesAreReportedAtFileLineColumn) {
  const std::string head = "model m\npredicate a()\npredicate b(x: int[0, 3])\n";
  const BadCase cases[] = {
      {"class C { attribute p = a | c }\n", 4, 21, "unknown predicate 'c'"},
      {"class C { attribute p = a }\n(q == a)\n", 5, 2, "unreachable schema"},
      {"class C { attribute p = a }\n(p == a) before(p == b(1))\n", 5, 17,
       "has no attribute 'p' that can take b"},
      {"class C { attribute p = a | b }\n(p == a) before[5, 2](p == b(1))\n", 5, 10, "exceeds"},
      {"class C { attribute p = a | b }\n(p == b(7))\n", 5, 9, "outside the parameter's range"},
      {"class C { attribute p = a | b }\n(p == b(1, 2))\n", 5, 2, "takes 1 parameters"},
      {"class C { attribute p = a }\n(p == a) sometime(p == a)\n", 5, 10, "expected"},
      {"predicate c(y: Nope)\n", 4, 13, "unknown type 'Nope'"},
      {"predicate c() duration [5, 2]\n", 4, 1, "duration lb > ub"},
      {"class C { attribute p = a $ }\n", 4, 27, "unexpected character"},
      {"predicate c(y: int[0, 2]) where y == z\n", 4, 38, "neither a parameter"},
      {"predicate c(y: int[0, 2], z: int[0, 9]) where (y, z) in {(1, 2), (3, 4)}\n", 4, 67,
       "outside the type of y"},
      {"predicate c(y: int[0, 2]) where (y, 5) in {(1, 2)}\n", 4, 37, "columns are parameters"},
      {"predicate c(y: int[0, 2], z: int[0, 9]) where (y, z) in {(1, 2, 3)}\n", 4, 63, "expected"},
      {"predicate c(y: int[0, 2]) where (y) in {(moon)}\n", 4, 42, "neither a parameter"},
      {"enum E { u, v }\npredicate c(e: E, y: int[0, 2]) where (e, y) in {(u, 1), (1, 2)}\n", 5, 59,
       "a number where e"},
  };
  for (const BadCase& c : cases) {
    Diagnostics errors;
    auto pbm = parse_model(head + c.text, "bad.model", &errors);
    if (pbm) build_domain_model(*pbm, &errors);
    ASSERT_FALSE(errors.empty()) << c.text;
    EXPECT_EQ(errors[0].file, "bad.model");
    EXPECT_EQ(errors[0].line, c.line) << c.text << errors[0].to_string();
    EXPECT_EQ(errors[0].column, c.column) << c.text << errors[0].to_string();
    EXPECT_NE(errors[0].message.find(c.words), std::string::npos) << errors[0].to_string();
  }
}

TEST(PlannerLanguage, ProblemMistakesNameTheStatement) {
  Diagnostics errors;
  auto pbm = parse_model(slurp_example(PLANNER_EXAMPLES_DIR "/camera.model"), "camera.model", &errors);
  auto model = build_domain_model(*pbm, &errors);
  ASSERT_TRUE(model);
  const char* cases[][2] = {
      {"problem p\nhorizon 10\nobject s : Spacecraft\ngoal s.camera == off\n", "cannot take 'off'"},
      {"problem p\nhorizon 10\nobject s : Spacecraft\ngoal s.wheel == off\n",
       "no attribute 'wheel'"},
      {"problem p\nhorizon 10\nobject s : Rover\n", "unknown class 'Rover'"},
      {"problem p\nhorizon 10\nobject s : Spacecraft\ngoal s.camera == picture(moon)\n",
       "not a value of enumeration Target"},
      {"problem p\nhorizon 10\nobject s : Spacecraft\ngoal g: s.camera == ready\ng before h\n",
       "unknown label 'h'"},
      {"problem p\nhorizon 10\nobject s : Spacecraft\ngoal s.camera == ready start [4, 3]\n",
       "start bounds: lb > ub"},
  };
  for (auto& c : cases) {
    Diagnostics e;
    auto pbp = parse_problem(c[0], "bad.problem", &e);
    ASSERT_TRUE(pbp) << to_string(e);
    EXPECT_FALSE(build_problem(*model, *pbp, &e));
    ASSERT_FALSE(e.empty()) << c[0];
    EXPECT_NE(e[0].message.find(c[1]), std::string::npos) << e[0].to_string();
    EXPECT_GE(e[0].line, 3u) << e[0].to_string();
  }
}

TEST(JobShop, Ft06ReadsIntoTimelinesAndGoals) {
  Diagnostics errors;
  auto inst = parse_jobshop(slurp_example(JOBSHOP_DIR "/ft06"), "ft06", &errors);
  ASSERT_TRUE(inst) << to_string(errors);
  EXPECT_EQ(inst->jobs, 6);
  EXPECT_EQ(inst->machines, 6);
  EXPECT_EQ(inst->operations[0][0], (std::pair<int, long>{2, 1}));
  auto model = build_domain_model(jobshop_model(*inst), &errors);
  ASSERT_TRUE(model) << to_string(errors);
  auto problem = build_problem(*model, jobshop_problem(*inst), &errors);
  ASSERT_TRUE(problem) << to_string(errors);
  EXPECT_EQ(problem->facts.size(), 36u);
  EXPECT_EQ(problem->relations.size(), 30u);
  EXPECT_EQ(problem->horizon, 197);  // the sum of ft06's durations
}

TEST(JobShop, MalformedInstancesNameTheLine) {
  Diagnostics errors;
  EXPECT_FALSE(parse_jobshop("2 2\n0 1 1 2\n0 3 7 1\n", "x", &errors));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].line, 3u);
  EXPECT_NE(errors[0].message.find("machine 7"), std::string::npos);
}

}  // namespace
}  // namespace autonomy::planner
