// The mission executor: the paper's serial mission, its wait-until-reconnected deadlock and the
// fixes (timeout, wander), transition chains, plans in parallel inside a state.
#include "services/behavior/core/mission/mission_executor.hpp"
#include "services/behavior/core/mission/mission_loader.hpp"
#include "services/behavior/core/schemas/noise.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace autonomy::behavior {
namespace {

using geometry::Vec2;
using Kind = MissionEvent::Kind;

MissionSpec parse(const std::string& text) {
  MissionLoadResult r = load_mission_text(text, "test.pbtxt");
  EXPECT_TRUE(r.ok()) << r.error_text();
  return r.ok() ? *r.mission : MissionSpec{};
}

// Holonomic, 1 m/s, one teammate r2 whose link the test switches.
Perception robot(double t, Vec2 position, bool r2_in_contact) {
  Perception p;
  p.time_s = t;
  p.pose = {position.x(), position.y(), 0.0};
  p.limits = {1.0, 2.0};
  p.teammates = {{"r2", Vec2(0.0, 10.0), r2_in_contact}};
  return p;
}

std::vector<std::string> describe(const std::vector<MissionEvent>& events) {
  std::vector<std::string> out;
  for (const MissionEvent& e : events) out.push_back(e.to_string());
  return out;
}

// Figure 1 of the paper, reduced to one leg: go to a point; if contact is lost, stop and wait
// until it is re-established; continue.
const std::string kPaperSerial = R"(
teammates: "r2"
initial_state: "go"
states {
  name: "go"
  go_to { goal { x: 40 y: 0 } tolerance: 1 }
  transitions { to: "wait" when { lost_contact {} } }
  transitions { to: "done" when { at_goal {} } }
}
states {
  name: "wait"
  wait {}
  transitions { to: "go" when { contact_restored {} } }
  WAIT_EXTRA
}
states {
  name: "go_alone"
  go_to { goal { x: 40 y: 0 } tolerance: 1 }
  transitions { to: "done" when { at_goal {} } }
}
states {
  name: "wander"
  wander { gains { noise: 1 } }
  transitions { to: "go" when { contact_restored {} } }
}
states { name: "done" stop {} }
)";

std::string with_wait_extra(const std::string& extra) {
  std::string text = kPaperSerial;
  text.replace(text.find("WAIT_EXTRA"), 10, extra);
  return text;
}

// Steps the executor once per second, moving the robot by the commanded velocity; the link to r2
// is down from t = 5 on, for good.
struct SteppedRun {
  MissionExecutor executor;
  Vec2 position = Vec2::Zero();
  std::vector<std::string> events;

  MissionStep step(double t) {
    MissionStep s = executor.step(robot(t, position, t < 5.0));
    position += Vec2(s.command.vx, s.command.vy) * 1.0;
    for (auto& e : describe(s.events)) events.push_back(e);
    return s;
  }
};

TEST(MissionExecutor, PaperWaitUntilReconnectedDeadlocks) {
  SteppedRun run{MissionExecutor(parse(with_wait_extra("")), {}), Vec2::Zero(), {}};
  const MissionStep first = run.step(0.0);
  EXPECT_EQ(first.state, "go");
  EXPECT_DOUBLE_EQ(first.velocity.x(), 1.0);  // move_to_goal alone, full speed
  EXPECT_DOUBLE_EQ(first.command.vx, 1.0);
  for (int t = 1; t <= 1000; ++t) (void)run.step(t);
  EXPECT_EQ(run.executor.state(), "wait");
  EXPECT_FALSE(run.executor.finished());
  EXPECT_EQ(run.position, Vec2(5.0, 0.0));  // stopped where the link broke, forever
  EXPECT_EQ(run.events, (std::vector<std::string>{"t=0 started in go",
                                                  "t=5 go -> wait: lost contact with r2"}));
}

TEST(MissionExecutor, TimeoutResolvesTheDeadlock) {
  SteppedRun run{MissionExecutor(parse(with_wait_extra(
              R"(transitions { to: "go_alone" when { timeout { seconds: 30 } } })")), {}),
          Vec2::Zero(), {}};
  MissionStep s;
  for (int t = 0; t <= 100 && !s.finished; ++t) s = run.step(t);
  EXPECT_TRUE(s.finished);
  EXPECT_EQ(s.state, "done");
  // Waited 5..35 at x = 5, then 1 m/s until within the 2 m slowdown radius; at_goal at x = 39.
  EXPECT_EQ(run.events, (std::vector<std::string>{
                            "t=0 started in go",
                            "t=5 go -> wait: lost contact with r2",
                            "t=35 wait -> go_alone: timeout: 30 s in state",
                            "t=69 go_alone -> done: at goal (40, 0) within 1 m",
                            "t=69 finished in done",
                        }));
  EXPECT_TRUE(s.command.is_zero());
  // Stop is final.
  const MissionStep after = run.executor.step(robot(70.0, run.position, true));
  EXPECT_EQ(after.state, "done");
  EXPECT_TRUE(after.events.empty());
}

