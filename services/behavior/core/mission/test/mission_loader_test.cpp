// Mission files: values of a valid file, and the exact position and text of each error.
#include "services/behavior/core/mission/mission_loader.hpp"

#include <gtest/gtest.h>

namespace autonomy::behavior {
namespace {

using Errors = std::vector<std::string>;

Errors errors_of(const std::string& text) {
  const MissionLoadResult result = load_mission_text(text, "m.pbtxt");
  EXPECT_FALSE(result.ok());
  EXPECT_FALSE(result.mission.has_value());
  Errors out;
  for (const MissionError& e : result.errors) out.push_back(e.to_string());
  return out;
}

TEST(MissionLoader, ValidFileLoadsWithItsValuesAndDefaults) {
  const std::string text = R"(# the leftmost robot of the serial experiment, shortened
name: "serial_r1"
robot: "r1"
teammates: "r2"
teammates: "r3"
initial_state: "disperse"
schemas { sphere_of_influence: 5 safety_margin: 1 noise_persistence: 3 }
layers { name: "comm_attenuation" areas { min_x: 60 min_y: 80 max_x: 110 max_y: 200 } }
plan_sets {
  name: "to_goal"
  goal { x: 125 y: 245 }
  layers: "obstacles"
  layers: "comm_attenuation"
  selection: BLENDED
  blend_gains: 0.3
  blend_gains: 0.7
}
states {
  name: "disperse"
  go_to { goal { x: 30 y: 40 } tolerance: 5 gains { reactive: 0.66 noise: 0.11 } }
  transitions { to: "regroup" when { in_area { rect { min_x: 0 min_y: 30 max_x: 60 max_y: 50 } } } }
}
states {
  name: "regroup"
  go_to { plan_set: "to_goal" gains { reactive: 0.34 plan: 0.66 avoid_teammates: 0.2 } }
  transitions { to: "wait" when { lost_contact { teammate: "r2" } } }
  transitions {
    to: "done"
    when { any_of { triggers { at_goal {} } triggers { timeout { seconds: 600 } } } }
  }
}
states {
  name: "wait"
  wait {}
  transitions { to: "regroup" when { contact_restored {} } }
  transitions { to: "wander" when { timeout { seconds: 30 } } }
}
states {
  name: "wander"
  wander { gains { noise: 0.8 stay_near_teammates: 0.5 } }
  transitions { to: "regroup" when { all_of { triggers { contact_restored {} } } } }
}
states { name: "done" stop {} }
)";
  const MissionLoadResult result = load_mission_text(text, "serial_r1.pbtxt");
  ASSERT_TRUE(result.ok()) << result.error_text();
  const MissionSpec& m = *result.mission;
  EXPECT_EQ(m.name, "serial_r1");
  EXPECT_EQ(m.robot, "r1");
  EXPECT_EQ(m.teammates, (std::vector<std::string>{"r2", "r3"}));
  EXPECT_EQ(m.initial_state, "disperse");
  EXPECT_DOUBLE_EQ(m.schemas.sphere_of_influence_m, 5.0);
  EXPECT_DOUBLE_EQ(m.schemas.safety_margin_m, 1.0);
  EXPECT_DOUBLE_EQ(m.schemas.noise_persistence_s, 3.0);
  EXPECT_DOUBLE_EQ(m.schemas.slowdown_radius_m, 2.0);  // default

  ASSERT_EQ(m.layers.size(), 1u);
  EXPECT_EQ(m.layers[0].name, "comm_attenuation");
  EXPECT_EQ(m.layers[0].areas[0], (geometry::Rect{60, 80, 110, 200}));

  ASSERT_EQ(m.plan_sets.size(), 1u);
  const PlanSetSpec& p = m.plan_sets[0];
  EXPECT_EQ(p.goal, geometry::Vec2(125, 245));
  EXPECT_EQ(p.layers, (std::vector<std::string>{"obstacles", "comm_attenuation"}));
  EXPECT_EQ(p.selection, PlanSelectionMode::Blended);
  EXPECT_EQ(p.blend_gains, (std::vector<double>{0.3, 0.7}));

