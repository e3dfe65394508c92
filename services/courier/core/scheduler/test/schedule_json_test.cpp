// Problems from JSON (paths in errors, times of day, a map with places) and schedules to JSON.
#include "services/courier/core/scheduler/schedule_json.hpp"
#include "services/courier/core/scheduler/scheduler_engine.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace autonomy::courier::scheduling {
namespace {

using nlohmann::json;

json paper_problem() {
  return json::parse(R"({
    "now": "10:00",
    "locations": [
      {"name": "hall"},
      {"name": "A-111 table", "room": "A-111", "station_handover_s": 10},
      {"name": "A-120 desk", "room": "A-120"}
    ],
    "travel_s": [[0, 10, 25], [10, 0, 20], [25, 20, 0]],
    "people": [{"name": "Michael", "handover_s": 20, "presence": [["08:00", "12:00"]]}],
    "couriers": [{"id": "rhino", "capacity": 2, "location": "hall"}],
    "jobs": [
      {"id": "red letter", "object": {"kind": "letter", "colour": "red"},
       "pickup": {"location": "A-111 table"},
       "delivery": {"location": "A-120 desk", "person": "Michael"}, "deadline": "10:30"}
    ]
  })");
}

std::string error_of(const json& doc) {
  return problem_from_json(doc, "").error;
}

TEST(ProblemJson, ReadsNamesAndTimes) {
  const ParsedProblem parsed = problem_from_json(paper_problem(), "");
  ASSERT_TRUE(parsed.ok()) << parsed.error;
  const SchedulingProblem& p = parsed.problem;
  EXPECT_DOUBLE_EQ(p.now_s, 36000.0);
  EXPECT_EQ(p.jobs[0].delivery.person, 0);
  EXPECT_EQ(p.jobs[0].delivery.location, 2);
  ASSERT_TRUE(p.jobs[0].deadline_s.has_value());
  EXPECT_DOUBLE_EQ(*p.jobs[0].deadline_s, 37800.0);
  EXPECT_DOUBLE_EQ(p.people[0].presence[0].end_s, 43200.0);
  EXPECT_DOUBLE_EQ(p.couriers[0].available_s, 36000.0);
}

TEST(ProblemJson, ErrorsNameThePath) {
  json doc = paper_problem();
  doc["jobs"][0]["delivery"]["location"] = "A-112 desk";
  EXPECT_EQ(error_of(doc), "/jobs/0/delivery/location: no location 'A-112 desk'");
  doc = paper_problem();
  doc["jobs"][0]["deadline"] = "10:75";
  EXPECT_NE(error_of(doc).find("/jobs/0/deadline: '10:75' is not a time of day"),
            std::string::npos);
  doc = paper_problem();
  doc["couriers"][0]["capacity"] = 0;
  EXPECT_NE(error_of(doc).find("/couriers/0/capacity"), std::string::npos);
  doc = paper_problem();
  doc["travel_s"][1] = json::array({10, 0});
  EXPECT_NE(error_of(doc).find("/travel_s/1: expected 3 entries"), std::string::npos);
  doc = paper_problem();
  doc["travel_s"][2][2] = 4;
  EXPECT_NE(error_of(doc).find("/travel_s/2/2: the diagonal must be 0"), std::string::npos);
  doc = paper_problem();
  doc["jobs"][0]["colour"] = "red";
  EXPECT_EQ(error_of(doc), "/jobs/0/colour: unknown field");
  doc = paper_problem();
  doc.erase("travel_s");
  EXPECT_NE(error_of(doc).find("exactly one of"), std::string::npos);
  doc = paper_problem();
  doc["jobs"][0]["aboard"] = "nobody";
  EXPECT_EQ(error_of(doc), "/jobs/0/aboard: no courier 'nobody'");
  doc = paper_problem();
  doc["people"][0]["presence"] = json::parse(R"([["11:00", "12:00"], ["09:00", "10:00"]])");
  EXPECT_NE(error_of(doc).find("/people/0/presence/1"), std::string::npos);
  doc = paper_problem();
  doc["couriers"][0]["forced_prefix"] = json::parse(R"([{"job": "red letter", "stop": "drop"}])");
  EXPECT_NE(error_of(doc).find("/couriers/0/forced_prefix/0/stop"), std::string::npos);
}

TEST(ProblemJson, UnparsableTextGivesLineAndColumn) {
  const ParsedProblem p =
      problem_from_json_text("{\n  \"now\": 10,\n  \"jobs\": [,]\n}", "p.json", "");
  EXPECT_EQ(p.error.rfind("p.json:3:12:", 0), 0u) << p.error;
}

