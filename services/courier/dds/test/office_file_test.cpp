#include "services/courier/dds/office_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <unistd.h>

namespace autonomy::courier {
namespace {

const std::string kOffice = std::string(AUTONOMY_SOURCE_DIR) + "/deploy/scenarios/office.pbtxt";

TEST(OfficeFile, ReadsTheCouriersKnowledgeFloorAndRobotsFromTheOfficeScenario) {
  const CourierOfficeResult r = load_courier_office(kOffice);
  ASSERT_TRUE(r.ok()) << r.error;
  const CourierOffice& o = *r.office;
  EXPECT_DOUBLE_EQ(o.knowledge.clock.day_start_s, 9 * 3600);
  ASSERT_NE(o.knowledge.find_person("Michael"), nullptr);
  EXPECT_EQ(o.knowledge.find_person("Michael")->desk, "michael-desk");
  ASSERT_NE(o.knowledge.find_object("letter-red"), nullptr);
  EXPECT_EQ(o.knowledge.find_object("letter-red")->place, "meeting-table");
  EXPECT_NE(o.knowledge.station_at("mail-tray"), nullptr);
  ASSERT_NE(o.floor.place("michael-desk"), nullptr);
  EXPECT_EQ(o.floor.place("michael-desk")->room, "A-120");
  EXPECT_EQ(o.floor.door_to("michael-desk"), std::optional<std::string>("A-120"));
  EXPECT_EQ(o.floor.door_to("hallway-west"), std::nullopt);  // the hallway has no door of its own
  EXPECT_EQ(o.floor.place("A-120"), nullptr);                // rooms are not places to drive to
  ASSERT_EQ(o.robots.size(), 1u);
  EXPECT_EQ(o.robots[0].id, "rhino");
  EXPECT_EQ(o.robots[0].capacity, 3);
  EXPECT_EQ(o.map.doors.size(), 12u);
  EXPECT_DOUBLE_EQ(o.map.width_m, 40.0);
}

// Every door of the office opens onto the hallway: each gets a lookout in the hallway, beside
// its doorway (not in front of it), clear of the walls and within the door sensor's 4 m.
TEST(OfficeFile, EveryDoorOntoTheHallwayHasALookoutBesideItsDoorway) {
  const CourierOfficeResult r = load_courier_office(kOffice);
  ASSERT_TRUE(r.ok()) << r.error;
  const CourierOffice& o = *r.office;
  ASSERT_EQ(o.floor.door_lookouts.size(), o.map.doors.size());
  for (const auto& door : o.map.doors) {
    const auto it = o.floor.door_lookouts.find(door.id);
    ASSERT_NE(it, o.floor.door_lookouts.end()) << door.id;
    const auto& spot = it->second;
    EXPECT_GT(spot.y, 7.1 + 0.3) << door.id;  // inside the hallway, a robot's radius off each wall
    EXPECT_LT(spot.y, 8.9 - 0.3) << door.id;
    const double dx = spot.x - door.centre.x(), dy = spot.y - door.centre.y();
    EXPECT_GT(std::abs(dx), door.width_m / 2) << door.id << ": in front of the doorway";
    EXPECT_LT(std::hypot(dx, dy), 4.0) << door.id;
  }
}

TEST(OfficeFile, ErrorsNameTheFileAndAnOfficeIsRequired) {
  const std::string bad = "/tmp/courier_office_test_" + std::to_string(getpid()) + ".pbtxt";
  std::ofstream(bad) << "name: \"x\"\nworld { width: 10 height: 5 }\nbogus: 3\n";
  const CourierOfficeResult r = load_courier_office(bad);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.error.find(bad + ":3"), std::string::npos) << r.error;
  std::ofstream(bad) << "name: \"x\"\nworld { width: 10 height: 5 }\n";
  const CourierOfficeResult no_office = load_courier_office(bad);
  EXPECT_FALSE(no_office.ok());
  EXPECT_NE(no_office.error.find("has no office"), std::string::npos) << no_office.error;
}

}  // namespace
}  // namespace autonomy::courier
