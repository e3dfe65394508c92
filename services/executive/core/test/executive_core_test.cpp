#include <gtest/gtest.h>

#include <random>
#include <set>

#include "dispatchable_every_timepoint.hpp"
#include "executive.hpp"
#include "mode_identification.hpp"
#include "planner.hpp"
#include "planner_language.hpp"

namespace autonomy::executive {
namespace {

using planner::FlexiblePlan;
using planner::PlanToken;

// A token; the caller adds it to a timeline.
void add_token(FlexiblePlan* plan, const std::string& timeline, const std::string& attr,
               const std::string& predicate, std::vector<std::string> params, Time s_lb, Time s_ub,
               Time d_lb, Time d_ub, const std::string& origin) {
  PlanToken t;
  t.id = static_cast<std::uint32_t>(plan->tokens.size());
  t.object = "sc";
  t.attribute = attr;
  t.predicate = predicate;
  t.parameters = std::move(params);
  t.start_lb = s_lb;
  t.start_ub = s_ub;
  t.end_lb = 0;
  t.end_ub = kUnbounded;
  t.duration_lb = d_lb;
  t.duration_ub = d_ub;
  t.origin = origin;
  plan->tokens.push_back(t);
  for (auto& line : plan->timelines)
    if (line.name == timeline) {
      // Tokens on a timeline meet: the previous end is this start.
      if (!line.tokens.empty())
        plan->constraints.push_back(
            {std::to_string(line.tokens.back()) + ".end", std::to_string(t.id) + ".start", 0, 0});
      line.tokens.push_back(t.id);
      return;
    }
  plan->timelines.push_back({timeline, {t.id}});
}

// camera: ready [initial] -> picture (start >= 20, lasting 5..10) -> ready.
FlexiblePlan picture_plan() {
  FlexiblePlan plan;
  plan.horizon = 200;
  add_token(&plan, "sc.camera", "camera", "ready", {}, 0, 0, 0, kUnbounded, "initial");
  add_token(&plan, "sc.camera", "camera", "picture", {"asteroid"}, 20, 100, 5, 10, "goal shot");
  add_token(&plan, "sc.camera", "camera", "ready", {}, 0, 200, 0, kUnbounded, "after of token 1");
  return plan;
}

Dispatcher make_dispatcher(FlexiblePlan plan, Time origin = 0) {
  std::string error;
  auto net = make_dispatchable(plan, &error);
  EXPECT_TRUE(net) << error;
  return Dispatcher(std::move(plan), std::move(*net), origin);
}

std::vector<std::string> kinds(const std::vector<DispatchEvent>& events) {
  std::vector<std::string> out;
  for (const DispatchEvent& e : events)
    out.push_back((e.kind == DispatchEvent::Kind::kStarted ? "start "
                   : e.kind == DispatchEvent::Kind::kEnded ? "end "
                                                           : "violation ") +
                  std::to_string(e.token) + "@" + std::to_string(e.time));
  return out;
}

TEST(DispatchableNetwork, RemovesDominatedEdgesAndKeepsTheNeeded) {
  std::string error;
  auto net = make_dispatchable(picture_plan(), &error);
  ASSERT_TRUE(net) << error;
  EXPECT_EQ(net->names.size(), 7u);
  EXPECT_LT(net->edges.size(), net->closed_edges);
  // The picture's duration (start -> end <= 10) is not implied by any other single edge
  // through a third timepoint, so it must stay.
  std::size_t s = net->index_of(1, true), e = net->index_of(1, false);
  bool kept = false;
  for (const DistanceEdge& d : net->edges) kept |= d.from == s && d.to == e && d.weight == 10;
  EXPECT_TRUE(kept);
}

FlexiblePlan ds1_plan();

// The point of the dispatchable form: propagating to neighbours over the filtered edges gives
// the same windows as propagating over the whole closure.
TEST(DispatchableNetwork, FilteredWindowsEqualThoseOfTheFullClosure) {
  std::string error;
  FlexiblePlan plan = ds1_plan();
  auto filtered = make_dispatchable(plan, &error);
  auto full = make_dispatchable(plan, &error, false);
  ASSERT_TRUE(filtered && full) << error;
  EXPECT_EQ(full->edges.size(), full->closed_edges);
  EXPECT_LT(filtered->edges.size(), full->edges.size());
  Dispatcher a(plan, *filtered, 0), b(plan, *full, 0);
  for (Dispatcher* d : {&a, &b}) d->set_observed(4, false, true);  // the arc ends when it ends
  for (Time t = 0; t <= 100; ++t) {
    if (t == 47)
      for (Dispatcher* d : {&a, &b}) d->observe(4, false, 47);
    EXPECT_EQ(kinds(a.step(t)), kinds(b.step(t))) << t;
    for (std::size_t i = 0; i < plan.tokens.size(); ++i)
      for (bool start : {true, false})
        if (!a.executed(i, start)) {
          EXPECT_EQ(a.lower(i, start), b.lower(i, start)) << t << " token " << i;
          EXPECT_EQ(a.upper(i, start), b.upper(i, start)) << t << " token " << i;
        }
  }
  EXPECT_TRUE(a.finished());
  EXPECT_FALSE(a.broken());
}

// A tight triangle is not enough: a non-negative A->C (C <= A + 7) through a negative B->C
// (C precedes B by 3) must stay, or C's bound would wait for B, which waits for C.
TEST(DispatchableNetwork, ANonNegativeEdgeIsNotDominatedThroughANegativeOne) {
  FlexiblePlan plan;
  plan.horizon = 200;
  add_token(&plan, "sc.a", "a", "x", {}, 0, 50, 0, 10, "");           // A = 0.start, B = 0.end
  add_token(&plan, "sc.c", "c", "y", {}, 5, 100, 0, kUnbounded, "");  // C = 1.start
  plan.constraints.push_back({"1.start", "0.end", 3, 100});
  plan.constraints.push_back({"0.start", "1.start", 0, 100});
  std::string error;
  auto net = make_dispatchable(plan, &error);
  ASSERT_TRUE(net) << error;
  Dispatcher d(plan, *net, 0);
  EXPECT_EQ(kinds(d.step(0)), (std::vector<std::string>{"start 0@0"}));
  EXPECT_EQ(d.lower(1, true), 5);
  EXPECT_EQ(d.upper(1, true), 7);  // A at 0, B <= 10, C <= B - 3
  EXPECT_EQ(kinds(d.step(5)), (std::vector<std::string>{"start 1@5"}));
  EXPECT_EQ(d.lower(0, false), 8);
  EXPECT_EQ(d.upper(0, false), 10);
}

TEST(DispatchableNetwork, RejectsInconsistentAndUnknownTimepoints) {
  FlexiblePlan plan = picture_plan();
  plan.constraints.push_back({"1.start", "1.end", 20, 30});  // duration is at most 10
  std::string error;
  EXPECT_FALSE(make_dispatchable(plan, &error));
  EXPECT_NE(error.find("negative cycle"), std::string::npos) << error;
  plan = picture_plan();
  plan.constraints.push_back({"9.start", "1.end", 0, 5});
  EXPECT_FALSE(make_dispatchable(plan, &error));
  EXPECT_NE(error.find("'9.start'"), std::string::npos) << error;
}

// The textbook construction, for comparison: Floyd-Warshall closure and the triangle rule
// tried for every middle timepoint (n^3). Returns the closure and the kept edges.
struct ReferenceNetwork {
  bool consistent = true;
  std::vector<Time> d;
  std::vector<std::pair<std::size_t, std::size_t>> kept;
};

ReferenceNetwork reference_dispatchable(const FlexiblePlan& plan) {
  const std::size_t n = 1 + 2 * plan.tokens.size();
  constexpr Time kNone = kUnbounded;
  auto tp = [&](const std::string& name) -> std::size_t {
    if (name == "origin") return 0;
    std::size_t dot = name.find('.');
    std::size_t id = std::stoul(name.substr(0, dot));
    return 1 + 2 * id + (name.substr(dot + 1) == "start" ? 0 : 1);
  };
  ReferenceNetwork r;
  r.d.assign(n * n, kNone);
  auto at = [&](std::size_t a, std::size_t b) -> Time& { return r.d[a * n + b]; };
  for (std::size_t a = 0; a < n; ++a) at(a, a) = 0;
  auto add = [&](std::size_t from, std::size_t to, Time lb, Time ub) {
    if (ub < kUnbounded) at(from, to) = std::min(at(from, to), ub);
    if (lb > -kUnbounded) at(to, from) = std::min(at(to, from), -lb);
  };
  for (std::size_t i = 0; i < plan.tokens.size(); ++i) {
    const PlanToken& t = plan.tokens[i];
    add(0, 1 + 2 * i, t.start_lb, t.start_ub);
    add(0, 2 + 2 * i, t.end_lb, t.end_ub);
    add(1 + 2 * i, 2 + 2 * i, std::max<Time>(0, t.duration_lb), t.duration_ub);
  }
  for (const auto& c : plan.constraints) add(tp(c.from), tp(c.to), c.lb, c.ub);
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = 0; b < n; ++b)
        if (at(a, k) != kNone && at(k, b) != kNone && at(a, k) + at(k, b) < at(a, b))
          at(a, b) = at(a, k) + at(k, b);
  for (std::size_t a = 0; a < n; ++a) r.consistent &= at(a, a) >= 0;
  if (!r.consistent) return r;
  auto rigid = [&](std::size_t x, std::size_t y) {
    return at(x, y) != kNone && at(y, x) != kNone && at(x, y) + at(y, x) == 0;
  };
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t c = 0; c < n; ++c) {
      if (a == c || at(a, c) == kNone) continue;
      bool dominated = false;
      for (std::size_t b = 0; b < n && !dominated; ++b) {
        if (b == a || b == c || at(a, b) == kNone || at(b, c) == kNone) continue;
        if (at(a, b) + at(b, c) != at(a, c) || rigid(a, b) || rigid(b, c)) continue;
        dominated = at(a, c) >= 0 ? at(b, c) >= 0 : at(a, b) < 0;
      }
      if (!dominated) r.kept.push_back({a, c});
    }
  return r;
}