  ASSERT_EQ(m.states.size(), 5u);
  const StateSpec& disperse = m.states[0];
  EXPECT_EQ(disperse.behavior.kind, BehaviorSpec::Kind::GoTo);
  EXPECT_EQ(disperse.behavior.goal, geometry::Vec2(30, 40));
  EXPECT_DOUBLE_EQ(disperse.behavior.tolerance_m, 5.0);
  SchemaGains g;
  g.move_to_goal = 0.66;
  g.avoid_obstacles = 0.66;
  g.noise = 0.11;
  EXPECT_EQ(disperse.behavior.gains, g);
  ASSERT_EQ(disperse.transitions.size(), 1u);
  EXPECT_EQ(disperse.transitions[0].to, "regroup");
  EXPECT_EQ(disperse.transitions[0].when.kind, TriggerSpec::Kind::InArea);
  EXPECT_EQ(disperse.transitions[0].when.area.shape, Area::Shape::Rect);
  EXPECT_EQ(disperse.transitions[0].when.area.rect, (geometry::Rect{0, 30, 60, 50}));

  const StateSpec& regroup = m.states[1];
  EXPECT_EQ(regroup.behavior.plan_set, "to_goal");
  EXPECT_EQ(regroup.behavior.goal, geometry::Vec2(125, 245));  // the plan set's goal
  EXPECT_DOUBLE_EQ(regroup.behavior.tolerance_m, 2.0);          // default
  EXPECT_DOUBLE_EQ(regroup.behavior.gains.move_to_goal, 0.34);
  EXPECT_DOUBLE_EQ(regroup.behavior.gains.plan, 0.66);
  EXPECT_DOUBLE_EQ(regroup.behavior.gains.avoid_teammates, 0.2);
  EXPECT_EQ(regroup.transitions[0].when.kind, TriggerSpec::Kind::LostContact);
  EXPECT_EQ(regroup.transitions[0].when.teammate, "r2");
  const TriggerSpec& any = regroup.transitions[1].when;
  EXPECT_EQ(any.kind, TriggerSpec::Kind::AnyOf);
  ASSERT_EQ(any.children.size(), 2u);
  EXPECT_EQ(any.children[0].kind, TriggerSpec::Kind::AtGoal);
  EXPECT_DOUBLE_EQ(any.children[1].seconds, 600.0);

