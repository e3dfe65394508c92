#include "token_network.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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

// Exclusion reasoning on one timeline (overload, detectable precedence, edge finding) only
// removes times no schedule uses: on random single-machine problems, every order of the tasks
// that fits their windows keeps its earliest schedule inside the propagated bounds, and a
// problem refused at the start has no such order (brute force over all orders).
TEST(TokenNetwork, ExclusionReasoningNeverRemovesAFeasibleSchedule) {
  Diagnostics errors;
  auto m =
      parse_model("model m\npredicate op(id: int[0, 9])\nclass Machine { attribute busy = op }\n",
                  "m.model", &errors);
  ASSERT_TRUE(m) << to_string(errors);
  auto model = build_domain_model(*m, &errors);
  ASSERT_TRUE(model) << to_string(errors);
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> release(0, 20), length(1, 8), slack(0, 25), count(3, 6);
  int tightened[2] = {0, 0}, refused = 0, feasible_problems = 0;
  // Edge finding alone, then with not-first/not-last too (the same 400 problems).
  for (int round = 0; round < 800; ++round) {
    if (round == 400) rng.seed(3);
    const bool not_first_not_last = round >= 400;
    const int n = count(rng);
    std::vector<int> r(n), p(n), dl(n);
    std::ostringstream text;
    text << "problem p\nhorizon 100\nobject m1 : Machine\n";
    for (int k = 0; k < n; ++k) {
      r[k] = release(rng);
      p[k] = length(rng);
      dl[k] = r[k] + p[k] + slack(rng);
      text << "goal g" << k << ": m1.busy == op(" << k << ") start [" << r[k] << ", inf] end [0, "
           << dl[k] << "] duration [" << p[k] << ", " << p[k] << "]\n";
    }
    auto pp = parse_problem(text.str(), "p.problem", &errors);
    ASSERT_TRUE(pp) << to_string(errors);
    auto problem = build_problem(*model, *pp, &errors);
    ASSERT_TRUE(problem) << to_string(errors);
    TokenNetwork net(*model, *problem);
    net.set_not_first_not_last(not_first_not_last);
    const bool ok = net.initialize();
    std::vector<int> order(n);
    for (int k = 0; k < n; ++k) order[k] = k;
    bool any = false;
    do {
      std::vector<int> start(n);
      int t = 0;
      bool fits = true;
      for (int k : order) {
        start[k] = std::max(t, r[k]);
        t = start[k] + p[k];
        fits &= t <= dl[k];
      }
      if (!fits) continue;
      any = true;
      ASSERT_TRUE(ok) << "round " << round << " refused a feasible problem: " << net.conflict();
      for (int k = 0; k < n; ++k) {
        const Token& tok = net.tokens()[k];  // goal k is token k (no initial values)
        ASSERT_GE(start[k], net.temporal().earliest(tok.start)) << "round " << round;
        ASSERT_LE(start[k], net.temporal().latest(tok.start)) << "round " << round;
      }
    } while (std::next_permutation(order.begin(), order.end()));
    if (!ok) {
      ++refused;
      EXPECT_FALSE(any);
      continue;
    }
    ++feasible_problems;
    for (int k = 0; k < n; ++k) {
      const Token& tok = net.tokens()[k];
      if (net.temporal().earliest(tok.start) > r[k] || net.temporal().latest(tok.end) < dl[k])
        ++tightened[not_first_not_last];
    }
  }
  // The reasoning does something: bounds narrowed, hopeless problems refused at once.
  EXPECT_GT(tightened[0], 100);
  // Not-first/not-last narrows bounds that edge finding leaves.
  EXPECT_GT(tightened[1], tightened[0]);
  EXPECT_GT(refused, 10);
  EXPECT_GT(feasible_problems, 100);
}

}  // namespace
}  // namespace autonomy::planner
