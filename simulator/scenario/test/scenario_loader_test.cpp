// Scenario files: values of a valid file, and the exact position and text of each error.
#include "simulator/scenario/scenario_loader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

namespace autonomy::sim {
namespace {

using Errors = std::vector<std::string>;

Errors errors_of(const std::string& text) {
  const ScenarioLoadResult result = load_scenario_text(text, "s.pbtxt");
  EXPECT_FALSE(result.ok());
  EXPECT_FALSE(result.scenario.has_value());
  Errors out;
  for (const ScenarioError& e : result.errors) out.push_back(e.to_string());
  return out;
}

// A minimal valid world to which each case adds one mistake.
const std::string kRoom = "world { width: 10 height: 5 }\n";

TEST(ScenarioLoader, ValidFileLoadsWithItsValuesAndDefaults) {
  const std::string text = R"(# a comment
name: "lab"
world {
  width: 20.0
  height: 12.0
  obstacles { min_x: 9.8 min_y: 0 max_x: 10.2 max_y: 8 }
}
robots {
  id: "r1"
  kinematics: UNICYCLE
  radius: 0.25
  max_speed: 0.8
  start { x: 2 y: 2 theta: 1.5 }
  spawn_at_start: true
}
robots {
  id: "r2"
  kinematics: HOLONOMIC
  start { x: 2 y: 5 }
}
attach_defaults { radius: 0.4 max_omega: 1.0 }
simulation { mode: PACED warp: 4 seed: 42 command_timeout_s: 0.25 }
)";
  const ScenarioLoadResult result = load_scenario_text(text, "lab.pbtxt");
  ASSERT_TRUE(result.ok()) << result.error_text();
  const Scenario& s = *result.scenario;
  EXPECT_EQ(s.world.name, "lab");
  EXPECT_DOUBLE_EQ(s.world.width, 20.0);
  EXPECT_DOUBLE_EQ(s.world.height, 12.0);
  ASSERT_EQ(s.world.obstacles.size(), 1u);
  EXPECT_EQ(s.world.obstacles[0], (geometry::Rect{9.8, 0.0, 10.2, 8.0}));

  ASSERT_EQ(s.world.robots_at_start.size(), 1u);
  const RobotSpec& r1 = s.world.robots_at_start[0];
  EXPECT_EQ(r1.id, "r1");
  EXPECT_EQ(r1.kinematics, Kinematics::Unicycle);
  EXPECT_DOUBLE_EQ(r1.radius, 0.25);
  EXPECT_DOUBLE_EQ(r1.max_speed, 0.8);
  EXPECT_DOUBLE_EQ(r1.max_omega, 1.0);  // from attach_defaults
  EXPECT_EQ(r1.start, (geometry::Pose2{2.0, 2.0, 1.5}));

  ASSERT_EQ(s.world.known_robots.size(), 1u);
  const RobotSpec& r2 = s.world.known_robots[0];
  EXPECT_EQ(r2.id, "r2");
  EXPECT_EQ(r2.kinematics, Kinematics::Holonomic);
  EXPECT_DOUBLE_EQ(r2.radius, 0.4);     // from attach_defaults
  EXPECT_DOUBLE_EQ(r2.max_speed, 1.0);  // built-in default

  EXPECT_EQ(s.world.attach_defaults.kinematics, Kinematics::Holonomic);
  EXPECT_DOUBLE_EQ(s.world.attach_defaults.radius, 0.4);
  EXPECT_DOUBLE_EQ(s.world.command_timeout_s, 0.25);