// Random plans of a few timelines whose tokens meet (rigid links), some with fixed durations,
// linked across timelines by random bounded and unbounded constraints.
FlexiblePlan random_plan(std::mt19937* rng, int tokens) {
  FlexiblePlan plan;
  plan.horizon = 1000;
  std::uniform_int_distribution<int> pick(0, 9);
  for (int i = 0; i < tokens; ++i) {
    Time d_lb = pick(*rng), d_ub = pick(*rng) < 3 ? d_lb : d_lb + 1 + pick(*rng);
    if (pick(*rng) == 0) d_ub = kUnbounded;
    add_token(&plan, "sc.line" + std::to_string(i % 3), "line" + std::to_string(i % 3), "p", {},
              pick(*rng), pick(*rng) < 2 ? kUnbounded : 40 + 10 * pick(*rng), d_lb, d_ub, "");
  }
  int links = pick(*rng) % 4 + tokens / 3;
  std::uniform_int_distribution<int> token(0, tokens - 1);
  for (int k = 0; k < links; ++k) {
    int a = token(*rng), b = token(*rng);
    const char* ends[] = {".start", ".end"};
    Time lb = -3 * pick(*rng), ub = pick(*rng) < 5 ? kUnbounded : lb + 5 * pick(*rng);
    if (pick(*rng) == 0) ub = lb;  // rigid across timelines too
    plan.constraints.push_back({std::to_string(a) + ends[pick(*rng) % 2],
                                std::to_string(b) + ends[pick(*rng) % 2], lb, ub});
  }
  return plan;
}

// The construction (one Dijkstra per rigid class, dominance carried along it) keeps exactly the
// edges the n^3 triangle rule keeps, with the same weights and windows, and rejects exactly
// the inconsistent plans.
TEST(DispatchableNetwork, SameEdgesAndWindowsAsTheCubicConstructionOnRandomPlans) {
  std::mt19937 rng(12);
  int consistent = 0, inconsistent = 0;
  for (int round = 0; round < 300; ++round) {
    FlexiblePlan plan = random_plan(&rng, 2 + round % 14);
    ReferenceNetwork ref = reference_dispatchable(plan);
    std::string error;
    auto net = make_dispatchable(plan, &error);
    ASSERT_EQ(net.has_value(), ref.consistent) << "round " << round << ": " << error;
    if (!net) {
      EXPECT_NE(error.find("negative cycle through"), std::string::npos) << error;
      ++inconsistent;
      continue;
    }
    ++consistent;
    const std::size_t n = net->names.size();
    std::vector<std::pair<std::size_t, std::size_t>> kept;
    for (const DistanceEdge& e : net->edges) {
      kept.push_back({e.from, e.to});
      EXPECT_EQ(e.weight, ref.d[e.from * n + e.to]) << "round " << round;
    }
    ASSERT_EQ(kept, ref.kept) << "round " << round;
    for (std::size_t p = 0; p < n; ++p) {
      Time lo = ref.d[p * n] == kUnbounded ? -kUnbounded : -ref.d[p * n];
      Time hi = ref.d[p];
      EXPECT_EQ(net->earliest[p], lo) << "round " << round << " " << net->names[p];
      EXPECT_EQ(net->latest[p], hi) << "round " << round << " " << net->names[p];
    }
  }
  // Both kinds of plan were met, so neither comparison is vacuous.
  EXPECT_GT(consistent, 100);
  EXPECT_GT(inconsistent, 10);
}

// Issue 28: the construction by rigid classes (one Dijkstra per class, dominance carried in
// it) against the per-timepoint construction it replaced, on plans too large for the cubic
// reference. Same edges in the same order, same weights, windows and closure size, or the same
// refusal.
void expect_same_network(const FlexiblePlan& plan, const std::string& what) {
  for (bool filter : {true, false}) {
    std::string error, old_error;
    auto net = make_dispatchable(plan, &error, filter);
    auto old = make_dispatchable_every_timepoint(plan, &old_error, filter);
    ASSERT_EQ(net.has_value(), old.has_value()) << what << ": " << error << " / " << old_error;
    if (!net) {
      EXPECT_EQ(error, old_error) << what;
      continue;
    }
    EXPECT_EQ(net->closed_edges, old->closed_edges) << what;
    EXPECT_EQ(net->earliest, old->earliest) << what;
    EXPECT_EQ(net->latest, old->latest) << what;
    ASSERT_EQ(net->edges.size(), old->edges.size()) << what << " filter " << filter;
    for (std::size_t i = 0; i < net->edges.size(); ++i) {
      const DistanceEdge &a = net->edges[i], &b = old->edges[i];
      ASSERT_TRUE(a.from == b.from && a.to == b.to && a.weight == b.weight)
          << what << " filter " << filter << " edge " << i << ": " << net->names[a.from] << " -> "
          << net->names[a.to] << " " << a.weight << " against " << old->names[b.from] << " -> "
          << old->names[b.to] << " " << b.weight;
    }
  }
}