TEST(MissionExecutor, WanderOutOfWaitingUntilContactIsBack) {
  MissionExecutorOptions options;
  options.noise_seed = 99;
  MissionExecutor executor(
      parse(with_wait_extra(R"(transitions { to: "wander" when { timeout { seconds: 30 } } })")), {},
      options);
  (void)executor.step(robot(0.0, Vec2(0, 0), false));  // go -> wait at once
  EXPECT_EQ(executor.state(), "wait");
  const MissionStep waiting = executor.step(robot(29.0, Vec2(0, 0), false));
  EXPECT_EQ(waiting.velocity, Vec2::Zero());
  const MissionStep wandering = executor.step(robot(30.0, Vec2(0, 0), false));
  EXPECT_EQ(wandering.state, "wander");
  // Wander = noise (gain 1) + avoid_obstacles (no rays): the noise direction at full speed.
  Perception p = robot(30.0, Vec2(0, 0), false);
  const Vec2 expected = Noise({2.0, 99}).vote(p);
  EXPECT_NEAR(wandering.velocity.x(), expected.x(), 1e-12);
  EXPECT_NEAR(wandering.velocity.y(), expected.y(), 1e-12);
  const MissionStep back = executor.step(robot(37.0, Vec2(3, 3), true));
  EXPECT_EQ(back.state, "go");
  EXPECT_EQ(describe(back.events),
            (std::vector<std::string>{"t=37 wander -> go: contact restored with all teammates"}));
}

TEST(MissionExecutor, EnteredStatesAreCheckedAtOnceAndCyclesAreCapped) {
  const std::string chain = R"(
teammates: "r2"
initial_state: "check"
states { name: "check" wait {} transitions { to: "go" when { contact_restored {} } } }
states { name: "go" go_to { goal { x: 10 y: 0 } } }
)";
  MissionExecutor executor(parse(chain), {});
  const MissionStep s = executor.step(robot(0.0, Vec2(0, 0), true));
  EXPECT_EQ(s.state, "go");
  EXPECT_EQ(describe(s.events),
            (std::vector<std::string>{"t=0 started in check",
                                      "t=0 check -> go: contact restored with all teammates"}));
  EXPECT_DOUBLE_EQ(s.velocity.x(), 1.0);

  const std::string cycle = R"(
initial_state: "a"
states { name: "a" wait {} transitions { to: "b" when { in_area { circle { center {} radius: 100 } } } } }
states { name: "b" wait {} transitions { to: "a" when { in_area { circle { center {} radius: 100 } } } } }
)";
  MissionExecutor looping(parse(cycle), {});
  const MissionStep l = looping.step(robot(0.0, Vec2(0, 0), true));
  EXPECT_EQ(l.events.size(), 3u);  // started, a -> b, b -> a; then the cap (2 states) stops it
  EXPECT_EQ(l.state, "a");
}

// Plans in parallel inside a go_to state. Hand-built fields (1 m cells), goal at cell (4, 1):
// "obstacles" is open; "obstacles+comm" blocks column 2 in rows 1-2 (an attenuating area).
PlanLibrary tiny_library() {
  const Vec2 goal(4.5, 1.5);
  auto field = [&](const std::vector<std::string>& picture) {
    return std::make_shared<const CostToGoField>(OccupancyGrid::from_picture(picture, 1.0), goal);
  };
  std::vector<Plan> plans;
  plans.push_back(Plan::from_field("obstacles", field({".....", ".....", "....."})));
  plans.push_back(Plan::from_field("obstacles+comm", field({"..#..", "..#..", "....."})));
  return {{"p", std::make_shared<const PlanSet>("p", goal, std::move(plans))}};
}

std::string plan_mission(const std::string& selection) {
  return R"(
initial_state: "go"
layers { name: "comm" areas { min_x: 2 min_y: 1 max_x: 3 max_y: 3 } }
plan_sets { name: "p" goal { x: 4.5 y: 1.5 } layers: "obstacles" layers: "comm" selection: )" +
         selection + R"( }
states { name: "go" go_to { plan_set: "p" gains { reactive: 0.66 plan: 0.34 } } }
)";
}

const double kR = 1.0 / std::sqrt(2.0);