  EXPECT_EQ(s.simulation.mode, ClockMode::Paced);
  EXPECT_DOUBLE_EQ(s.simulation.step_s, 0.05);  // default
  EXPECT_DOUBLE_EQ(s.simulation.warp, 4.0);
  EXPECT_EQ(s.simulation.seed, 42u);
  EXPECT_DOUBLE_EQ(s.simulation.ack_timeout_s, 2.0);  // default
}

TEST(ScenarioLoader, AbsentSimulationMeansLockstepDefaults) {
  const ScenarioLoadResult result = load_scenario_text(kRoom, "s.pbtxt");
  ASSERT_TRUE(result.ok()) << result.error_text();
  EXPECT_EQ(result.scenario->simulation.mode, ClockMode::Lockstep);
  EXPECT_DOUBLE_EQ(result.scenario->simulation.step_s, 0.05);
  EXPECT_DOUBLE_EQ(result.scenario->simulation.warp, 1.0);
  EXPECT_DOUBLE_EQ(result.scenario->simulation.ack_timeout_s, 2.0);
  EXPECT_DOUBLE_EQ(result.scenario->world.command_timeout_s, 0.5);
  EXPECT_DOUBLE_EQ(result.scenario->world.attach_defaults.radius, 0.3);
}

TEST(ScenarioLoader, SyntaxErrorIsLocated) {
  EXPECT_EQ(errors_of("world {\n  width: 10\n  height 5\n}\n"),
            Errors{"s.pbtxt:3:10: Expected \":\", found \"5\"."});
}

TEST(ScenarioLoader, UnknownFieldIsASyntaxErrorWithItsPosition) {
  // Column 9 is the ":" after the misspelt name: protobuf reports after reading the name.
  EXPECT_EQ(errors_of("world {\n  width: 10\n  hieght: 5\n}\n"),
            Errors{"s.pbtxt:3:9: Message type \"autonomy.config.World\" has no field named "
                   "\"hieght\"."});
}

TEST(ScenarioLoader, UnknownEnumNameIsASyntaxError) {
  // protobuf places name errors at the token after the name ("}" here, column 25).
  EXPECT_EQ(errors_of(kRoom + "simulation { mode: FAST }\n"),
            Errors{"s.pbtxt:2:25: Unknown enumeration value of \"FAST\" for field \"mode\"."});
}

TEST(ScenarioLoader, MissingWorld) {
  EXPECT_EQ(errors_of("name: \"x\"\n"), Errors{"s.pbtxt:1:1: world is missing"});
}

TEST(ScenarioLoader, NonPositiveWorldSize) {
  EXPECT_EQ(errors_of("world {\n  width: 0\n  height: -2\n}\n"),
            (Errors{"s.pbtxt:2:3: world: width must be positive (got 0.0)",
                    "s.pbtxt:3:3: world: height must be positive (got -2.0)"}));
  EXPECT_EQ(errors_of("world {\n  height: 2\n}\n"),
            Errors{"s.pbtxt:1:1: world: width must be positive (got 0.0)"});
}

TEST(ScenarioLoader, InvertedAndOutsideObstacles) {
  const std::string text = R"(world {
  width: 10
  height: 5
  obstacles { min_x: 1 min_y: 1 max_x: 2 max_y: 2 }
  obstacles { min_x: 4 min_y: 1 max_x: 3 max_y: 2 }
  obstacles { min_x: 9 min_y: 1 max_x: 11 max_y: 2 }
    obstacles { min_x: 5 min_y: 1 max_x: 6 max_y: 1 }
}
)";
  EXPECT_EQ(errors_of(text),
            (Errors{"s.pbtxt:5:3: obstacle 1 is empty or inverted: min (4.0, 1.0) must be below max (3.0, 2.0)",
                    "s.pbtxt:6:3: obstacle 2 from (9.0, 1.0) to (11.0, 2.0) extends outside the world [0, 10.0] x [0, 5.0]",
                    "s.pbtxt:7:5: obstacle 3 is empty or inverted: min (5.0, 1.0) must be below max (6.0, 1.0)"}));
}

TEST(ScenarioLoader, RobotIdProblems) {
  const std::string text = kRoom + R"(robots { kinematics: HOLONOMIC start { x: 1 y: 1 } }
robots { id: "a" kinematics: HOLONOMIC start { x: 3 y: 1 } }
robots {
  id: "a"
  kinematics: HOLONOMIC
  start { x: 5 y: 1 }
}
robots { id: "b c" kinematics: HOLONOMIC start { x: 7 y: 1 } }
)";
  EXPECT_EQ(errors_of(text),
            (Errors{"s.pbtxt:2:1: robot id is empty",
                    "s.pbtxt:5:3: duplicate robot id a (first defined at line 3)",
                    "s.pbtxt:9:10: robot id 'b c' has characters outside [A-Za-z0-9_.-]"}));
}

