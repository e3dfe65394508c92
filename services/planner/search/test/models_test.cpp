// The shipped models (services/planner/examples) planned by every engine, every plan through
// the independent validator, and their outcomes checked on the plan itself: the DS1-like day,
// the rover, job-shop ft06; and infeasible variants answered with their conflicting
// statements' file:line.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

#include "jobshop_instance.hpp"
#include "plan_validator.hpp"
#include "planner.hpp"
#include "planner_language.hpp"

namespace autonomy::planner {
namespace {

const std::string kExamples = PLANNER_EXAMPLES_DIR;

struct LoadedModel {
  DomainModel model;
  PlanningProblem problem;
};

// Model and problem files as shipped; `extra` is appended to the problem (its lines follow
// the file's, so conflicts keep naming the file's own lines).
std::optional<LoadedModel> load_model(const std::string& model_name, const std::string& problem_name,
                           const std::string& extra = "") {
  const std::string model_file = kExamples + "/" + model_name;
  const std::string problem_file = kExamples + "/" + problem_name;
  Diagnostics errors;
  auto model_text = read_text_file(model_file, &errors);
  auto problem_text = read_text_file(problem_file, &errors);
  if (!model_text || !problem_text) {
    ADD_FAILURE() << to_string(errors);
    return std::nullopt;
  }
  auto m = parse_model(*model_text, model_file, &errors);
  auto model = m ? build_domain_model(*m, &errors) : std::nullopt;
  auto p = model ? parse_problem(*problem_text + extra, problem_file, &errors) : std::nullopt;
  auto problem = p ? build_problem(*model, *p, &errors) : std::nullopt;
  if (!problem) {
    ADD_FAILURE() << to_string(errors);
    return std::nullopt;
  }
  return LoadedModel{*model, *problem};
}

// "file:line" of the first line of a shipped file that starts with `prefix`.
std::string line_of(const std::string& name, const std::string& prefix) {
  std::ifstream in(kExamples + "/" + name);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (line.rfind(prefix, 0) == 0) return kExamples + "/" + name + ":" + std::to_string(n);
  ADD_FAILURE() << "no line starting with " << prefix << " in " << name;
  return "?";
}

int line_count(const std::string& name) {
  std::ifstream in(kExamples + "/" + name);
  std::string line;
  int n = 0;
  while (std::getline(in, line)) ++n;
  return n;
}

PlanResult plan_with(const LoadedModel& c, const std::string& engine, std::size_t budget = 200000) {
  PlanningOptions options;
  options.engine = engine;
  options.termination.max_decisions = budget;
  return make_plan(c.model, c.problem, options);
}

std::vector<const PlanToken*> tokens_of(const FlexiblePlan& plan, const std::string& timeline,
                                        const std::string& predicate) {
  std::vector<const PlanToken*> out;
  for (const PlanToken& t : plan.tokens)
    if (t.timeline() == timeline && t.predicate == predicate) out.push_back(&t);
  return out;
}

// At the earliest times (the schedule the validator fixes), [start, end) intervals.
bool overlap(const PlanToken& a, const PlanToken& b) {
  return a.start_lb < b.end_lb && b.start_lb < a.end_lb;
}
bool within(const PlanToken& inner, const PlanToken& outer) {
  return outer.start_lb <= inner.start_lb && inner.end_lb <= outer.end_lb;
}

// Every mandatory goal is achieved by a token of the plan (merged goals count for each).
void expect_every_mandatory_goal(const PlanningProblem& problem, const FlexiblePlan& plan,
                                 const std::string& engine) {
  std::vector<bool> achieved(problem.facts.size(), false);
  for (const PlanToken& t : plan.tokens) {
    if (t.fact >= 0) achieved[t.fact] = true;
    for (int f : t.facts) achieved[f] = true;
  }
  for (std::size_t f = 0; f < problem.facts.size(); ++f)
    if (!problem.facts[f].optional)
      EXPECT_TRUE(achieved[f]) << engine << ": goal " << problem.facts[f].label << " missing";
}

// Engines expected to plan each shipped problem within the decision budget. Iterative
// sampling restarts at every dead end: the DS1 day needs about a hundred backtracks, which no
// probe survives, so it is not expected there.
bool engine_expected(const std::string& problem, const std::string& engine) {
  return !(problem == "ds1-day.problem" && engine == "sampling");
}

TEST(ShippedModels, TheDs1DayIsPlannedWithEveryOutcomeTheModelPromises) {
  auto c = load_model("ds1.model", "ds1-day.problem");
  ASSERT_TRUE(c);
  std::size_t goals = 0;
  for (const FactDef& f : c->problem.facts) goals += !f.initial;
  EXPECT_EQ(goals, 100u);
  for (const std::string& engine : search_engine_names()) {
    PlanResult r = plan_with(*c, engine);
    if (!engine_expected("ds1-day.problem", engine)) {
      // It never claims more than it knows: no plan is not "infeasible".
      EXPECT_NE(r.status, PlanStatus::kInfeasible) << engine;
      if (!r.plan) continue;
    }
    ASSERT_EQ(r.status, PlanStatus::kPlanFound) << engine << ": " << r.explanation;
    const FlexiblePlan& plan = *r.plan;
    EXPECT_EQ(validate_plan(c->model, c->problem, plan), std::vector<std::string>{}) << engine;
    expect_every_mandatory_goal(c->problem, plan, engine);

    const auto pictures = tokens_of(plan, "dsone.camera", "picture");
    const auto thrusts = tokens_of(plan, "dsone.engine", "thrusting");
    const auto pointings = tokens_of(plan, "dsone.attitude", "pointAt");
    const auto turns = tokens_of(plan, "dsone.attitude", "turning");
    const auto downlinks = tokens_of(plan, "dsone.radio", "downlink");
    EXPECT_GE(pictures.size(), 48u) << engine;
    EXPECT_EQ(thrusts.size(), 12u) << engine;
    EXPECT_EQ(downlinks.size(), 12u) << engine;
    // Images never while thrusting; the spacecraft points at the target during each image.
    for (const PlanToken* p : pictures) {
      for (const PlanToken* t : thrusts)
        EXPECT_FALSE(overlap(*p, *t)) << engine << ": picture " << p->id << " during thrust";
      bool pointed = false;
      for (const PlanToken* a : pointings)
        pointed |= a->parameters[0] == p->parameters[0] && within(*p, *a);
      EXPECT_TRUE(pointed) << engine << ": picture " << p->id << " of " << p->parameters[0];
    }
    // Downlinks point at Earth; power (2500) never holds a thrust (2000) and a downlink (600).
    for (const PlanToken* d : downlinks) {
      bool earth = false;
      for (const PlanToken* a : pointings) earth |= a->parameters[0] == "earth" && within(*d, *a);
      EXPECT_TRUE(earth) << engine;
      for (const PlanToken* t : thrusts) EXPECT_FALSE(overlap(*d, *t)) << engine;
    }
    // Each turn lasts 60 s + 4 s per degree of the angle the table gives for its targets,
    // and the attitude timeline is continuous: pointing, turn, pointing, ...
    ASSERT_FALSE(turns.empty());
    for (const PlanToken* t : turns) {
      const long angle = std::stol(t->parameters[2]);
      EXPECT_EQ(t->end_lb - t->start_lb, 60 + 4 * angle) << engine;
      EXPECT_NE(t->parameters[0], t->parameters[1]);
    }
    const PlanTimeline* attitude = nullptr;
    for (const PlanTimeline& tl : plan.timelines)
      if (tl.name == "dsone.attitude") attitude = &tl;
    ASSERT_TRUE(attitude);
    for (std::size_t k = 1; k < attitude->tokens.size(); ++k) {
      const PlanToken &a = plan.tokens[attitude->tokens[k - 1]],
                      &b = plan.tokens[attitude->tokens[k]];
      EXPECT_EQ(a.end_lb, b.start_lb) << engine << ": a gap in the attitude";
      EXPECT_NE(a.predicate, b.predicate) << engine;
      if (b.predicate == "turning") EXPECT_EQ(b.parameters[0], a.parameters[0]);
      if (a.predicate == "turning") EXPECT_EQ(a.parameters[1], b.parameters[0]);
    }
    // Data storage: images add 4, downlinks take 16; never below 0 nor above 40.
    std::map<std::int64_t, double> change;
    for (const PlanToken* p : pictures) change[p->end_lb] += 4;
    for (const PlanToken* d : downlinks) change[d->end_lb] -= 16;
    double level = 0, peak = 0;
    for (auto& [at, delta] : change) {
      level += delta;
      peak = std::max(peak, level);
      EXPECT_GE(level, 0) << engine << " at " << at;
      EXPECT_LE(level, 40) << engine << " at " << at;
    }
    EXPECT_GE(peak, 16);
    std::printf("%s: DS1 day, %zu tokens, %zu decisions, %zu backtracks, %zu omitted\n",
                engine.c_str(), plan.tokens.size(), r.statistics.decisions, r.statistics.backtracks,
                plan.omitted_goals.size());
  }
}

TEST(ShippedModels, TheRoverSamplesWhereItStandsAndTransmitsInPassesOnItsBattery) {
  auto c = load_model("rover.model", "rover.problem");
  ASSERT_TRUE(c);
  for (const std::string& engine : search_engine_names()) {
    PlanResult r = plan_with(*c, engine);
    ASSERT_EQ(r.status, PlanStatus::kPlanFound) << engine << ": " << r.explanation;
    const FlexiblePlan& plan = *r.plan;
    EXPECT_EQ(validate_plan(c->model, c->problem, plan), std::vector<std::string>{}) << engine;
    expect_every_mandatory_goal(c->problem, plan, engine);
    const auto samples = tokens_of(plan, "spirit.arm", "sampling");
    const auto places = tokens_of(plan, "spirit.location", "at");
    const auto drives = tokens_of(plan, "spirit.location", "driving");
    const auto sends = tokens_of(plan, "spirit.radio", "transmitting");
    const auto passes = tokens_of(plan, "spirit.orbiter", "overhead");
    ASSERT_EQ(samples.size(), 3u) << engine;
    ASSERT_EQ(sends.size(), 3u) << engine;
    for (const PlanToken* s : samples) {
      bool there = false;
      for (const PlanToken* a : places)
        there |= a->parameters[0] == s->parameters[0] && within(*s, *a);
      EXPECT_TRUE(there) << engine << ": sample at " << s->parameters[0];
      // Its results go home in a pass, after it.
      bool sent = false;
      for (const PlanToken* t : sends) {
        if (t->parameters[0] != s->parameters[0]) continue;
        sent = true;
        EXPECT_GE(t->start_lb, s->end_lb) << engine;
        bool in_pass = false;
        for (const PlanToken* p : passes)
          in_pass |= p->parameters[0] == t->parameters[1] && within(*t, *p);
        EXPECT_TRUE(in_pass) << engine;
      }
      EXPECT_TRUE(sent) << engine;
    }
    for (const PlanToken* d : drives)
      EXPECT_EQ(d->end_lb - d->start_lb, 2 * std::stol(d->parameters[2])) << engine;
    // Battery: 50 at first, drives 15, samples 10, transmissions 5, the charge +40 at 9000.
    std::map<std::int64_t, double> change;
    for (const PlanToken* d : drives) change[d->end_lb] -= 15;
    for (const PlanToken* s : samples) change[s->end_lb] -= 10;
    for (const PlanToken* t : sends) change[t->end_lb] -= 5;
    for (const PlanToken* ch : tokens_of(plan, "spirit.sun", "charging")) change[ch->end_lb] += 40;
    double level = 50;
    for (auto& [at, delta] : change) {
      level += delta;
      EXPECT_GE(level, 0) << engine << " at " << at;
    }
    // 90 needed, 50 in the battery: something waits for the charge.
    std::int64_t last_end = 0;
    for (const PlanToken* t : sends) last_end = std::max(last_end, t->end_lb);
    EXPECT_GT(last_end, 9000) << engine;
  }
}

TEST(ShippedModels, JobShopFt06WithEveryEngine) {
  Diagnostics errors;
  const std::string file = kExamples + "/jobshop/ft06";
  auto inst = parse_jobshop(*read_text_file(file, &errors), file, &errors);
  ASSERT_TRUE(inst) << to_string(errors);
  auto model = build_domain_model(jobshop_model(*inst), &errors);
  auto problem = build_problem(*model, jobshop_problem(*inst), &errors);
  ASSERT_TRUE(model && problem) << to_string(errors);
  for (const std::string& engine : search_engine_names()) {
    PlanResult r = plan_with({*model, *problem}, engine, 50000);
    ASSERT_TRUE(r.plan) << engine << ": " << to_string(r.status);
    EXPECT_EQ(validate_plan(*model, *problem, *r.plan), std::vector<std::string>{}) << engine;
    EXPECT_GE(r.plan->makespan, 55) << engine;
    if (engine == "sampling") {
      EXPECT_EQ(r.status, PlanStatus::kPlanFound);  // incomplete: never a proof
    } else if (engine == "repair") {
      // Incomplete, but its proofs are sound: it proves only what it exhausted.
      EXPECT_NE(r.status, PlanStatus::kInfeasible);
      if (r.status == PlanStatus::kOptimal) {
        EXPECT_EQ(r.plan->makespan, 55);
      }
    } else {
      EXPECT_EQ(r.status, PlanStatus::kOptimal) << engine;
      EXPECT_EQ(r.plan->makespan, 55) << engine;
    }
  }
}

TEST(ShippedModels, TheCameraWithEveryEngine) {
  auto c = load_model("camera.model", "camera.problem");
  ASSERT_TRUE(c);
  for (const std::string& engine : search_engine_names()) {
    PlanResult r = plan_with(*c, engine);
    ASSERT_EQ(r.status, PlanStatus::kPlanFound) << engine;
    EXPECT_EQ(validate_plan(c->model, c->problem, *r.plan), std::vector<std::string>{});
    expect_every_mandatory_goal(c->problem, *r.plan, engine);
  }
}

void expect_names(const std::string& explanation, const std::vector<std::string>& places) {
  for (const std::string& p : places)
    EXPECT_NE(explanation.find(p + ")"), std::string::npos) << p << " not in: " << explanation;
}

TEST(ShippedModels, AnInfeasibleDs1DayNamesItsConflictingStatements) {
  // The first downlink (in the pass from 4800) cannot come before the first image (by 4800).
  const int relation_line = line_count("ds1-day.problem") + 1;
  auto c = load_model("ds1.model", "ds1-day.problem", "down1 before nav1_1\n");
  ASSERT_TRUE(c);
  for (const std::string& engine : search_engine_names()) {
    PlanResult r = plan_with(*c, engine);
    EXPECT_EQ(r.status, PlanStatus::kInfeasible) << engine;
    expect_names(r.explanation, {line_of("ds1-day.problem", "goal down1:"),
                                 line_of("ds1-day.problem", "goal nav1_1:"),
                                 kExamples + "/ds1-day.problem:" + std::to_string(relation_line)});
  }
}

TEST(ShippedModels, AnInfeasibleRoverNamesItsConflictingStatements) {
  const int first = line_count("rover.problem") + 1;
  auto c = load_model("rover.model", "rover.problem", "s1 before s2\ns2 before s1\n");
  ASSERT_TRUE(c);
  PlanResult r = plan_with(*c, "chronological");
  EXPECT_EQ(r.status, PlanStatus::kInfeasible);
  expect_names(r.explanation, {kExamples + "/rover.problem:" + std::to_string(first),
                               kExamples + "/rover.problem:" + std::to_string(first + 1)});
  // The samples' own statements are in the cycle too (their durations separate the ends).
  EXPECT_NE(r.explanation.find("duration of sampling"), std::string::npos) << r.explanation;
}

TEST(ShippedModels, AJobShopWithTooShortAHorizonNamesTheJobAndTheHorizon) {
  Diagnostics errors;
  const std::string file = kExamples + "/jobshop/ft06";
  auto inst = parse_jobshop(*read_text_file(file, &errors), file, &errors);
  ASSERT_TRUE(inst);
  pb::Problem p = jobshop_problem(*inst);
  // Job 0 of ft06 takes 1 + 3 + 6 + 7 + 3 + 6 = 26 on its own.
  p.set_horizon(25);
  auto model = build_domain_model(jobshop_model(*inst), &errors);
  auto problem = build_problem(*model, p, &errors);
  ASSERT_TRUE(model && problem) << to_string(errors);
  PlanResult r = make_plan(*model, *problem, {});
  EXPECT_EQ(r.status, PlanStatus::kInfeasible);
  EXPECT_NE(r.explanation.find("the horizon 25"), std::string::npos) << r.explanation;
  EXPECT_NE(r.explanation.find(file + ":" + std::to_string(inst->job_lines[0]) + ")"),
            std::string::npos)
      << r.explanation;
}

}  // namespace
}  // namespace autonomy::planner