// Consistent by construction: every timepoint has a hidden time, every bound contains the
// hidden difference; some links rigid (lb = ub), some one-sided, durations fixed or flexible,
// timelines of meeting tokens. `scale` multiplies every time (large scales make the class
// distances too long for 64-bit keys). With `break_it`, two rigid links A->B, B->C and a bound
// on C->A that contradicts them: inconsistent.
FlexiblePlan random_consistent_plan(std::mt19937* rng, int tokens, int lines, Time scale,
                                    bool break_it) {
  FlexiblePlan plan;
  std::uniform_int_distribution<int> pick(0, 9);
  std::vector<Time> start(tokens), end(tokens);
  std::vector<Time> line_end(lines, 0);
  for (int i = 0; i < tokens; ++i) {
    int l = i % lines;
    start[i] = line_end[l];
    end[i] = start[i] + scale * (1 + pick(*rng));
    line_end[l] = end[i];
  }
  Time horizon = *std::max_element(line_end.begin(), line_end.end()) + scale * 10;
  plan.horizon = horizon;
  auto slack = [&]() { return scale * pick(*rng); };
  for (int i = 0; i < tokens; ++i) {
    PlanToken t;
    t.id = static_cast<std::uint32_t>(i);
    t.object = "sc";
    t.attribute = "line" + std::to_string(i % lines);
    t.predicate = "p";
    t.start_lb = std::max<Time>(0, start[i] - slack());
    t.start_ub = pick(*rng) < 3 ? kUnbounded : start[i] + slack();
    t.end_lb = 0;
    t.end_ub = pick(*rng) < 5 ? kUnbounded : end[i] + slack();
    Time d = end[i] - start[i];
    bool fixed = pick(*rng) < 3;
    t.duration_lb = fixed ? d : std::max<Time>(0, d - slack());
    t.duration_ub = fixed ? d : pick(*rng) == 0 ? kUnbounded : d + slack();
    plan.tokens.push_back(t);
    std::string id = std::to_string(i);
    if (i >= lines)
      plan.constraints.push_back({std::to_string(i - lines) + ".end", id + ".start", 0, 0});
  }
  auto time_of = [&](int token, bool s) { return s ? start[token] : end[token]; };
  std::uniform_int_distribution<int> token(0, tokens - 1);
  int links = tokens / 2 + pick(*rng);
  for (int k = 0; k < links; ++k) {
    int a = token(*rng), b = token(*rng);
    bool sa = pick(*rng) < 5, sb = pick(*rng) < 5;
    Time diff = time_of(b, sb) - time_of(a, sa);
    Time lb = diff - slack(), ub = diff + slack();
    int kind = pick(*rng);
    if (kind == 0)
      lb = ub = diff;  // rigid across timelines
    else if (kind < 3)
      ub = kUnbounded;  // one-sided
    else if (kind < 4)
      lb = -kUnbounded;
    plan.constraints.push_back({std::to_string(a) + (sa ? ".start" : ".end"),
                                std::to_string(b) + (sb ? ".start" : ".end"), lb, ub});
  }
  if (break_it) {
    int a = token(*rng), b = token(*rng), c = token(*rng);
    std::string ta = std::to_string(a) + ".start", tb = std::to_string(b) + ".end",
                tc = std::to_string(c) + ".start";
    Time ab = end[b] - start[a], bc = start[c] - end[b];
    plan.constraints.push_back({ta, tb, ab, ab});
    plan.constraints.push_back({tb, tc, bc, bc});
    plan.constraints.push_back({tc, ta, -(ab + bc) + scale, kUnbounded});
  }
  return plan;
}

TEST(DispatchableNetwork, SameNetworkAsThePerTimepointConstructionOnLargerRandomPlans) {
  std::mt19937 rng(28);
  int consistent = 0, inconsistent = 0;
  for (int round = 0; round < 60; ++round) {
    int tokens = 10 + static_cast<int>(rng() % 110), lines = 1 + static_cast<int>(rng() % 6);
    FlexiblePlan plan = random_consistent_plan(&rng, tokens, lines, 1, round % 5 == 4);
    std::string error;
    (make_dispatchable(plan, &error) ? consistent : inconsistent)++;
    expect_same_network(plan, "round " + std::to_string(round));
  }
  EXPECT_GT(consistent, 40);
  EXPECT_GT(inconsistent, 5);
}

// Distances too long for 64-bit Dijkstra keys (a time unit of 2^45, horizons near 2^51, short
// timelines, so many large weights and a few hundred rigid classes) take the 128-bit keys; the
// network is the same.
TEST(DispatchableNetwork, SameNetworkWithTimesTooLongForNarrowKeys) {
  std::mt19937 rng(44);
  for (int round = 0; round < 3; ++round) {
    FlexiblePlan plan = random_consistent_plan(&rng, 150 + 20 * round, 40, Time{1} << 45, false);
    std::string error;
    ASSERT_TRUE(make_dispatchable(plan, &error)) << error;
    expect_same_network(plan, "round " + std::to_string(round));
  }
}

// The hand-written plans of this file and the bench's kind of plan.
TEST(DispatchableNetwork, SameNetworkAsThePerTimepointConstructionOnTheExamplePlans) {
  expect_same_network(picture_plan(), "picture");
  expect_same_network(ds1_plan(), "ds1");
  std::mt19937 rng(3);
  FlexiblePlan lines;
  lines.horizon = 2000;
  std::uniform_int_distribution<int> coin(0, 3);
  for (int l = 0; l < 5; ++l)
    for (int k = 0; k < 30; ++k) {
      bool fixed = coin(rng) == 0;
      add_token(&lines, "sc.line" + std::to_string(l), "line" + std::to_string(l), "p", {}, 0,
                k == 0 ? 0 : lines.horizon, fixed ? 15 : 10, fixed ? 15 : 20, "");
      if (l > 0 && k % 4 == 3)
        lines.constraints.push_back({std::to_string((l - 1) * 30 + k - 1) + ".end",
                                     std::to_string(l * 30 + k) + ".start", 0, 30});
    }
  expect_same_network(lines, "timelines");
}

// The planner's plans for the example problems, checked against both earlier constructions.
TEST(DispatchableNetwork, SameNetworkOnThePlannersExamplePlans) {
  const std::string dir = PLANNER_EXAMPLES_DIR;
  int planned = 0;
  for (const char* name : {"camera", "rover", "field-rover"}) {
    planner::Diagnostics errors;
    auto model_text = planner::read_text_file(dir + "/" + name + ".model", &errors);
    auto problem_text = planner::read_text_file(dir + "/" + name + ".problem", &errors);
    ASSERT_TRUE(model_text && problem_text) << planner::to_string(errors);
    auto m = planner::parse_model(*model_text, std::string(name) + ".model", &errors);
    auto model = planner::build_domain_model(*m, &errors);
    auto p = planner::parse_problem(*problem_text, std::string(name) + ".problem", &errors);
    auto problem = planner::build_problem(*model, *p, &errors);
    ASSERT_TRUE(problem) << planner::to_string(errors);
    planner::PlanningOptions options;
    options.termination.max_decisions = 20000;
    planner::PlanResult result = planner::make_plan(*model, *problem, options);
    ASSERT_TRUE(result.plan) << name << ": " << result.explanation;
    ++planned;
    expect_same_network(*result.plan, name);
    ReferenceNetwork ref = reference_dispatchable(*result.plan);
    std::string error;
    auto net = make_dispatchable(*result.plan, &error);
    ASSERT_TRUE(net && ref.consistent) << name << ": " << error;
    std::vector<std::pair<std::size_t, std::size_t>> kept;
    for (const DistanceEdge& e : net->edges) kept.push_back({e.from, e.to});
    EXPECT_EQ(kept, ref.kept) << name;
  }
  EXPECT_EQ(planned, 3);
}