TEST(ScenarioLoader, RobotBodyAndLimitProblems) {
  const std::string text = kRoom + R"(robots {
  id: "r1"
  radius: 0
  max_speed: -1
  max_omega: inf
  start { x: 1 y: 1 }
}
robots { id: "r2" kinematics: UNICYCLE }
)";
  EXPECT_EQ(errors_of(text),
            (Errors{"s.pbtxt:2:1: robot r1: kinematics must be HOLONOMIC or UNICYCLE",
                    "s.pbtxt:4:3: robot r1: radius must be positive (got 0.0)",
                    "s.pbtxt:5:3: robot r1: max_speed must be positive (got -1.0)",
                    "s.pbtxt:6:3: robot r1: max_omega must be positive (got inf)",
                    "s.pbtxt:9:1: robot r2: start pose is missing"}));
}

TEST(ScenarioLoader, RobotPlacementProblems) {
  const std::string text = R"(world {
  width: 10
  height: 5
  obstacles { min_x: 4 min_y: 0 max_x: 5 max_y: 3 }
}
robots { id: "out" kinematics: HOLONOMIC start { x: 9.9 y: 2 } }
robots { id: "wall" kinematics: HOLONOMIC start { x: 5.2 y: 2 } }
robots { id: "a" kinematics: HOLONOMIC start { x: 1 y: 1 } spawn_at_start: true }
robots { id: "b" kinematics: HOLONOMIC
         start { x: 1.5 y: 1 } }
robots { id: "c" kinematics: HOLONOMIC start { x: 1 y: nan } }
)";
  EXPECT_EQ(errors_of(text),
            (Errors{"s.pbtxt:6:42: robot out at (9.9, 2.0) does not fit inside the world [0, 10.0] x [0, 5.0]",
                    "s.pbtxt:7:43: robot wall at (5.2, 2.0) overlaps obstacle 0",
                    "s.pbtxt:10:10: robot b at (1.5, 1.0) overlaps robot a",
                    "s.pbtxt:11:40: robot c: start pose is not finite"}));
}

TEST(ScenarioLoader, AttachDefaultsProblems) {
  const std::string text = kRoom + R"(attach_defaults {
  id: "x"
  radius: -0.3
  spawn_at_start: true
}
)";
  EXPECT_EQ(errors_of(text),
            (Errors{"s.pbtxt:3:3: attach_defaults: id has no meaning here; remove it",
                    "s.pbtxt:4:3: attach_defaults: radius must be positive (got -0.3)",
                    "s.pbtxt:5:3: attach_defaults: spawn_at_start has no meaning here; remove it"}));
}

TEST(ScenarioLoader, SimulationProblems) {
  const std::string text = kRoom + R"(simulation {
  mode: PACED
  step_s: -0.05
  warp: 0
  ack_timeout_s: 0
  command_timeout_s: -1
}
)";
  EXPECT_EQ(errors_of(text),
            (Errors{"s.pbtxt:4:3: simulation: step_s must be positive (got -0.05)",
                    "s.pbtxt:5:3: simulation: warp must be positive (got 0.0)",
                    "s.pbtxt:6:3: simulation: ack_timeout_s must be positive (got 0.0)",
                    "s.pbtxt:7:3: simulation: command_timeout_s must be positive (got -1.0)"}));
}

TEST(ScenarioLoader, ReportsEveryErrorInFileOrder) {
  const std::string text = R"(simulation { step_s: 0 }
world { width: -1 height: 5 }
robots { id: "r1" start { x: 1 y: 1 } }
)";
  EXPECT_EQ(errors_of(text),
            (Errors{"s.pbtxt:1:14: simulation: step_s must be positive (got 0.0)",
                    "s.pbtxt:2:9: world: width must be positive (got -1.0)",
                    "s.pbtxt:3:1: robot r1: kinematics must be HOLONOMIC or UNICYCLE"}));
}

// --- Office content ---------------------------------------------------------------------------

