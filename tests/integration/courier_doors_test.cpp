// The door policy for any room of the paper's example (courier-scheduling-faxbot, section 2):
// each door that one of the two jobs needs (A-111 and A-110 for the pickups, A-120 and A-114 for
// the deliveries) is closed in turn from the start, for a short time (2 min) and a long one
// (10 min, longer than a closed sighting stays fresh), in lockstep over the real processes.
// Each time the job behind the door waits for it as an opportunistic job (its object aboard if
// it was loaded), the other job goes on, and both complete once the door reopens; the courier's
// own account says so in order: the door seen closed, the job failed over, the door seen open
// (or assumed open again), the job taken up, its object loaded or delivered after the reopening.
//
// One DDS domain per test; this file uses 220-227.
#include "tests/integration/courier_fixture.hpp"

#include <gtest/gtest.h>

namespace autonomy::test {
namespace {

struct DoorCase {
  std::string door;
  double closed_for_s;
  int domain;
  std::string job;     // the job that needs the door
  std::string object;  // its object
  std::string place;   // behind the door: its pickup or its delivery
  bool pickup;
};

std::string case_name(const ::testing::TestParamInfo<DoorCase>& info) {
  std::string door = info.param.door;
  door.erase(std::remove(door.begin(), door.end(), '-'), door.end());
  return door + (info.param.closed_for_s < 300 ? "ClosedTwoMinutes" : "ClosedTenMinutes");
}

// The shipped office floor with `door` closed from t = 1 s to t = 1 s + closed_for_s (and A-120's
// Fig. 5 script removed).
std::string office_with_closed_door(const std::string& door, double closed_for_s) {
  std::string text = office_scenario("");
  const std::string id = "id: \"" + door + "\"";
  const auto at = text.find(id);
  EXPECT_NE(at, std::string::npos) << door;
  const auto end = text.find("\n}", at);
  char script[160];
  std::snprintf(script, sizeof script,
                "\n  script {\n    events { time_s: 1 angle: 0.0 }\n    events { time_s: %.0f angle: 1.5707963 }\n  }",
                1.0 + closed_for_s);
  text.insert(end, script);
  return text;
}

class CourierDoorTest : public CourierTest, public ::testing::WithParamInterface<DoorCase> {};

TEST_P(CourierDoorTest, TheJobBehindTheDoorWaitsForItAndBothJobsComplete) {
  const DoorCase& c = GetParam();
  setup_observers(c.domain);
  start_world(office_with_closed_door(c.door, c.closed_for_s));
  send_paper_commands();
  ASSERT_TRUE(both_jobs_finished("both jobs finished"));
  EXPECT_TRUE(job_in("job-1", msg::JobState::Completed)) << job_story("job-1");
  EXPECT_TRUE(job_in("job-2", msg::JobState::Completed)) << job_story("job-2");
  const auto waited = job_in(c.job, msg::JobState::Opportunistic);
  ASSERT_TRUE(waited) << job_story(c.job);
  EXPECT_NE(waited->reason.find(c.door + " closed at"), std::string::npos) << waited->reason;

  // In the world: the object reached its place behind the door only after the door reopened.
  constexpr double kStepS = 0.1;  // office.pbtxt
  const auto reopened_tick = static_cast<int64_t>((1.0 + c.closed_for_s) / kStepS);
  const auto reached = c.pickup ? object_tick(c.object, "rhino", "") : object_tick(c.object, "", c.place);
  ASSERT_TRUE(reached) << job_story(c.job);
  EXPECT_GE(*reached, reopened_tick);
  EXPECT_LT(waited->tick, reopened_tick);
  // Nothing went back: neither object lay at its pickup again once loaded.
  for (const auto& [object, pickup] : {std::pair<std::string, std::string>{"letter-red", "meeting-table"},
                                       std::pair<std::string, std::string>{"book-green", "librarian-desk"}}) {
    const auto loaded = object_tick(object, "rhino", "");
    ASSERT_TRUE(loaded) << object;
    EXPECT_FALSE(object_tick(object, "", pickup, *loaded)) << object << " went back";
  }

  // The courier's account, in order.
  const std::vector<std::pair<std::string, std::string>> expected = {
      {"door_closed", c.door},
      {"failed_over", c.job},
      {"door_opened", c.door},
      {"opportunity_taken", c.job},
      {c.pickup ? "loaded" : "unloaded", c.object},
      {"finished", c.job}};
  size_t next = 0;
  std::string told;
  for (const auto& [kind, line] : events()) {
    const std::string text = line.at("text");
    told += kind + ": " + text + "\n";
    if (next < expected.size() && kind == expected[next].first && text.find(expected[next].second) != std::string::npos)
      ++next;
  }
  EXPECT_EQ(next, expected.size()) << "the steps, in order, not all found in:\n" << told;
}

INSTANTIATE_TEST_SUITE_P(
    PapersDoors, CourierDoorTest,
    ::testing::Values(DoorCase{"A-111", 120, 220, "job-1", "letter-red", "meeting-table", true},
                      DoorCase{"A-111", 600, 221, "job-1", "letter-red", "meeting-table", true},
                      DoorCase{"A-120", 120, 222, "job-1", "letter-red", "michael-desk", false},
                      DoorCase{"A-120", 600, 223, "job-1", "letter-red", "michael-desk", false},
                      DoorCase{"A-110", 120, 224, "job-2", "book-green", "librarian-desk", true},
                      DoorCase{"A-110", 600, 225, "job-2", "book-green", "librarian-desk", true},
                      DoorCase{"A-114", 120, 226, "job-2", "book-green", "a114-desk", false},
                      DoorCase{"A-114", 600, 227, "job-2", "book-green", "a114-desk", false}),
    case_name);

}  // namespace
}  // namespace autonomy::test