TEST(Dispatcher, ExecutesTimepointsInOrderAtTheirEarliestTimes) {
  Dispatcher d = make_dispatcher(picture_plan());
  EXPECT_EQ(kinds(d.step(0)), (std::vector<std::string>{"start 0@0"}));
  EXPECT_TRUE(d.step(19).empty());  // the picture may not start before 20
  EXPECT_EQ(kinds(d.step(20)), (std::vector<std::string>{"end 0@20", "start 1@20"}));
  EXPECT_EQ(d.lower(1, false), 25);
  EXPECT_EQ(d.upper(1, false), 30);
  EXPECT_TRUE(d.step(24).empty());
  EXPECT_EQ(kinds(d.step(25)), (std::vector<std::string>{"end 1@25", "start 2@25"}));
  // The last ready holds the camera's value to the horizon.
  EXPECT_TRUE(d.step(199).empty());
  EXPECT_FALSE(d.finished());
  EXPECT_EQ(kinds(d.step(200)), (std::vector<std::string>{"end 2@200"}));
  EXPECT_TRUE(d.finished());
  EXPECT_FALSE(d.broken());
}

TEST(Dispatcher, AnObservedEndTightensTheBoundsAfterIt) {
  Dispatcher d = make_dispatcher(picture_plan(), 1000);  // the origin at absolute time 1000
  d.set_observed(1, false, true);
  d.step(1000);
  d.step(1020);
  EXPECT_TRUE(d.step(1025).empty());  // observed: not forced at its earliest time
  d.observe(1, false, 1028);
  EXPECT_EQ(d.lower(2, true), 1028);
  EXPECT_EQ(d.upper(2, true), 1028);
  EXPECT_EQ(kinds(d.step(1028)), (std::vector<std::string>{"end 1@1028", "start 2@1028"}));
  EXPECT_FALSE(d.broken());
}

TEST(Dispatcher, AMissingObservationIsAViolationNotAHang) {
  Dispatcher d = make_dispatcher(picture_plan());
  d.set_observed(1, false, true);
  d.step(0);
  d.step(20);
  EXPECT_TRUE(d.step(30).empty());  // still inside [25, 30]
  auto events = d.step(31);
  // The picture's end and the ready start rigidly tied to it both passed their bound.
  ASSERT_EQ(kinds(events), (std::vector<std::string>{"violation 1@31", "violation 2@31"}));
  EXPECT_EQ(events[0].kind, DispatchEvent::Kind::kViolation);
  EXPECT_NE(events[0].reason.find("1.end: not observed by its bound 30"), std::string::npos)
      << events[0].reason;
  EXPECT_TRUE(d.broken());
  EXPECT_TRUE(d.step(32).empty());  // reported once
}

TEST(Dispatcher, AnObservationOutsideItsWindowIsAViolation) {
  Dispatcher d = make_dispatcher(picture_plan());
  d.set_observed(1, false, true);
  d.step(0);
  d.step(20);
  d.observe(1, false, 22);  // the picture lasts at least 5
  auto events = d.step(22);
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events[0].kind, DispatchEvent::Kind::kViolation);
  EXPECT_NE(events[0].reason.find("outside [25, 30]"), std::string::npos) << events[0].reason;
}

TEST(CommandMap, ChecksRulesAndFillsParameters) {
  CommandMap map;
  std::string error;
  EXPECT_FALSE(map.add({"sc.camera", "picture", "camera", "take_image", "", {"?x"}}, &error));
  EXPECT_NE(error.find("'?x' is not ?<number>"), std::string::npos) << error;
  EXPECT_FALSE(map.add({"sc.camera", "ready", "camera", "", ""}, &error));
  EXPECT_NE(error.find("a command or an expected mode"), std::string::npos) << error;
  ASSERT_TRUE(
      map.add({"sc.camera", "picture", "camera", "take_image", "imaging", {"?0", "raw"}}, &error));
  EXPECT_FALSE(map.add({"sc.camera", "picture", "camera", "x", ""}, &error));
  EXPECT_NE(error.find("declared twice"), std::string::npos);
  FlexiblePlan plan = picture_plan();
  auto c = map.command_for(plan.tokens[1], 1, 7, &error);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->arguments, (std::vector<std::string>{"asteroid", "raw"}));
  EXPECT_EQ(c->sent, 7);
  plan.tokens[1].parameters.clear();
  error.clear();
  EXPECT_FALSE(map.command_for(plan.tokens[1], 1, 7, &error));
  EXPECT_NE(error.find("no parameter ?0"), std::string::npos) << error;
}

// ---- the executive against a small simulated spacecraft ----

// A toy spacecraft: devices take the mode their command implies, confirm the next tick, and
// faults from the test change that.
struct ToySpacecraft {
  std::map<std::string, std::string> modes{
      {"camera", "ready"}, {"ips", "standby"}, {"adcs", "pointing"}};
  std::map<std::string, double> readings;
  std::set<std::string> never_confirm, stuck;
  std::vector<DeviceCommand> to_confirm, received;
  Time imaging_until = -1;

  Observations observe(Time now) {
    if (imaging_until >= 0 && now >= imaging_until && !stuck.count("camera")) {
      modes["camera"] = "ready";
      imaging_until = -1;
    }
    return {now, modes, readings, {}};
  }
  void receive(const std::vector<DeviceCommand>& commands, Time now) {
    for (const DeviceCommand& c : commands) {
      received.push_back(c);
      if (never_confirm.count(c.device)) continue;
      if (c.command == "take_image") {
        modes["camera"] = "imaging";
        imaging_until = now + 5;
      } else if (c.command == "thrust") {
        modes["ips"] = "thrusting";
      } else if (c.command == "standby") {
        modes["ips"] = "standby";
      } else if (c.command == "reset") {
        modes[c.device] = "ok";
      } else if (c.command == "turn") {
        modes["adcs"] = "turning";
      }
      to_confirm.push_back(c);
    }
  }
};

// camera: ready -> picture(asteroid) at >= 10 for 5..10 -> ready;
// engine: off -> thrusting(2) at >= 30 for 10..20 -> off. Both are goals.
FlexiblePlan ds1_plan() {
  FlexiblePlan plan;
  plan.horizon = 100;
  add_token(&plan, "sc.camera", "camera", "ready", {}, 0, 0, 0, kUnbounded, "initial");
  add_token(&plan, "sc.camera", "camera", "picture", {"asteroid"}, 10, 60, 5, 10, "goal shot");
  add_token(&plan, "sc.camera", "camera", "ready", {}, 0, 100, 0, kUnbounded, "after");
  add_token(&plan, "sc.engine", "engine", "off", {}, 0, 0, 0, kUnbounded, "initial");
  add_token(&plan, "sc.engine", "engine", "thrusting", {"2"}, 30, 60, 10, 20, "goal arc");
  add_token(&plan, "sc.engine", "engine", "off", {}, 0, 100, 0, kUnbounded, "after");
  return plan;
}

CommandMap ds1_commands() {
  CommandMap map;
  std::string error;
  for (CommandRule r : std::vector<CommandRule>{
           {"sc.camera", "picture", "camera", "take_image", "imaging", {"?0"}, 3},
           {"sc.camera", "ready", "camera", "", "ready"},
           {"sc.engine", "thrusting", "ips", "thrust", "thrusting", {"?0"}, 5},
           {"sc.engine", "off", "ips", "standby", "standby", {}, 5}})
    EXPECT_TRUE(map.add(r, &error)) << error;
  return map;
}