const std::string kOffice = R"(world { width: 10 height: 5 }
rooms { name: "A-110" bounds { min_x: 0 min_y: 0 max_x: 6 max_y: 4 } }
places { name: "anna-desk" room: "A-110" position { x: 2 y: 2 } radius: 0.8 }
places { name: "mailroom" room: "A-110" position { x: 5 y: 1 } kind: STATION }
places { name: "table" room: "A-110" position { x: 4 y: 3 } kind: TABLE }
robots { id: "r1" kinematics: HOLONOMIC start { x: 8 y: 2 } capacity: 2 }
)";

TEST(ScenarioLoader, OfficeContentBecomesAnOfficeSpec) {
  const std::string text = kOffice + R"(day_start: "09:00"
people {
  name: "Anna"
  desk: "anna-desk"
  presence { start: "09:00" end: "12:00" }
  presence { start: "13:00" end: "24:00" }
  handover_time { normal { mean_s: 20 sd_s: 5 min_s: 5 } }
}
people { name: "Bob" desk: "table" }
loading_stations { place: "mailroom" handover_time { uniform { min_s: 2 max_s: 4 } } }
objects { id: "letter-1" kind: "letter" colour: "red" place: "anna-desk" }
objects { id: "book-1" kind: "book" carrier: "r1" }
)";
  const ScenarioLoadResult result = load_scenario_text(text, "office.pbtxt");
  ASSERT_TRUE(result.ok()) << result.error_text();
  ASSERT_TRUE(result.scenario->office.has_value());
  const office::OfficeSpec& o = *result.scenario->office;
  EXPECT_DOUBLE_EQ(o.clock.day_start_s, 9 * 3600.0);

  // The room first (centre of its bounds, half its diagonal), then the places.
  ASSERT_EQ(o.places.size(), 4u);
  EXPECT_EQ(o.places[0].name, "A-110");
  EXPECT_EQ(o.places[0].kind, office::PlaceKind::room);
  EXPECT_EQ(o.places[0].position, geometry::Vec2(3.0, 2.0));
  EXPECT_DOUBLE_EQ(o.places[0].radius, std::hypot(6.0, 4.0) / 2);
  EXPECT_EQ(o.places[1].name, "anna-desk");
  EXPECT_EQ(o.places[1].kind, office::PlaceKind::desk);
  EXPECT_EQ(o.places[1].room, "A-110");
  EXPECT_DOUBLE_EQ(o.places[1].radius, 0.8);
  EXPECT_EQ(o.places[2].kind, office::PlaceKind::station);
  EXPECT_DOUBLE_EQ(o.places[2].radius, 1.0);  // default
  EXPECT_EQ(o.places[3].kind, office::PlaceKind::table);

  ASSERT_EQ(o.people.size(), 2u);
  const office::Person& anna = o.people[0];
  EXPECT_EQ(anna.desk, "anna-desk");
  ASSERT_EQ(anna.presence.size(), 2u);
  EXPECT_DOUBLE_EQ(anna.presence[0].start_s, 9 * 3600.0);
  EXPECT_DOUBLE_EQ(anna.presence[1].end_s, 86400.0);
  EXPECT_EQ(anna.handover_time.kind, office::HandoverTimeModel::Kind::normal);
  EXPECT_DOUBLE_EQ(anna.handover_time.mean_s, 20.0);
  EXPECT_DOUBLE_EQ(anna.handover_time.min_s, 5.0);
  EXPECT_DOUBLE_EQ(anna.handover_time.max_s, 40.0);  // absent: mean + 4 sd
  const office::Person& bob = o.people[1];
  EXPECT_TRUE(bob.presence.empty());
  EXPECT_EQ(bob.handover_time.kind, office::HandoverTimeModel::Kind::fixed);
  EXPECT_DOUBLE_EQ(bob.handover_time.mean_s, 10.0);  // default

  ASSERT_EQ(o.stations.size(), 1u);
  EXPECT_EQ(o.stations[0].place, "mailroom");
  EXPECT_EQ(o.stations[0].handover_time.kind, office::HandoverTimeModel::Kind::uniform);
  EXPECT_DOUBLE_EQ(o.stations[0].handover_time.max_s, 4.0);

  ASSERT_EQ(o.objects.size(), 2u);
  EXPECT_EQ(o.objects[0].id, "letter-1");
  EXPECT_EQ(o.objects[0].kind, "letter");
  EXPECT_EQ(o.objects[0].colour, "red");
  EXPECT_TRUE(o.objects[0].location.is_at("anna-desk"));
  EXPECT_TRUE(o.objects[1].location.is_carried_by("r1"));
}

