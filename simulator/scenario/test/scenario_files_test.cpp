// Scenario files as files: every malformed file in test/bad/ is refused with the message its first
// line announces ("# expect: line:col: message", the message as a prefix), and the shipped
// scenarios in deploy/scenarios/ load and build a World.
#include "simulator/core/world.hpp"
#include "simulator/office/office_state.hpp"
#include "simulator/scenario/scenario_loader.hpp"
#include "simulator/spacecraft/spacecraft.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace autonomy::sim {
namespace {

namespace fs = std::filesystem;

const fs::path kBad = fs::path(AUTONOMY_SOURCE_DIR) / "simulator/scenario/test/bad";
const fs::path kShipped = fs::path(AUTONOMY_SOURCE_DIR) / "deploy/scenarios";

std::string expectation(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  const std::string tag = "# expect: ";
  return line.rfind(tag, 0) == 0 ? line.substr(tag.size()) : "";
}

class BadScenario : public ::testing::TestWithParam<std::string> {};

TEST_P(BadScenario, IsRefusedWithItsFileLineAndMessage) {
  const fs::path file = kBad / GetParam();
  const std::string expected = file.string() + ":" + expectation(file);
  ASSERT_NE(expectation(file), "") << file << " has no '# expect:' first line";
  const ScenarioLoadResult result = load_scenario_file(file.string());
  ASSERT_FALSE(result.ok());
  ASSERT_EQ(result.errors.size(), 1u) << result.error_text();
  EXPECT_EQ(result.errors[0].to_string().substr(0, expected.size()), expected);
}

INSTANTIATE_TEST_SUITE_P(Files, BadScenario,
                         ::testing::Values("door_unknown_room.pbtxt", "overlapping_robots.pbtxt",
                                           "robot_in_polygon.pbtxt", "robot_in_map.pbtxt",
                                           "robot_on_door.pbtxt", "self_crossing_polygon.pbtxt",
                                           "missing_map.pbtxt", "door_script_backwards.pbtxt",
                                           "place_unknown_room.pbtxt", "place_in_obstacle.pbtxt",
                                           "duplicate_waypoint.pbtxt", "bad_sensor.pbtxt",
                                           "bad_area.pbtxt", "bad_radio.pbtxt", "syntax_error.pbtxt",
                                           "parking_in_obstacle.pbtxt", "duplicate_parking.pbtxt",
                                           // The office: people, objects, loading stations.
                                           "person_unknown_desk.pbtxt", "duplicate_person.pbtxt",
                                           "presence_backwards.pbtxt", "presence_overlap.pbtxt",
                                           "presence_bad_clock.pbtxt", "negative_handover_time.pbtxt",
                                           "station_uniform_backwards.pbtxt", "object_unknown_place.pbtxt",
                                           "duplicate_object.pbtxt", "object_unknown_carrier.pbtxt",
                                           "carrier_over_capacity.pbtxt"),
                         [](const auto& info) { return info.param.substr(0, info.param.find('.')); });

TEST(BadScenarioFiles, EveryFileInTheFolderIsListed) {
  int files = 0;
  for (const auto& entry : fs::directory_iterator(kBad)) files += entry.path().extension() == ".pbtxt";
  EXPECT_EQ(files, 28);  // 17 of the world, 11 of the office
}

Scenario load_shipped(const std::string& name) {
  const ScenarioLoadResult result = load_scenario_file((kShipped / name).string());
  EXPECT_TRUE(result.ok()) << result.error_text();
  return result.ok() ? *result.scenario : Scenario{};
}

TEST(ShippedScenarios, OfficeFloorHasTheCourierPapersRoomsDoorsAndPlaces) {
  const Scenario s = load_shipped("office.pbtxt");
  EXPECT_EQ(s.world.name, "office-floor");
  EXPECT_EQ(s.rooms.size(), 13u);  // hallway + 12 rooms
  EXPECT_EQ(s.world.doors.size(), 12u);
  const auto door = [&](const std::string& id) {
    for (const DoorSpec& d : s.world.doors) if (d.id == id) return d;
    return DoorSpec{};
  };
  EXPECT_EQ(door("A-120").schedule.kind, DoorScheduleSpec::Kind::Script);
  EXPECT_EQ(door("A-116").schedule.kind, DoorScheduleSpec::Kind::Random);
  EXPECT_EQ(door("A-120").rooms[1], "A-120");
  bool michael = false;
  for (const PlaceSpec& p : s.places) michael |= p.name == "michael-desk" && p.room == "A-120";
  EXPECT_TRUE(michael);
  ASSERT_EQ(s.parking.size(), 4u);  // the hallway's dead ends and two empty offices
  EXPECT_EQ(s.parking[0].name, "hall-west-end");
  EXPECT_DOUBLE_EQ(s.parking[1].position.x(), 39.4);
  World world(s.world);
  const auto rhino = world.robot_spec("rhino");
  ASSERT_TRUE(rhino.has_value());
  EXPECT_EQ(rhino->capacity, 3u);
  EXPECT_EQ(rhino->kind, "courier");
  // The office: people at their desks, objects on desks and the mail room's tray.
  ASSERT_TRUE(s.office.has_value());
  EXPECT_EQ(s.office->people.size(), 6u);
  EXPECT_EQ(s.office->objects.size(), 8u);
  ASSERT_EQ(s.office->stations.size(), 2u);
  EXPECT_EQ(s.office->stations[0].place, "mail-tray");
  const office::OfficeState office(*s.office);
  EXPECT_EQ(office.people_present("michael-desk", 0.0), std::vector<std::string>{"Michael"});  // 09:00
  EXPECT_EQ(office.people_present("michael-desk", 12600.0), std::vector<std::string>{});  // 12:30, lunch
  EXPECT_TRUE(office.object("book-green")->location.is_at("librarian-desk"));
  EXPECT_EQ(office.place("michael-desk")->room, "A-120");
  // Every door is reachable through its doorway from the hallway: sight from the hallway centre
  // line in front of it to a point 1.5 m into the room.
  for (const DoorSpec& d : s.world.doors) {
    const double into = d.swing == DoorSwing::Clockwise ? -1.5 : 1.5;
    EXPECT_TRUE(world.line_of_sight({d.position.x(), 8.0}, {d.position.x() + 0.2, d.position.y() + into})) << d.id;
  }
  // A-120 closes at t = 15 s and opens again at t = 40 s (the paper's Fig. 5).
  for (int i = 0; i < 151; ++i) world.step(0.1);
  EXPECT_TRUE(world.door("A-120")->closed());
  for (int i = 0; i < 250; ++i) world.step(0.1);
  EXPECT_FALSE(world.door("A-120")->closed());
}

TEST(ShippedScenarios, ReconAreaHasBuildingsCarsAreasAndWaypoints) {
  const Scenario s = load_shipped("recon.pbtxt");
  EXPECT_DOUBLE_EQ(s.world.width, 250.0);
  EXPECT_EQ(s.world.polygons.size(), 30u);
  ASSERT_EQ(s.world.rasters.size(), 1u);
  EXPECT_EQ(s.world.rasters[0].raster->width(), 250);
  EXPECT_DOUBLE_EQ(s.world.rasters[0].raster->resolution_m(), 1.0);
  EXPECT_GE(s.radio.areas.size(), 10u);
  EXPECT_EQ(s.waypoints.size(), 5u);
  EXPECT_EQ(s.world.robots_at_start.size(), 3u);
  World world(s.world);
  // The street is open from the entrance to the goal.
  EXPECT_TRUE(world.line_of_sight({125, 55}, {125, 245}));
  EXPECT_EQ(world.sense("scout1")->ranges.size(), 32u);
}

TEST(ShippedScenarios, StressMapHasAHundredRobotsOnAThousandMetres) {
  const Scenario s = load_shipped("stress.pbtxt");
  EXPECT_DOUBLE_EQ(s.world.width, 1000.0);
  EXPECT_EQ(s.world.robots_at_start.size(), 100u);
  World world(s.world);
  EXPECT_EQ(world.robots().size(), 100u);
}

TEST(ShippedScenarios, Ds1IsTheSpacecraftDayOfThePlannersModelWithoutRobots) {
  const Scenario s = load_shipped("ds1.pbtxt");
  ASSERT_TRUE(s.spacecraft.has_value());
  EXPECT_EQ(s.spacecraft->name, "ds1");
  EXPECT_EQ(s.spacecraft->targets.size(), 9u);  // the sky of services/planner/examples/ds1.model
  EXPECT_EQ(s.spacecraft->telecom.windows.size(), 12u);  // ds1-day.problem's passes
  EXPECT_TRUE(s.spacecraft->faults.empty());  // switched on per run
  EXPECT_TRUE(s.world.robots_at_start.empty());
  EXPECT_EQ(s.simulation.mode, ClockMode::Lockstep);
  EXPECT_DOUBLE_EQ(s.simulation.step_s, 1.0);
  const spacecraft::Spacecraft ds1(*s.spacecraft);
  EXPECT_EQ(ds1.mode("camera"), "ready");
  EXPECT_EQ(ds1.attitude().pointing_target(), "earth");
}

TEST(ShippedScenarios, DemoStillLoads) {
  const Scenario s = load_shipped("demo.pbtxt");
  EXPECT_EQ(s.world.name, "demo");
}

}  // namespace
}  // namespace autonomy::sim