struct Outcome {
  std::vector<Tick> ticks;
  std::vector<ExecutiveEvent> events;
  std::optional<ReplanRequest> replan;
  bool has(const std::string& kind) const {
    for (const auto& e : events)
      if (e.kind == kind) return true;
    return false;
  }
  std::size_t count(const std::string& kind) const {
    std::size_t n = 0;
    for (const auto& e : events) n += e.kind == kind;
    return n;
  }
  std::vector<std::string> responses() const {  // "fault <kind>@time", in order
    std::vector<std::string> out;
    for (const auto& e : events)
      if (e.kind.rfind("fault ", 0) == 0) out.push_back(e.kind + "@" + std::to_string(e.time));
    return out;
  }
  const ExecutiveEvent* first(const std::string& kind) const {
    for (const auto& e : events)
      if (e.kind == kind) return &e;
    return nullptr;
  }
};

std::unique_ptr<Executive> ds1_executive(FlexiblePlan plan = ds1_plan()) {
  std::string error;
  ExecutiveOptions options;
  options.safing = {{"camera", "off", {}}, {"ips", "standby", {}}};
  auto exec = Executive::create(
      std::move(plan), ds1_commands(),
      ds1_fault_table({{"bus_switch_status", {"bus_current_a", "bus_current_b"}, 0.5, 3}},
                      {{"thruster_x", "adcs", "wheels_and_other_thrusters"}}),
      options, 0, &error);
  EXPECT_TRUE(exec) << error;
  return exec;
}

// Steps executive and spacecraft together once per time unit; `inject` may change the
// spacecraft before it is observed. Bounded by `until`.
template <typename Inject>
Outcome run(Executive* exec, ToySpacecraft* sc, Time until, Inject inject) {
  Outcome r;
  for (Time t = 0; t <= until; ++t) {
    for (const DeviceCommand& c : sc->to_confirm) exec->confirm(c.device, c.command);
    sc->to_confirm.clear();
    inject(t, sc);
    Tick tick = exec->step(sc->observe(t));
    sc->receive(tick.commands, t);
    r.events.insert(r.events.end(), tick.events.begin(), tick.events.end());
    if (tick.replan) r.replan = tick.replan;
    r.ticks.push_back(std::move(tick));
  }
  return r;
}

std::vector<std::string> sent(const ToySpacecraft& sc) {
  std::vector<std::string> out;
  for (const DeviceCommand& c : sc.received)
    out.push_back(c.device + " " + c.command + "@" + std::to_string(c.sent));
  return out;
}

TEST(Executive, APlanNamingAMissingTokenIsRefusedWithTheReason) {
  FlexiblePlan plan = ds1_plan();
  plan.timelines[0].tokens.push_back(99);
  std::string error;
  EXPECT_FALSE(Executive::create(plan, CommandMap{}, {}, {}, 0, &error));
  EXPECT_NE(error.find("names token 99 of"), std::string::npos) << error;
}

TEST(Executive, APlanStartedAfterItsOriginStartsItsInitialValuesAtTheOrigin) {
  // Paced time goes on while the planner searches: the plan for origin 0 is first stepped at 4.
  // Its initial values start at the origin (their window is [0, 0]), not at 4 and not never.
  auto exec = ds1_executive();
  ToySpacecraft sc;
  Tick first = exec->step(sc.observe(4));
  std::vector<std::string> started;
  for (const auto& e : first.events) started.push_back(e.kind + " " + e.text + "@" + std::to_string(e.time));
  EXPECT_EQ(started, (std::vector<std::string>{"started sc.camera == ready() #0@0", "started sc.engine == off() #3@0"}));
  EXPECT_FALSE(exec->aborted());
  EXPECT_EQ(exec->dispatcher().executed_at(0, true), 0);
  sc.receive(first.commands, 4);
  bool violation = false;
  for (Time t = 5; t <= 100; ++t) {
    for (const DeviceCommand& c : sc.to_confirm) exec->confirm(c.device, c.command);
    sc.to_confirm.clear();
    Tick tick = exec->step(sc.observe(t));
    sc.receive(tick.commands, t);
    for (const auto& e : tick.events) violation = violation || e.kind == "violation";
  }
  EXPECT_FALSE(violation);
  EXPECT_EQ(sent(sc), (std::vector<std::string>{"camera take_image@10", "ips thrust@30", "ips standby@40"}));
  EXPECT_TRUE(exec->finished());
}

TEST(Executive, WithoutFaultsCommandsThePlanInOrderAndFinishes) {
  auto exec = ds1_executive();
  ToySpacecraft sc;
  Outcome r = run(exec.get(), &sc, 100, [](Time, ToySpacecraft*) {});
  EXPECT_EQ(sent(sc),
            (std::vector<std::string>{"camera take_image@10", "ips thrust@30", "ips standby@40"}));
  EXPECT_EQ(sc.received[0].arguments, std::vector<std::string>{"asteroid"});
  EXPECT_TRUE(exec->finished());
  EXPECT_FALSE(exec->aborted());
  EXPECT_FALSE(r.has("violation"));
  EXPECT_EQ(r.count("fault abort_and_replan") + r.count("fault reset"), 0u);
  // A token's start and end name it "timeline == predicate(args) #id": the viewer maps them to
  // the plan's tokens by that (services/viewer/core/execution_trace.hpp).
  std::vector<std::string> picture;
  for (const auto& e : r.events)
    if ((e.kind == "started" || e.kind == "ended") && e.text.find("picture") != std::string::npos)
      picture.push_back(e.kind + " " + e.text);
  EXPECT_EQ(picture, (std::vector<std::string>{"started sc.camera == picture(asteroid) #1",
                                               "ended sc.camera == picture(asteroid) #1"}));
}

TEST(Executive, CameraStuckOnAbortsSafesAndRequestsAPlanFromTheCurrentState) {
  auto exec = ds1_executive();
  ToySpacecraft sc;
  sc.stuck.insert("camera");
  Outcome r = run(exec.get(), &sc, 100, [](Time, ToySpacecraft*) {});
  // The picture ends by time at 15; the camera still images at 15 and 16: two samples.
  const ExecutiveEvent* fault = r.first("fault abort_and_replan");
  ASSERT_TRUE(fault);
  EXPECT_EQ(fault->time, 16);
  EXPECT_NE(fault->text.find("camera reports imaging but the plan expects ready"),
            std::string::npos);
  ASSERT_TRUE(r.replan);
  EXPECT_EQ(r.replan->time, 16);
  EXPECT_EQ(r.replan->known_faults, (std::map<std::string, std::string>{{"camera", "imaging"}}));
  ASSERT_EQ(r.replan->state.size(), 2u);
  EXPECT_EQ(r.replan->state[0].timeline, "sc.camera");
  EXPECT_EQ(r.replan->state[0].predicate, "ready");
  EXPECT_EQ(r.replan->state[0].since, 15);
  EXPECT_EQ(r.replan->state[1].predicate, "off");
  // The picture was taken (its token ended); the thrusting arc remains to be planned.
  ASSERT_EQ(r.replan->remaining_goals.size(), 1u);
  EXPECT_EQ(r.replan->remaining_goals[0].predicate, "thrusting");
  // Safing sent on the abort tick, and nothing more dispatched after it.
  EXPECT_EQ(sent(sc),
            (std::vector<std::string>{"camera take_image@10", "camera off@16", "ips standby@16"}));
  EXPECT_TRUE(exec->aborted());
}