TEST(ScenarioLoader, WithoutPeopleObjectsOrStationsThereIsNoOffice) {
  const ScenarioLoadResult result = load_scenario_text(kOffice, "s.pbtxt");
  ASSERT_TRUE(result.ok()) << result.error_text();
  EXPECT_FALSE(result.scenario->office.has_value());
}

TEST(ScenarioLoader, OfficeProblemsAreEachLocated) {
  const std::string text = kOffice + R"(day_start: "25:00"
people { desk: "anna-desk" }
people { name: "Anna" }
people {
  name: "Bob"
  desk: "nowhere"
  presence { start: "10:00" end: "10:00" }
  handover_time { }
}
people { name: "Cleo" desk: "table" handover_time { normal { mean_s: 5 sd_s: -1 } } }
loading_stations { handover_time { fixed_s: 1 } }
loading_stations { place: "mailroom" }
loading_stations { place: "mailroom" }
objects { id: "bad id" kind: "letter" place: "table" }
objects { id: "letter-2" place: "table" }
objects { id: "letter-3" kind: "letter" }
)";
  EXPECT_EQ(errors_of(text),
            (Errors{"s.pbtxt:7:1: day_start '25:00' is not a time of day HH:MM or HH:MM:SS (00:00 .. 24:00)",
                    "s.pbtxt:8:1: person name is empty",
                    "s.pbtxt:9:1: person 'Anna': desk is missing",
                    "s.pbtxt:12:3: person 'Bob': unknown place 'nowhere'",
                    "s.pbtxt:13:3: person 'Bob': presence 10:00-10:00 is empty",
                    "s.pbtxt:14:3: person 'Bob': handover_time names no model (fixed_s, uniform or normal)",
                    "s.pbtxt:16:72: person 'Cleo': handover_time normal sd_s must be >= 0 (got -1.0)",
                    "s.pbtxt:17:1: loading station: place is missing",
                    "s.pbtxt:19:20: duplicate loading station at 'mailroom' (first defined at line 18)",
                    "s.pbtxt:20:11: object id 'bad id' has characters outside [A-Za-z0-9_.-]",
                    "s.pbtxt:21:1: object 'letter-2': kind is missing (letter, book, envelope, ...)",
                    "s.pbtxt:22:1: object 'letter-3': place or carrier is missing"}));
}

TEST(ScenarioLoader, WithAnOfficeRoomsAndPlacesShareOneNamespace) {
  const std::string text = R"(world { width: 10 height: 5 }
rooms { name: "A-1" }
places { name: "A-1" room: "A-1" position { x: 1 y: 1 } }
objects { id: "letter-1" kind: "letter" place: "A-1" }
)";
  EXPECT_EQ(errors_of(text),
            (Errors{"s.pbtxt:3:10: place 'A-1' has the name of a room (line 2); with people, objects or loading "
                    "stations they share one namespace"}));
  // Without office content the same names are fine.
  EXPECT_TRUE(load_scenario_text(text.substr(0, text.find("objects")), "s.pbtxt").ok());
}

TEST(ScenarioLoader, FileIsReadAndNamedByItsPath) {
  const std::string path = ::testing::TempDir() + "scenario_loader_test.pbtxt";
  {
    std::ofstream out(path);
    out << "world { width: 0 height: 5 }\n";
  }
  const ScenarioLoadResult result = load_scenario_file(path);
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_EQ(result.errors[0].to_string(), path + ":1:9: world: width must be positive (got 0.0)");
  std::remove(path.c_str());
}

TEST(ScenarioLoader, UnreadableFileIsAnError) {
  const ScenarioLoadResult result = load_scenario_file("/nonexistent/x.pbtxt");
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_EQ(result.errors[0].to_string(), "/nonexistent/x.pbtxt: cannot read file: No such file or directory");
}

}  // namespace
}  // namespace autonomy::sim