TEST(ProblemJson, NoRouteIsNullInTheMatrix) {
  json doc = paper_problem();
  doc["travel_s"][0][2] = nullptr;
  doc["travel_s"][1][2] = "inf";
  const ParsedProblem parsed = problem_from_json(doc, "");
  ASSERT_TRUE(parsed.ok()) << parsed.error;
  EXPECT_EQ(parsed.problem.travel.at(1, 2), kNoRoute);
}

TEST(ProblemJson, TravelFromAMapWithAClosedDoor) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("courier_json_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  {
    // 20 x 10 image, a wall at column 10 with a door at image row 4 (raster row 5).
    std::ofstream pgm(dir / "office.pgm", std::ios::binary);
    pgm << "P5\n20 10\n255\n";
    for (int y = 0; y < 10; ++y)
      for (int x = 0; x < 20; ++x) pgm.put(static_cast<char>(x == 10 && y != 4 ? 0 : 254));
    std::ofstream yaml(dir / "office.yaml");
    yaml << "image: office.pgm\nresolution: 1.0\norigin: [0.0, 0.0, 0.0]\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\n";
  }
  json doc = paper_problem();
  doc.erase("travel_s");
  doc["locations"][0]["x"] = 2.5, doc["locations"][0]["y"] = 5.5;
  doc["locations"][1]["x"] = 6.5, doc["locations"][1]["y"] = 5.5;
  doc["locations"][2]["x"] = 17.5, doc["locations"][2]["y"] = 5.5;
  doc["map"] = {{"yaml", "office.yaml"}, {"speed_mps", 0.5}};
  ParsedProblem parsed = problem_from_json(doc, dir.string());
  ASSERT_TRUE(parsed.ok()) << parsed.error;
  EXPECT_NEAR(parsed.problem.travel.at(0, 2), 30.0, 1e-4);  // 15 cells at 0.5 m/s
  doc["map"]["closed"] = json::parse("[[10.0, 5.0, 11.0, 6.0]]");
  parsed = problem_from_json(doc, dir.string());
  ASSERT_TRUE(parsed.ok()) << parsed.error;
  EXPECT_EQ(parsed.problem.travel.at(0, 2), kNoRoute);
  EXPECT_NEAR(parsed.problem.travel.at(0, 1), 8.0, 1e-4);
  doc["map"]["yaml"] = "missing.yaml";
  EXPECT_NE(problem_from_json(doc, dir.string()).error.find("/map/yaml"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(ScheduleJson, CarriesObjectiveStopsAndAssumptions) {
  const ParsedProblem parsed = problem_from_json(paper_problem(), "");
  ASSERT_TRUE(parsed.ok());
  const JobSchedule s = make_scheduler_engine("exact")->solve(parsed.problem, {});
  ASSERT_TRUE(s.ok()) << s.reason;
  const json out = schedule_to_json(parsed.problem, s);
  EXPECT_EQ(out["status"], "ok");
  EXPECT_EQ(out["proved_optimal"], true);
  EXPECT_EQ(out["routes"][0]["courier"], "rhino");
  EXPECT_EQ(out["routes"][0]["stops"][1]["person"], "Michael");
  // hall -> A-111 10 s, 10 s load, -> A-120 20 s, 20 s handover: 10:01:00.
  EXPECT_EQ(out["jobs"][0]["completion"], "10:01:00");
  EXPECT_EQ(out["objective"]["completion_s"], 60.0);
  EXPECT_EQ(out["assumptions"][1]["room"], "A-120");
  EXPECT_EQ(out["assumptions"][1]["open_at"], "10:00:40");
}

TEST(TimeOfDay, ParseAndFormat) {
  EXPECT_EQ(parse_time_of_day("10:30"), 37800.0);
  EXPECT_EQ(parse_time_of_day("09:05:07"), 9 * 3600.0 + 5 * 60 + 7);
  EXPECT_FALSE(parse_time_of_day("25:00"));
  EXPECT_FALSE(parse_time_of_day("10:3x"));
  EXPECT_FALSE(parse_time_of_day(""));
  EXPECT_EQ(format_time_of_day(37800.4), "10:30:00");
  EXPECT_EQ(format_time_of_day(86400.0 + 60), "00:01:00+1d");
}

}  // namespace
}  // namespace autonomy::courier::scheduling