TEST(Executive, AFailedUnitIsResetWithoutReplanning) {
  auto exec = ds1_executive();
  ToySpacecraft sc;
  Outcome r = run(exec.get(), &sc, 100, [](Time t, ToySpacecraft* s) {
    if (t == 20) s->modes["lpe"] = "failed";  // cured by the reset the executive sends
  });
  EXPECT_EQ(r.count("fault reset"), 1u);
  EXPECT_EQ(sc.modes["lpe"], "ok");
  EXPECT_EQ(sent(sc), (std::vector<std::string>{"camera take_image@10", "lpe reset@20",
                                                "ips thrust@30", "ips standby@40"}));
  EXPECT_FALSE(r.replan);
  EXPECT_TRUE(exec->finished());
}

// The picture's command refused (its electronics unit failed a moment before): not awaited,
// so the camera is not given up; the picture is lost with the reason, the rest goes on.
TEST(Executive, ARejectedCommandLosesItsTokenButNotItsDevice) {
  auto exec = ds1_executive();
  ToySpacecraft sc;
  Outcome r;
  for (Time t = 0; t <= 100; ++t) {
    for (const DeviceCommand& c : sc.to_confirm) {
      if (c.device == "camera") EXPECT_TRUE(exec->rejected(c, "lpe has failed"));
      else exec->confirm(c.device, c.command);
    }
    sc.to_confirm.clear();
    Tick tick = exec->step(sc.observe(t));
    sc.receive(tick.commands, t);
    r.events.insert(r.events.end(), tick.events.begin(), tick.events.end());
  }
  EXPECT_FALSE(exec->disabled("camera"));
  EXPECT_EQ(r.count("fault stop_commanding"), 0u);
  const ExecutiveEvent* lost = r.first("goal_lost");
  ASSERT_TRUE(lost);
  EXPECT_NE(lost->text.find("camera take_image rejected: lpe has failed"), std::string::npos) << lost->text;
  EXPECT_EQ(sent(sc), (std::vector<std::string>{"camera take_image@10", "ips thrust@30", "ips standby@40"}));
  EXPECT_TRUE(exec->finished());
}

TEST(Executive, AFalseSensorIsRecognisedByRedundantEvidenceAndIgnored) {
  auto exec = ds1_executive();
  ToySpacecraft sc;
  Outcome r = run(exec.get(), &sc, 100, [](Time t, ToySpacecraft* s) {
    s->readings["bus_current_a"] = 1.0;
    s->readings["bus_current_b"] = 1.1;
    s->readings["bus_switch_status"] = t < 5 ? 1.0 : 0.0;  // false from 5 on
  });
  const ExecutiveEvent* e = r.first("fault ignore_sensor");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->time, 7);  // third disagreeing sample
  EXPECT_EQ(r.count("fault ignore_sensor"), 1u);
  EXPECT_TRUE(exec->ignored("bus_switch_status"));
  EXPECT_FALSE(r.replan);
  EXPECT_TRUE(exec->finished());
}

TEST(Executive, SensorsThatAgreeAmongThemselvesAreNotJudgedFalse) {
  FalseSensorResponse part({{"s", {"a", "b"}, 0.5, 2}});
  PlanState plan;
  // The evidence disagrees within itself: it cannot judge s.
  for (int i = 0; i < 5; ++i)
    EXPECT_TRUE(part.assess({i, {}, {{"s", 0}, {"a", 1}, {"b", 3}}, {}}, plan).empty());
  // Agreement in between resets the count.
  EXPECT_TRUE(part.assess({5, {}, {{"s", 0}, {"a", 1}, {"b", 1}}, {}}, plan).empty());
  EXPECT_TRUE(part.assess({6, {}, {{"s", 1}, {"a", 1}, {"b", 1}}, {}}, plan).empty());
  EXPECT_TRUE(part.assess({7, {}, {{"s", 0}, {"a", 1}, {"b", 1}}, {}}, plan).empty());
  EXPECT_EQ(part.assess({8, {}, {{"s", 0}, {"a", 1}, {"b", 1}}, {}}, plan).size(), 1u);
  EXPECT_TRUE(part.ignored("s"));
}

TEST(Executive, AThrusterStuckClosedSwitchesTheControlModeOnce) {
  auto exec = ds1_executive();
  ToySpacecraft sc;
  Outcome r = run(exec.get(), &sc, 100, [](Time t, ToySpacecraft* s) {
    if (t == 12) s->modes["thruster_x"] = "stuck_closed";
  });
  EXPECT_EQ(r.count("fault switch_control_mode"), 1u);
  ASSERT_EQ(sc.received.size(), 4u);
  EXPECT_EQ(sent(sc)[1], "adcs set_mode@12");
  EXPECT_EQ(sc.received[1].arguments, std::vector<std::string>{"wheels_and_other_thrusters"});
  EXPECT_FALSE(r.replan);
  EXPECT_TRUE(exec->finished());
}

TEST(Executive, AnUnconfirmedCommandStopsCommandingThatDeviceAndTheRestGoesOn) {
  auto exec = ds1_executive();
  ToySpacecraft sc;
  sc.never_confirm.insert("ips");
  Outcome r = run(exec.get(), &sc, 100, [](Time, ToySpacecraft*) {});
  const ExecutiveEvent* e = r.first("fault stop_commanding");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->time, 36);  // thrust sent at 30, 5 to confirm
  EXPECT_TRUE(exec->disabled("ips"));
  // The planned standby is not sent to the engine; the camera's part of the plan was done.
  EXPECT_EQ(sent(sc), (std::vector<std::string>{"camera take_image@10", "ips thrust@30"}));
  EXPECT_TRUE(r.has("skipped"));
  EXPECT_FALSE(r.replan);
  EXPECT_TRUE(exec->finished());
}

TEST(Executive, ATurnTheWorldEndsIsObservedAndItsLatenessBreaksThePlan) {
  FlexiblePlan plan;
  plan.horizon = 100;
  add_token(&plan, "sc.attitude", "attitude", "pointAt", {"star"}, 0, 0, 0, kUnbounded, "initial");
  add_token(&plan, "sc.attitude", "attitude", "turning", {"star", "asteroid"}, 0, 100, 20, 40,
            "before of token 2");
  add_token(&plan, "sc.attitude", "attitude", "pointAt", {"asteroid"}, 0, 100, 0, kUnbounded,
            "goal point");
  CommandMap map;
  std::string error;
  ASSERT_TRUE(map.add({"sc.attitude", "turning", "adcs", "turn", "turning", {"?1"}, 3, "pointing"},
                      &error));
  auto exec = Executive::create(plan, map, ds1_fault_table({}, {}), {}, 0, &error);
  ASSERT_TRUE(exec) << error;
  ToySpacecraft sc;
  // The turn never completes: at 41 its bound (start 0 + 40) has passed.
  Outcome r = run(exec.get(), &sc, 60, [](Time, ToySpacecraft*) {});
  EXPECT_EQ(sent(sc), (std::vector<std::string>{"adcs turn@0"}));
  EXPECT_EQ(sc.received[0].arguments, std::vector<std::string>{"asteroid"});
  const ExecutiveEvent* v = r.first("violation");
  ASSERT_TRUE(v);
  EXPECT_EQ(v->time, 41);
  ASSERT_TRUE(r.replan);
  EXPECT_EQ(r.replan->state[0].predicate, "turning");
  EXPECT_EQ(r.replan->remaining_goals.size(), 1u);

  // Ended by the world at 25: the pointing starts then, and the plan finishes.
  exec = Executive::create(plan, map, ds1_fault_table({}, {}), {}, 0, &error);
  ToySpacecraft sc2;
  r = run(exec.get(), &sc2, 100, [](Time t, ToySpacecraft* s) {
    if (t == 25) s->modes["adcs"] = "pointing";
  });
  EXPECT_FALSE(r.replan);
  EXPECT_TRUE(exec->finished());
  EXPECT_EQ(exec->dispatcher().executed_at(2, true), 25);
}

