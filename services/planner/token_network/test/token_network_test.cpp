#include "token_network.hpp"

#include <gtest/gtest.h>

#include <random>
#include <sstream>

#include "planner_language.hpp"

namespace autonomy::planner {
namespace {

std::string slurp(const std::string& path) {
  Diagnostics errors;
  return read_text_file(path, &errors).value_or("");
}

struct Camera {
  Camera() {
    Diagnostics errors;
    auto m = parse_model(slurp(PLANNER_EXAMPLES_DIR "/camera.model"), "camera.model", &errors);
    model = *build_domain_model(*m, &errors);
    auto p =
        parse_problem(slurp(PLANNER_EXAMPLES_DIR "/camera.problem"), "camera.problem", &errors);
    problem = *build_problem(model, *p, &errors);
  }
  DomainModel model;
  PlanningProblem problem;
};

TEST(TokenNetwork, PlacingAPictureInstantiatesItsFourSlaves) {
  Camera c;
  TokenNetwork net(c.model, c.problem);
  ASSERT_TRUE(net.initialize()) << net.conflict();
  EXPECT_EQ(net.timelines().size(), 3u);
  ASSERT_EQ(net.tokens().size(), 4u);
  EXPECT_EQ(net.flaws().size(), 4u);  // four free tokens
  const TokenId shot = 3;
  EXPECT_EQ(net.token_text(shot), "dsone.camera == picture(asteroid)");
  auto m = net.mark();
  ASSERT_TRUE(net.apply({Decision::Kind::kInsert, shot, 0}));
  // containedBy(engine == off), containedBy(attitude == pointAt(?target)), ready before, after.
  ASSERT_EQ(net.tokens().size(), 8u);
  EXPECT_EQ(net.token_text(5), "dsone.attitude == pointAt(asteroid)");
  EXPECT_EQ(net.tokens()[6].master, shot);
  // The slaves' timepoints follow the relations: ready after the picture starts at its end.
  const Token& after = net.tokens()[6];
  EXPECT_EQ(net.temporal().earliest(after.start), net.temporal().earliest(net.tokens()[shot].end));
  net.undo_to(m);
  EXPECT_EQ(net.tokens().size(), 4u);
  EXPECT_EQ(net.instances().size(), 0u);
  EXPECT_EQ(net.timelines()[1].sequence.size(), 0u);
  EXPECT_EQ(net.flaws().size(), 4u);
}

TEST(TokenNetwork, MergingIsOfferedOnlyForCompatibleTokens) {
  Camera c;
  TokenNetwork net(c.model, c.problem);
  ASSERT_TRUE(net.initialize());
  ASSERT_TRUE(net.apply({Decision::Kind::kInsert, 0, 0}));  // initial pointAt(star)
  ASSERT_TRUE(net.apply({Decision::Kind::kInsert, 1, 0}));  // initial camera ready
  ASSERT_TRUE(net.apply({Decision::Kind::kInsert, 3, 1}));  // the picture after it
  // Slave 7 is "ready after[0,0]" the picture's start: mergeable with the initial ready.
  std::vector<Flaw> flaws = net.flaws();
  bool offered = false;
  for (const Flaw& f : flaws) {
    if (f.kind != Flaw::Kind::kFreeToken || f.token != 7) continue;
    for (const Decision& d : net.options(f))
      offered |= d.kind == Decision::Kind::kMerge && d.index == 1;
  }
  EXPECT_TRUE(offered);
  EXPECT_FALSE(net.may_merge(5, 0));  // pointAt(asteroid) vs pointAt(star)
}

// The undo property: random decisions, undone in any nesting, return the exact state.
std::string snapshot(const TokenNetwork& net) {
  std::ostringstream out;
  for (TokenId t = 0; t < net.tokens().size(); ++t) {
    const Token& k = net.tokens()[t];
    out << net.token_text(t) << ' ' << int(k.state) << ' ' << net.temporal().earliest(k.start)
        << ' ' << net.temporal().latest(k.start) << ' ' << net.temporal().earliest(k.end) << ' '
        << net.temporal().latest(k.end) << '\n';
  }
  for (const Timeline& tl : net.timelines()) {
    out << tl.name << ':';
    for (TokenId t : tl.sequence) out << ' ' << t;
    out << '\n';
  }
  out << net.instances().size() << ' ' << net.constraints().variable_count() << ' '
      << net.temporal().constraints().size();
  return out.str();
}

TEST(TokenNetwork, UndoingIsTheSameAsNeverHavingDone) {
  Camera c;
  std::mt19937 rng(3);
  for (int round = 0; round < 30; ++round) {
    TokenNetwork net(c.model, c.problem);
    ASSERT_TRUE(net.initialize());
    std::vector<std::pair<TokenNetwork::Mark, std::string>> stack;
    for (int step = 0; step < 40; ++step) {
      std::vector<Flaw> flaws = net.flaws();
      bool pop = stack.size() > 0 && (flaws.empty() || rng() % 4 == 0);
      if (pop) {
        net.undo_to(stack.back().first);
        ASSERT_EQ(snapshot(net), stack.back().second) << "round " << round << " step " << step;
        stack.pop_back();
        continue;
      }
      if (flaws.empty()) break;
      const Flaw& f = flaws[rng() % flaws.size()];
      std::vector<Decision> options = net.options(f);
      if (options.empty()) continue;
      stack.push_back({net.mark(), snapshot(net)});
      if (!net.apply(options[rng() % options.size()])) {
        net.undo_to(stack.back().first);
        ASSERT_EQ(snapshot(net), stack.back().second);
        stack.pop_back();
      }
    }
    while (!stack.empty()) {
      net.undo_to(stack.back().first);
      ASSERT_EQ(snapshot(net), stack.back().second);
      stack.pop_back();
    }
  }
}

TEST(TokenNetwork, AnInconsistentProblemNamesItsStatements) {
  Camera c;
  Diagnostics errors;
  auto p = parse_problem(
      "problem late\nhorizon 100\nobject s : Spacecraft\n"
      "goal a: s.camera == picture(comet) end [0, 20]\n"
      "goal b: s.engine == thrusting(2) start [0, 50]\n"
      "a after[40, 60] b\n",
      "late.problem", &errors);
  ASSERT_TRUE(p);
  auto problem = build_problem(c.model, *p, &errors);
  ASSERT_TRUE(problem);
  TokenNetwork net(c.model, *problem);
  EXPECT_FALSE(net.initialize());
  EXPECT_NE(net.conflict().find("late.problem:6"), std::string::npos) << net.conflict();
  EXPECT_NE(net.conflict().find("late.problem:4"), std::string::npos) << net.conflict();
}

}  // namespace
}  // namespace autonomy::planner