  EXPECT_EQ(m.states[2].behavior.kind, BehaviorSpec::Kind::Wait);
  EXPECT_EQ(m.states[2].transitions[0].when.kind, TriggerSpec::Kind::ContactRestored);
  EXPECT_EQ(m.states[2].transitions[0].when.teammate, "");
  const BehaviorSpec& wander = m.states[3].behavior;
  EXPECT_EQ(wander.kind, BehaviorSpec::Kind::Wander);
  EXPECT_DOUBLE_EQ(wander.gains.noise, 0.8);
  EXPECT_DOUBLE_EQ(wander.gains.avoid_obstacles, 1.0);  // wander default
  EXPECT_DOUBLE_EQ(wander.gains.move_to_goal, 0.0);
  EXPECT_DOUBLE_EQ(wander.gains.stay_near_teammates, 0.5);
  EXPECT_EQ(m.states[4].behavior.kind, BehaviorSpec::Kind::Stop);
}

TEST(MissionLoader, SyntaxErrorsComeAloneWithTheParsersPosition) {
  // The parser reports where it noticed the problem: after the unknown name, at its value.
  EXPECT_EQ(errors_of("initial_state: \"a\"\nstates { name: \"a\" wiat {} }\n"),
            Errors{"m.pbtxt:2:25: Message type \"autonomy.config.MissionState\" has no field named "
                   "\"wiat\"."});
}

TEST(MissionLoader, NoInitialState) {
  EXPECT_EQ(errors_of("states { name: \"a\" wait {} }\n"),
            Errors{"m.pbtxt:1:1: initial_state is missing"});
  EXPECT_EQ(errors_of("initial_state: \"b\"\nstates { name: \"a\" wait {} }\n"),
            Errors{"m.pbtxt:1:1: initial_state names unknown state b"});
  EXPECT_EQ(errors_of("initial_state: \"a\"\n"),
            (Errors{"m.pbtxt:1:1: mission has no states",
                    "m.pbtxt:1:1: initial_state names unknown state a"}));
}

TEST(MissionLoader, DuplicateStateName) {
  EXPECT_EQ(errors_of("initial_state: \"a\"\n"
                      "states { name: \"a\" wait {} }\n"
                      "states { name: \"a\" stop {} }\n"),
            Errors{"m.pbtxt:3:10: duplicate state name a (first defined at line 2)"});
}

TEST(MissionLoader, UnknownStateInATransition) {
  EXPECT_EQ(errors_of("initial_state: \"a\"\n"
                      "states { name: \"a\" wait {} transitions { to: \"b\" when { timeout { seconds: 1 } } } }\n"),
            Errors{"m.pbtxt:2:42: state a: transition to unknown state b"});
}

TEST(MissionLoader, NegativeGain) {
  EXPECT_EQ(errors_of("initial_state: \"a\"\n"
                      "states {\n"
                      "  name: \"a\"\n"
                      "  go_to { goal { x: 1 y: 1 } gains { noise: -0.5 reactive: -1 } }\n"
                      "}\n"),
            (Errors{"m.pbtxt:4:38: state a: gain noise must not be negative (got -0.5)",
                    "m.pbtxt:4:50: state a: gain reactive must not be negative (got -1)"}));
}

TEST(MissionLoader, TriggersMissingParameters) {
  const std::string head = "initial_state: \"a\"\nteammates: \"r2\"\n";
  EXPECT_EQ(errors_of(head + "states { name: \"a\" wait {} transitions { to: \"a\" when { timeout {} } } }\n"),
            Errors{"m.pbtxt:3:57: state a: timeout seconds must be positive (got 0)"});
  EXPECT_EQ(errors_of(head + "states { name: \"a\" wait {} transitions { to: \"a\" when { timeout { seconds: -2 } } } }\n"),
            Errors{"m.pbtxt:3:67: state a: timeout seconds must be positive (got -2)"});
  EXPECT_EQ(errors_of(head + "states { name: \"a\" wait {} transitions { to: \"a\" when { lost_contact { teammate: \"r9\" } } } }\n"),
            Errors{"m.pbtxt:3:72: state a: lost_contact names unknown teammate r9"});
  EXPECT_EQ(errors_of(head + "states { name: \"a\" wait {} transitions { to: \"a\" when { in_area {} } } }\n"),
            Errors{"m.pbtxt:3:57: state a: in_area needs a circle or a rect"});
  EXPECT_EQ(errors_of(head + "states { name: \"a\" wait {} transitions { to: \"a\" when { in_area { circle { center {} } } } } }\n"),
            Errors{"m.pbtxt:3:67: state a: in_area circle radius must be positive (got 0)"});
  EXPECT_EQ(errors_of(head + "states { name: \"a\" wait {} transitions { to: \"a\" when { at_goal {} } } }\n"),
            Errors{"m.pbtxt:3:57: state a: at_goal needs a go_to state (this state has no goal)"});
  EXPECT_EQ(errors_of(head + "states { name: \"a\" wait {} transitions { to: \"a\" when {} } }\n"),
            Errors{"m.pbtxt:3:50: state a: trigger is empty (at_goal, in_area, lost_contact, "
                   "contact_restored, timeout, all_of or any_of)"});
  EXPECT_EQ(errors_of(head + "states { name: \"a\" wait {} transitions { to: \"a\" } }\n"),
            Errors{"m.pbtxt:3:28: state a: transition to a has no trigger (when)"});
  EXPECT_EQ(errors_of(head + "states { name: \"a\" wait {} transitions { to: \"a\" when { any_of {} } } }\n"),
            Errors{"m.pbtxt:3:57: state a: any_of has no triggers"});
  // Without a teammates list, "any" / "all" contact triggers have nobody to watch.
  EXPECT_EQ(errors_of("initial_state: \"a\"\n"
                      "states { name: \"a\" wait {} transitions { to: \"a\" when { contact_restored {} } } }\n"),
            Errors{"m.pbtxt:2:57: state a: contact_restored without a teammate needs the "
                   "mission's teammates list"});
}

TEST(MissionLoader, BehaviorMistakes) {
  EXPECT_EQ(errors_of("initial_state: \"a\"\nstates { name: \"a\" }\n"),
            Errors{"m.pbtxt:2:1: state a: behavior is missing (go_to, wait, wander or stop)"});
  EXPECT_EQ(errors_of("initial_state: \"a\"\nstates { name: \"a\" go_to { plan_set: \"p\" } }\n"),
            Errors{"m.pbtxt:2:28: state a: unknown plan set p"});
  EXPECT_EQ(errors_of("initial_state: \"a\"\nstates { name: \"a\" go_to { tolerance: 1 } }\n"),
            Errors{"m.pbtxt:2:20: state a: go_to needs a plan_set or a goal"});
  EXPECT_EQ(errors_of("initial_state: \"a\"\nstates { name: \"a\" go_to { goal {} gains { plan: 1 } } }\n"),
            Errors{"m.pbtxt:2:44: state a: gain plan needs a plan_set to advise"});
  EXPECT_EQ(errors_of("initial_state: \"a\"\nstates { name: \"a\" wander { gains { move_to_goal: 1 } } }\n"),
            Errors{"m.pbtxt:2:37: state a: gain move_to_goal has no meaning in wander"});
  EXPECT_EQ(errors_of("initial_state: \"a\"\n"
                      "states { name: \"a\" stop {} transitions { to: \"a\" when { timeout { seconds: 1 } } } }\n"),
            Errors{"m.pbtxt:2:28: state a: a stop state ends the mission; remove its transitions"});
}

TEST(MissionLoader, PlanSetMistakes) {
  const std::string tail = "initial_state: \"a\"\nstates { name: \"a\" stop {} }\n";
  EXPECT_EQ(errors_of("plan_sets { name: \"p\" goal {} layers: \"comm\" }\n" + tail),
            Errors{"m.pbtxt:1:31: plan set p: the first layer must be \"obstacles\" (got \"comm\")"});
  EXPECT_EQ(errors_of("plan_sets { name: \"p\" goal {} layers: \"obstacles\" layers: \"fog\" }\n" + tail),
            Errors{"m.pbtxt:1:51: plan set p: unknown layer fog"});
  EXPECT_EQ(errors_of("plan_sets { name: \"p\" layers: \"obstacles\" }\n" + tail),
            Errors{"m.pbtxt:1:1: plan set p: goal is missing"});
  EXPECT_EQ(errors_of("plan_sets { name: \"p\" goal {} layers: \"obstacles\" selection: BLENDED blend_gains: 1 blend_gains: 2 }\n" + tail),
            Errors{"m.pbtxt:1:70: plan set p: BLENDED needs one blend gain per layer (1), got 2"});
  EXPECT_EQ(errors_of("plan_sets { name: \"p\" goal {} layers: \"obstacles\" blend_gains: 1 }\n" + tail),
            Errors{"m.pbtxt:1:51: plan set p: blend_gains are only used with selection BLENDED"});
  EXPECT_EQ(errors_of("layers { name: \"obstacles\" areas { max_x: 1 max_y: 1 } }\n" + tail),
            Errors{"m.pbtxt:1:10: layer name obstacles is reserved for the map's obstacles"});
  EXPECT_EQ(errors_of("layers { name: \"fog+rain\" areas { max_x: 1 max_y: 1 } }\n" + tail),
            Errors{"m.pbtxt:1:10: layer name fog+rain contains '+', which joins layer names in constraint sets"});
  EXPECT_EQ(errors_of("layers { name: \"c\" areas { min_x: 2 max_x: 1 max_y: 1 } }\n" + tail),
            Errors{"m.pbtxt:1:20: layer c: area 0 is empty or inverted: min (2, 0) must be below max (1, 1)"});
}

TEST(MissionLoader, SchemaParameterMistakesAndDuplicates) {
  const std::string tail = "initial_state: \"a\"\nstates { name: \"a\" stop {} }\n";
  EXPECT_EQ(errors_of("schemas { safety_margin: 4 }\n" + tail),
            Errors{"m.pbtxt:1:11: schemas: safety_margin 4 must be less than sphere_of_influence 3"});
  EXPECT_EQ(errors_of("schemas { noise_persistence: 0 }\n" + tail),
            Errors{"m.pbtxt:1:11: schemas: noise_persistence must be positive (got 0)"});
  EXPECT_EQ(errors_of("teammates: \"r2\"\nteammates: \"r2\"\n" + tail),
            Errors{"m.pbtxt:2:1: duplicate teammate name r2 (first defined at line 1)"});
}

TEST(MissionLoader, EveryProblemReportedInFileOrder) {
  EXPECT_EQ(errors_of("initial_state: \"a\"\n"
                      "states { name: \"a\" go_to { goal {} tolerance: -1 } transitions { to: \"x\" when { at_goal {} } } }\n"
                      "states { name: \"a\" wait {} }\n"),
            (Errors{"m.pbtxt:2:36: state a: tolerance must be positive (got -1)",
                    "m.pbtxt:2:66: state a: transition to unknown state x",
                    "m.pbtxt:3:10: duplicate state name a (first defined at line 2)"}));
}

TEST(MissionLoader, UnreadableFile) {
  const MissionLoadResult r = load_mission_file("/nonexistent/mission.pbtxt");
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].to_string(),
            "/nonexistent/mission.pbtxt: cannot read file: No such file or directory");
}

}  // namespace
}  // namespace autonomy::behavior