TEST(Executive, DispatchesThePlannersCameraPlan) {
  planner::Diagnostics errors;
  const std::string dir = PLANNER_EXAMPLES_DIR;
  auto model_text = planner::read_text_file(dir + "/camera.model", &errors);
  auto problem_text = planner::read_text_file(dir + "/camera.problem", &errors);
  ASSERT_TRUE(model_text && problem_text) << planner::to_string(errors);
  auto m = planner::parse_model(*model_text, "camera.model", &errors);
  auto model = planner::build_domain_model(*m, &errors);
  auto p = planner::parse_problem(*problem_text, "camera.problem", &errors);
  auto problem = planner::build_problem(*model, *p, &errors);
  ASSERT_TRUE(problem) << planner::to_string(errors);
  planner::PlanningOptions options;
  options.termination.max_decisions = 10000;
  planner::PlanResult result = planner::make_plan(*model, *problem, options);
  ASSERT_TRUE(result.plan) << result.explanation;

  CommandMap map;
  std::string error;
  for (CommandRule r : std::vector<CommandRule>{
           {"dsone.attitude", "turning", "adcs", "turn", "turning", {"?1"}, 3, "pointing"},
           {"dsone.camera", "picture", "camera", "take_image", "imaging", {"?0"}, 3},
           {"dsone.camera", "ready", "camera", "", "ready"}})
    ASSERT_TRUE(map.add(r, &error)) << error;
  auto exec = Executive::create(*result.plan, map, ds1_fault_table({}, {}), {}, 0, &error);
  ASSERT_TRUE(exec) << error;
  ToySpacecraft sc;
  Time turn_done = -1;
  Outcome r = run(exec.get(), &sc, 200, [&](Time t, ToySpacecraft* s) {
    if (s->modes["adcs"] == "turning" && turn_done < 0) turn_done = t + 25;  // the turn takes 25
    if (t == turn_done) s->modes["adcs"] = "pointing";
  });
  EXPECT_FALSE(r.replan) << (r.replan ? r.replan->reason : "");
  EXPECT_TRUE(exec->finished());
  ASSERT_EQ(sc.received.size(), 2u);
  EXPECT_EQ(sc.received[0].command, "turn");
  EXPECT_EQ(sc.received[0].arguments, std::vector<std::string>{"asteroid"});
  EXPECT_EQ(sc.received[1].command, "take_image");
  EXPECT_EQ(sc.received[1].arguments, std::vector<std::string>{"asteroid"});
  EXPECT_GE(sc.received[1].sent, turn_done);  // the picture waits for the observed turn end
}

// The camera sticks (abort at 16); the thruster sticks at 30, while the replan is awaited: the
// control mode is switched then, and there is no second abort.
TEST(Executive, AThrusterStickingWhileAReplanIsAwaitedIsAnsweredWithoutASecondAbort) {
  auto exec = ds1_executive();
  ToySpacecraft sc;
  sc.stuck.insert("camera");
  Outcome r = run(exec.get(), &sc, 100, [](Time t, ToySpacecraft* s) {
    if (t == 30) s->modes["thruster_x"] = "stuck_closed";
  });
  ASSERT_TRUE(r.replan);
  const std::vector<std::string> responses = r.responses();
  ASSERT_FALSE(responses.empty());
  EXPECT_EQ(std::count(responses.begin(), responses.end(), "fault switch_control_mode@30"), 1) << responses.back();
  EXPECT_EQ(std::count_if(responses.begin(), responses.end(),
                          [](const std::string& x) { return x.rfind("fault abort_and_replan", 0) == 0; }),
            1);
  const std::vector<std::string> commands = sent(sc);
  EXPECT_EQ(std::count(commands.begin(), commands.end(), "adcs set_mode@30"), 1);
}

}  // namespace
}  // namespace autonomy::executive

namespace autonomy::executive {
namespace {

void four_faults(Time t, ToySpacecraft* s) {
  s->readings["bus_current_a"] = 1.0;
  s->readings["bus_current_b"] = 1.0;
  s->readings["bus_switch_status"] = t < 5 ? 1.0 : 0.0;
  if (t == 12) s->modes["thruster_x"] = "stuck_closed";
  if (t == 20) s->modes["lpe"] = "failed";
}

TEST(Executive, FourFaultsTogetherEachGetItsResponseAndThePlanFinishes) {
  auto exec = ds1_executive();
  ToySpacecraft sc;
  sc.never_confirm.insert("ips");
  Outcome r = run(exec.get(), &sc, 100, four_faults);
  EXPECT_EQ(r.responses(),
            (std::vector<std::string>{"fault ignore_sensor@7", "fault switch_control_mode@12",
                                      "fault reset@20", "fault stop_commanding@36"}));
  EXPECT_EQ(sent(sc), (std::vector<std::string>{"camera take_image@10", "adcs set_mode@12",
                                                "lpe reset@20", "ips thrust@30"}));
  EXPECT_FALSE(r.replan);
  EXPECT_TRUE(exec->finished());
}

TEST(Executive, WithAllFiveTheStuckCameraAbortsAfterTheEarlierResponses) {
  auto exec = ds1_executive();
  ToySpacecraft sc;
  sc.never_confirm.insert("ips");
  sc.stuck.insert("camera");
  Outcome r = run(exec.get(), &sc, 100, four_faults);
  // The electronics unit that fails at 20, after the abort, is still reset: faults are answered
  // while the replan is awaited.
  EXPECT_EQ(r.responses(),
            (std::vector<std::string>{"fault ignore_sensor@7", "fault switch_control_mode@12",
                                      "fault abort_and_replan@16", "fault reset@20"}));
  const std::vector<std::string> commands = sent(sc);
  EXPECT_EQ(std::count(commands.begin(), commands.end(), "lpe reset@20"), 1);
  ASSERT_TRUE(r.replan);
  EXPECT_EQ(r.replan->known_faults, (std::map<std::string, std::string>{
                                        {"camera", "imaging"}, {"thruster_x", "stuck_closed"}}));
  EXPECT_TRUE(exec->aborted());
  EXPECT_FALSE(exec->finished());
}

}  // namespace
}  // namespace autonomy::executive