TEST(MissionExecutor, StaticPlanChosenOnEntryAndBlendedWithReactiveGains) {
  MissionExecutor executor(parse(plan_mission("STATIC")), tiny_library());
  const MissionStep s = executor.step(robot(0.0, Vec2(0.5, 1.5), true));
  EXPECT_EQ(describe(s.events), (std::vector<std::string>{
                                    "t=0 started in go",
                                    "t=0 go: static selection chose plan obstacles+comm"}));
  // 0.66 * move_to_goal (1, 0) + 0.34 * advice (r, -r); avoid_obstacles sees no rays.
  EXPECT_NEAR(s.velocity.x(), 0.66 + 0.34 * kR, 1e-6);
  EXPECT_NEAR(s.velocity.y(), -0.34 * kR, 1e-6);
  ASSERT_TRUE(s.plan.has_value());
  EXPECT_EQ(s.plan->plan, 1u);
  // Pushed into the attenuating area (column 2, rows 1-2): static selection keeps plan 1, whose
  // advice there is the way back out, to the nearest cell it affords a route from: (2, 0), south.
  const MissionStep inside = executor.step(robot(1.0, Vec2(2.5, 1.5), true));
  EXPECT_EQ(inside.plan->plan, 1u);
  EXPECT_NEAR(inside.velocity.x(), 0.66, 1e-9);
  EXPECT_NEAR(inside.velocity.y(), -0.34, 1e-9);
}

TEST(MissionExecutor, DynamicPlanReChosenEveryStep) {
  MissionExecutor executor(parse(plan_mission("DYNAMIC")), tiny_library());
  EXPECT_EQ(executor.step(robot(0.0, Vec2(0.5, 1.5), true)).plan->plan, 1u);
  const MissionStep inside = executor.step(robot(1.0, Vec2(2.5, 1.5), true));
  EXPECT_EQ(inside.plan->plan, 0u);
  EXPECT_NEAR(inside.velocity.x(), 0.66 + 0.34, 1e-9);  // both point east; 1.0 = max speed
}

TEST(MissionExecutor, StaticChoiceRetriedUntilAPlanHasARoute) {
  MissionExecutor executor(parse(plan_mission("STATIC")), tiny_library());
  const MissionStep off = executor.step(robot(0.0, Vec2(50.0, 50.0), true));
  EXPECT_EQ(describe(off.events), (std::vector<std::string>{
                                      "t=0 started in go", "t=0 go: no plan has a route from here yet"}));
  EXPECT_FALSE(off.plan.has_value());
  const MissionStep on = executor.step(robot(1.0, Vec2(2.5, 1.5), true));
  EXPECT_EQ(describe(on.events),
            (std::vector<std::string>{"t=1 go: static selection chose plan obstacles"}));
  EXPECT_EQ(on.plan->plan, 0u);
}

// A resumed executor (behavior --journal after a restart) continues in the journalled state:
// its Timeout counts from the first entry, not from the resume; nothing before is done again.
TEST(MissionExecutor, ResumedWhereItWasWithTheTimeFromTheFirstEntry) {
  const std::string text = with_wait_extra(R"(transitions { to: "go_alone" when { timeout { seconds: 30 } } })");
  SteppedRun first{MissionExecutor(parse(text), {}), Vec2::Zero(), {}};
  for (int t = 0; t <= 10; ++t) (void)first.step(t);
  const auto progress = first.executor.progress();
  ASSERT_TRUE(progress);
  EXPECT_EQ(progress->state, "wait");
  EXPECT_EQ(progress->entered_at_s, 5.0);
  EXPECT_EQ(progress->plan, "");

  SteppedRun second{MissionExecutor(parse(text), {}), first.position, {}};
  EXPECT_FALSE(second.executor.progress());
  EXPECT_EQ(describe(second.executor.resume(*progress, robot(20.0, second.position, false), "after a restart")),
            (std::vector<std::string>{"t=20 resumed in wait: after a restart"}));
  EXPECT_EQ(second.executor.state(), "wait");
  MissionStep s;
  for (int t = 20; t <= 100 && !s.finished; ++t) s = second.step(t);
  EXPECT_TRUE(s.finished);
  // The timeout fires 30 s after the first entry (t = 5), not after the resume (t = 20).
  EXPECT_EQ(second.events, (std::vector<std::string>{
                               "t=35 wait -> go_alone: timeout: 30 s in state",
                               "t=69 go_alone -> done: at goal (40, 0) within 1 m",
                               "t=69 finished in done",
                           }));
  EXPECT_THROW((void)second.executor.resume(*progress, robot(70.0, second.position, false), ""), std::logic_error);

  MissionExecutor unknown(parse(text), {});
  EXPECT_THROW((void)unknown.resume({"fly", 0.0, ""}, robot(0.0, Vec2::Zero(), true), ""), std::invalid_argument);
  // A finished mission resumes finished, without a second Finished event.
  MissionExecutor done(parse(text), {});
  EXPECT_EQ(describe(done.resume({"done", 69.0, ""}, robot(80.0, Vec2(39.0, 0.0), true), "again")),
            (std::vector<std::string>{"t=80 resumed in done: again"}));
  EXPECT_TRUE(done.finished());
}

TEST(MissionExecutor, ResumedStaticChoiceKeepsThePlanChosenBefore) {
  MissionExecutor executor(parse(plan_mission("STATIC")), tiny_library());
  (void)executor.step(robot(0.0, Vec2(0.5, 1.5), true));
  ASSERT_TRUE(executor.progress());
  EXPECT_EQ(executor.progress()->plan, "obstacles+comm");
  // From (2.5, 1.5), inside the attenuating area, a fresh static choice would take plan 0
  // ("obstacles"): the resumed one keeps the plan chosen before and announces no choice.
  MissionExecutor fresh(parse(plan_mission("STATIC")), tiny_library());
  EXPECT_EQ(fresh.step(robot(0.0, Vec2(2.5, 1.5), true)).plan->plan, 0u);
  MissionExecutor resumed(parse(plan_mission("STATIC")), tiny_library());
  EXPECT_EQ(describe(resumed.resume(*executor.progress(), robot(3.0, Vec2(2.5, 1.5), true), "restart")),
            (std::vector<std::string>{"t=3 resumed in go: restart"}));
  EXPECT_EQ(resumed.step(robot(3.0, Vec2(2.5, 1.5), true)).plan->plan, 1u);
  // A plan the set no longer has is chosen anew, and said so.
  MissionExecutor renamed(parse(plan_mission("STATIC")), tiny_library());
  EXPECT_EQ(describe(renamed.resume({"go", 0.0, "gone"}, robot(3.0, Vec2(2.5, 1.5), true), "restart")),
            (std::vector<std::string>{"t=3 resumed in go: restart", "t=3 go: static selection chose plan obstacles"}));
}

TEST(MissionExecutor, UnicycleCommandFromTheBlend) {
  MissionExecutor executor(parse(with_wait_extra("")), {});
  Perception p = robot(0.0, Vec2(0, 0), true);
  p.kinematics = Kinematics::Unicycle;
  p.pose.theta = M_PI / 2;  // facing +y, goal along +x: turn in place
  const MissionStep s = executor.step(p);
  EXPECT_DOUBLE_EQ(s.command.vx, 0.0);
  EXPECT_DOUBLE_EQ(s.command.omega, -2.0);
}

TEST(MissionExecutor, RejectsInconsistentSpecs) {
  EXPECT_THROW(MissionExecutor(parse(plan_mission("STATIC")), {}), std::invalid_argument);
  MissionSpec spec = parse(with_wait_extra(""));
  spec.initial_state = "nowhere";
  EXPECT_THROW(MissionExecutor(spec, {}), std::invalid_argument);
}

TEST(PlanLibrary, BuildsCumulativeConstraintLayersFromTheMap) {
  const MissionSpec spec = parse(R"(
initial_state: "s"
layers { name: "comm" areas { min_x: 8 min_y: 0 max_x: 12 max_y: 6 } }
plan_sets { name: "p" goal { x: 18 y: 2 } layers: "obstacles" layers: "comm" }
states { name: "s" stop {} }
)");
  WorldMap map{20.0, 10.0, {geometry::Rect{4.0, 4.0, 6.0, 10.0}}};
  const PlanLibrary library = build_plan_library(spec, map, 0.5, 0.25);
  ASSERT_EQ(library.count("p"), 1u);
  const PlanSet& set = *library.at("p");
  ASSERT_EQ(set.size(), 2u);
  EXPECT_EQ(set.plans()[0].name(), "obstacles");
  EXPECT_EQ(set.plans()[1].name(), "obstacles+comm");
  EXPECT_TRUE(std::isfinite(set.plans()[0].query({10.0, 3.0}).cost));  // inside the comm area
  EXPECT_FALSE(std::isfinite(set.plans()[1].query({10.0, 3.0}).cost));
  EXPECT_FALSE(std::isfinite(set.plans()[0].query({5.0, 7.0}).cost));  // the map's obstacle
  EXPECT_EQ(set.most_constrained_viable({1.0, 1.0}), 1u);  // around the area over the top
}

}  // namespace
}  // namespace autonomy::behavior