namespace autonomy::executive {
namespace {

// The camera's power: a bus switch with a status sensor, the camera's current on the bus, the
// camera's own mode report. The camera needs the bus on.
ModeIdentifier camera_power_model() {
  ComponentModel bus{"camera_bus",
                     {{"on", false, 0, "", {{"camera_bus.status", 1, 0.1}}},
                      {"off", false, 0, "", {{"camera_bus.status", 0, 0.1}}},
                      {"failed", true, 1.0, "", {{"camera_bus.status", 0, 0.1}}}},
                     {}};
  ComponentModel camera{"camera",
                        {{"off", false, 0, "off", {{"camera.current", 0, 0.1}}},
                         {"ready", false, 0, "ready", {{"camera.current", 0.5, 0.2}}},
                         {"imaging", false, 0, "imaging", {{"camera.current", 1.2, 0.3}}},
                         {"stuck_on", true, 1.0, "imaging", {{"camera.current", 1.2, 0.3}}},
                         {"unpowered", false, 0, "off", {{"camera.current", 0, 0.1}}}},
                        {{"camera_bus", {"on"}, "unpowered"}}};
  std::string error;
  // Given dependants first: the identifier orders them itself.
  auto id = ModeIdentifier::create({camera, bus}, ModeCosts{}, &error);
  EXPECT_TRUE(id) << error;
  return *id;
}

Observations camera_readings(double status, double current, std::string report) {
  Observations o;
  o.readings = {{"camera_bus.status", status}, {"camera.current", current}};
  o.device_modes = {{"camera", std::move(report)}};
  return o;
}

const std::map<std::string, std::string> kImaging{{"camera_bus", "on"}, {"camera", "imaging"}};

TEST(ModeIdentification, ReadingsAsCommandedAreTheCommandedModes) {
  Diagnosis d = camera_power_model().identify(kImaging, camera_readings(1, 1.2, "imaging"));
  EXPECT_EQ(d.modes.at("camera_bus"), "on");
  EXPECT_EQ(d.modes.at("camera"), "imaging");
  EXPECT_TRUE(d.faults.empty());
  EXPECT_TRUE(d.false_sensors.empty());
  EXPECT_DOUBLE_EQ(d.cost, 0);
  EXPECT_FALSE(d.ambiguous);
}

// The DS1 case: the bus status says off while the camera draws imaging current and reports
// imaging. One false sensor (cost 1) explains it; a failed bus would leave two readings
// unexplained (the current and the report: cost 1 + 2).
TEST(ModeIdentification, ALoneDisagreeingSensorIsJudgedFalse) {
  Diagnosis d = camera_power_model().identify(kImaging, camera_readings(0, 1.2, "imaging"));
  EXPECT_EQ(d.modes.at("camera_bus"), "on");
  EXPECT_EQ(d.modes.at("camera"), "imaging");
  EXPECT_EQ(d.false_sensors, (std::vector<std::string>{"camera_bus.status"}));
  EXPECT_TRUE(d.faults.empty());
  EXPECT_DOUBLE_EQ(d.cost, 1.0);
}

// The same status reading with the other readings agreeing: the bus failed (cost 1) and the
// camera is off because of it, not a second fault; blaming sensors would take three.
TEST(ModeIdentification, ReadingsThatAgreeOnAFailureAreAFailedDevice) {
  Diagnosis d = camera_power_model().identify(kImaging, camera_readings(0, 0, "off"));
  EXPECT_EQ(d.modes.at("camera_bus"), "failed");
  EXPECT_EQ(d.modes.at("camera"), "unpowered");
  EXPECT_EQ(d.faults, (std::vector<std::string>{"camera_bus=failed"}));
  EXPECT_TRUE(d.false_sensors.empty());
  EXPECT_DOUBLE_EQ(d.cost, 1.0);
}

// Commanded off, the camera still reports imaging and draws current: stuck on (1) beats
// "the command was not taken" (2) and two false readings (2).
TEST(ModeIdentification, ACameraStillOnAfterItsOffIsStuckOn) {
  Diagnosis d = camera_power_model().identify({{"camera_bus", "on"}, {"camera", "off"}},
                                              camera_readings(1, 1.2, "imaging"));
  EXPECT_EQ(d.modes.at("camera"), "stuck_on");
  EXPECT_EQ(d.faults, (std::vector<std::string>{"camera=stuck_on"}));
  EXPECT_DOUBLE_EQ(d.cost, 1.0);
  EXPECT_GT(d.assignments_tried, 0u);
}

// Absent readings predict nothing: with no telemetry at all the commanded modes stand.
TEST(ModeIdentification, NoReadingsLeaveTheCommandedModes) {
  Diagnosis d = camera_power_model().identify(kImaging, Observations{});
  EXPECT_EQ(d.modes.at("camera"), "imaging");
  EXPECT_DOUBLE_EQ(d.cost, 0);
}

TEST(ModeIdentification, BadModelsAreRejectedWithTheirReason) {
  std::string error;
  ComponentModel a{"a", {{"on", false, 0, "", {}}}, {{"b", {"on"}, "on"}}};
  ComponentModel b{"b", {{"on", false, 0, "", {}}}, {{"a", {"on"}, "on"}}};
  EXPECT_FALSE(ModeIdentifier::create({a, b}, ModeCosts{}, &error));
  EXPECT_NE(error.find("cycle"), std::string::npos) << error;
  ComponentModel c{"c", {{"on", false, 0, "", {}}}, {{"nobody", {"on"}, "on"}}};
  EXPECT_FALSE(ModeIdentifier::create({c}, ModeCosts{}, &error));
  EXPECT_NE(error.find("unknown component 'nobody'"), std::string::npos) << error;
  ComponentModel d{"d", {{"on", false, 0, "", {}}}, {{"b2", {"up"}, "on"}}};
  ComponentModel b2{"b2", {{"on", false, 0, "", {}}}, {}};
  EXPECT_FALSE(ModeIdentifier::create({d, b2}, ModeCosts{}, &error));
  EXPECT_NE(error.find("unknown mode 'up'"), std::string::npos) << error;
}

// As a fault response: the diagnosis acts once it held for `samples` ticks: the false
// sensor is ignored (once), the failed bus reset (and answered again if it fails again after
// recovering).
TEST(ModeIdentification, AsAResponseItActsOnStableDiagnosesOnce) {
  ModeIdentificationResponse response(
      camera_power_model(), {{"camera_bus", "failed", FaultAction::Kind::kReset, "", ""}}, 2);
  PlanState plan;
  plan.expected_modes = kImaging;
  EXPECT_TRUE(response.assess(camera_readings(0, 1.2, "imaging"), plan).empty());  // 1st sample
  auto actions = response.assess(camera_readings(0, 1.2, "imaging"), plan);
  ASSERT_EQ(actions.size(), 1u);
  EXPECT_EQ(actions[0].kind, FaultAction::Kind::kIgnoreSensor);
  EXPECT_EQ(actions[0].subject, "camera_bus.status");
  EXPECT_NE(actions[0].reason.find("false camera_bus.status"), std::string::npos)
      << actions[0].reason;
  EXPECT_TRUE(response.assess(camera_readings(0, 1.2, "imaging"), plan).empty());  // done

  for (int round = 0; round < 2; ++round) {
    EXPECT_TRUE(response.assess(camera_readings(0, 0, "off"), plan).empty());
    actions = response.assess(camera_readings(0, 0, "off"), plan);
    ASSERT_EQ(actions.size(), 1u) << round;
    EXPECT_EQ(actions[0].kind, FaultAction::Kind::kReset);
    EXPECT_EQ(actions[0].subject, "camera_bus");
    EXPECT_TRUE(response.assess(camera_readings(0, 0, "off"), plan).empty());
    // The reset worked: nominal readings again.
    response.assess(camera_readings(1, 1.2, "imaging"), plan);
    response.assess(camera_readings(1, 1.2, "imaging"), plan);
  }
}

}  // namespace
}  // namespace autonomy::executive

namespace autonomy::executive {
namespace {

TEST(GoalLabel, IsTheGoalsOwnLabelWhateverMergedIntoIt) {
  EXPECT_EQ(goal_label("goal down1"), "down1");
  EXPECT_EQ(goal_label("goal pass1; containedBy of token 22"), "pass1");
  EXPECT_EQ(goal_label("goal"), "goal");
  EXPECT_EQ(goal_label("initial dsone.camera"), "");
  EXPECT_EQ(goal_label("before of token 3"), "");
}

}  // namespace
}  // namespace autonomy::executive
