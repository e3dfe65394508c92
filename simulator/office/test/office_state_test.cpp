#include "simulator/office/office_state.hpp"
#include "simulator/office/test/office_fixture.hpp"

#include <gtest/gtest.h>

#include <random>

namespace autonomy::sim::office {
namespace {

using test::at_clock;
using test::small_office;
using Positions = std::map<std::string, geometry::Vec2>;

HandoverRequest ask(const std::string& robot, geometry::Vec2 where, const std::string& place,
                    const std::string& object, double now_s, int capacity = 1) {
  HandoverRequest r;
  r.robot_id = robot;
  r.robot_position = where;
  r.place = place;
  r.object_id = object;
  r.now_s = now_s;
  r.capacity = capacity;
  return r;
}

class OfficeStateTest : public ::testing::Test {
 protected:
  OfficeState office{small_office()};
  std::mt19937_64 rng{1};
  const geometry::Vec2 anna_desk{2.0, 2.0};
  const geometry::Vec2 bob_desk{8.0, 8.0};
  const geometry::Vec2 mailroom{10.0, 1.0};

  // Loads `object` at `place` for `robot` and runs the handover to completion.
  void load_now(const std::string& robot, geometry::Vec2 where, const std::string& place,
                const std::string& object, double now_s, int capacity = 1) {
    const auto t = office.request_load(ask(robot, where, place, object, now_s, capacity), rng);
    ASSERT_TRUE(t.accepted) << t.detail;
    const auto done = office.advance(t.completes_at_s, {{robot, where}});
    ASSERT_EQ(done.size(), 1u);
    ASSERT_TRUE(done[0].succeeded) << done[0].detail;
  }
};

TEST_F(OfficeStateTest, LoadWithThePersonPresentTakesTheirTimeThenTheRobotCarriesIt) {
  const double t0 = at_clock(9, 15);
  const auto ticket = office.request_load(ask("r1", {2.3, 2.4}, "anna-desk", "letter-1", t0), rng);
  ASSERT_TRUE(ticket.accepted) << ticket.detail;
  EXPECT_EQ(ticket.helper, "Anna");
  EXPECT_DOUBLE_EQ(ticket.completes_at_s, t0 + 20.0);
  EXPECT_EQ(ticket.detail, "load of letter-1 at anna-desk by Anna, 20.0 s");
  EXPECT_EQ(office.pending_count(), 1u);

  // Not instant: nothing changes until the handover completes.
  EXPECT_TRUE(office.advance(t0 + 19.9, {{"r1", {2.3, 2.4}}}).empty());
  EXPECT_TRUE(office.object("letter-1")->location.is_at("anna-desk"));
  EXPECT_TRUE(office.carried_by("r1").empty());

  const auto done = office.advance(t0 + 20.05, {{"r1", {2.3, 2.4}}});
  ASSERT_EQ(done.size(), 1u);
  EXPECT_TRUE(done[0].succeeded);
  EXPECT_EQ(done[0].handover_id, ticket.handover_id);
  EXPECT_EQ(done[0].kind, HandoverKind::load);
  EXPECT_EQ(done[0].helper, "Anna");
  EXPECT_DOUBLE_EQ(done[0].requested_at_s, t0);
  EXPECT_DOUBLE_EQ(done[0].finished_at_s, t0 + 20.0);  // the completion time, not the call's
  EXPECT_TRUE(office.object("letter-1")->location.is_carried_by("r1"));
  EXPECT_EQ(office.carried_by("r1"), std::vector<std::string>{"letter-1"});
  EXPECT_EQ(office.pending_count(), 0u);
}

TEST_F(OfficeStateTest, UnloadPutsTheObjectAtThePlace) {
  load_now("r1", anna_desk, "anna-desk", "letter-1", at_clock(9, 50));
  const double t = at_clock(10, 5);
  const auto ticket = office.request_unload(ask("r1", bob_desk, "bob-desk", "letter-1", t), rng);
  ASSERT_TRUE(ticket.accepted) << ticket.detail;
  EXPECT_EQ(ticket.helper, "Bob");
  EXPECT_GE(ticket.completes_at_s, t + 5.0);  // Bob takes uniform 5..15 s
  EXPECT_LT(ticket.completes_at_s, t + 15.0);
  const auto done = office.advance(t + 15.0, {{"r1", bob_desk}});
  ASSERT_EQ(done.size(), 1u);
  EXPECT_TRUE(done[0].succeeded);
  EXPECT_EQ(done[0].kind, HandoverKind::unload);
  EXPECT_TRUE(office.object("letter-1")->location.is_at("bob-desk"));
  EXPECT_TRUE(office.carried_by("r1").empty());
}

TEST_F(OfficeStateTest, ALoadingStationNeedsNobodyAndWorksAtNight) {
  const double night = at_clock(23, 0);
  const auto ticket = office.request_load(ask("r1", {10.5, 1.5}, "mailroom", "book-1", night), rng);
  ASSERT_TRUE(ticket.accepted) << ticket.detail;
  EXPECT_EQ(ticket.helper, "station");
  EXPECT_DOUBLE_EQ(ticket.completes_at_s, night + 5.0);
}

TEST_F(OfficeStateTest, RejectsUnknownPlaceAndObject) {
  auto t = office.request_load(ask("r1", anna_desk, "attic", "letter-1", at_clock(10)), rng);
  EXPECT_FALSE(t.accepted);
  EXPECT_EQ(t.reason, HandoverRejection::unknown_place);
  EXPECT_EQ(t.detail, "unknown place attic");
  t = office.request_unload(ask("r1", anna_desk, "anna-desk", "letter-9", at_clock(10)), rng);
  EXPECT_EQ(t.reason, HandoverRejection::unknown_object);
  EXPECT_EQ(t.detail, "unknown object letter-9");
}

TEST_F(OfficeStateTest, RejectsARobotThatIsNotAtThePlace) {
  auto t = office.request_load(ask("r1", {4.0, 2.0}, "anna-desk", "letter-1", at_clock(10)), rng);
  EXPECT_FALSE(t.accepted);
  EXPECT_EQ(t.reason, HandoverRejection::robot_not_at_place);
  EXPECT_EQ(t.detail, "robot r1 is 2.0 m from anna-desk (must be within 0.8 m)");
  // The radius itself is still at the place.
  t = office.request_load(ask("r1", {2.8, 2.0}, "anna-desk", "letter-1", at_clock(10)), rng);
  EXPECT_TRUE(t.accepted) << t.detail;
}

TEST_F(OfficeStateTest, RejectsWhenNobodyIsThereAndSaysWhenSomebodyIsBack) {
  auto t = office.request_load(ask("r1", anna_desk, "anna-desk", "letter-1", at_clock(12, 10)), rng);
  EXPECT_FALSE(t.accepted);
  EXPECT_EQ(t.reason, HandoverRejection::nobody_present);
  EXPECT_EQ(t.detail, "nobody at anna-desk at 12:10 (somebody is back at 13:00)");

  t = office.request_load(ask("r1", anna_desk, "anna-desk", "letter-1", 0.0), rng);  // 08:30
  EXPECT_EQ(t.detail, "nobody at anna-desk at 08:30 (somebody is back at 09:00)");

  t = office.request_load(ask("r1", anna_desk, "anna-desk", "letter-1", at_clock(18)), rng);
  EXPECT_EQ(t.detail, "nobody at anna-desk at 18:00 (nobody is back before tomorrow 09:00)");

  t = office.request_load(ask("r1", {6, 2}, "meeting-table", "envelope-1", at_clock(10)), rng);
  EXPECT_EQ(t.reason, HandoverRejection::nobody_present);
  EXPECT_EQ(t.detail, "nobody at meeting-table at 10:00 (nobody works there)");
}

TEST_F(OfficeStateTest, PresenceIntervalsAreHalfOpen) {
  EXPECT_EQ(office.people_present("anna-desk", at_clock(9, 0)), std::vector<std::string>{"Anna"});
  EXPECT_EQ(office.people_present("anna-desk", at_clock(12, 0) - 0.001), std::vector<std::string>{"Anna"});
  EXPECT_TRUE(office.people_present("anna-desk", at_clock(12, 0)).empty());
  EXPECT_TRUE(office.people_present("anna-desk", at_clock(9, 0) - 0.001).empty());
  // The next day, presence repeats: 09:30 tomorrow.
  EXPECT_EQ(office.people_present("anna-desk", at_clock(9, 30) + 86400.0), std::vector<std::string>{"Anna"});
}

TEST_F(OfficeStateTest, RejectsLoadingAnObjectThatIsNotThere) {
  auto t = office.request_load(ask("r1", anna_desk, "anna-desk", "book-1", at_clock(10)), rng);
  EXPECT_EQ(t.reason, HandoverRejection::object_not_at_place);
  EXPECT_EQ(t.detail, "object book-1 is not at anna-desk (it is at mailroom)");

  load_now("r2", anna_desk, "anna-desk", "letter-1", at_clock(10));
  t = office.request_load(ask("r1", anna_desk, "anna-desk", "letter-1", at_clock(10, 5)), rng);
  EXPECT_EQ(t.reason, HandoverRejection::object_not_at_place);
  EXPECT_EQ(t.detail, "object letter-1 is not at anna-desk (it is carried by r2)");
}

TEST_F(OfficeStateTest, RejectsLoadingARobotThatIsFull) {
  load_now("r1", mailroom, "mailroom", "book-1", at_clock(10));
  auto t = office.request_load(ask("r1", mailroom, "mailroom", "letter-2", at_clock(10, 1)), rng);
  EXPECT_EQ(t.reason, HandoverRejection::robot_full);
  EXPECT_EQ(t.detail, "robot r1 carries 1 objects, its capacity is 1");
  // A robot with room for two takes the second.
  t = office.request_load(ask("r1", mailroom, "mailroom", "letter-2", at_clock(10, 1), 2), rng);
  EXPECT_TRUE(t.accepted) << t.detail;
}

TEST_F(OfficeStateTest, RejectsUnloadingWhatTheRobotDoesNotCarry) {
  auto t = office.request_unload(ask("r1", anna_desk, "anna-desk", "letter-1", at_clock(10)), rng);
  EXPECT_EQ(t.reason, HandoverRejection::object_not_carried_by_robot);
  EXPECT_EQ(t.detail, "robot r1 does not carry object letter-1 (it is at anna-desk)");
  load_now("r2", mailroom, "mailroom", "book-1", at_clock(10));
  t = office.request_unload(ask("r1", mailroom, "mailroom", "book-1", at_clock(10, 1)), rng);
  EXPECT_EQ(t.reason, HandoverRejection::object_not_carried_by_robot);
  EXPECT_EQ(t.detail, "robot r1 does not carry object book-1 (it is carried by r2)");
}

TEST_F(OfficeStateTest, OneHandoverPerRobotObjectAndHelperAtATime) {
  const double t = at_clock(10);
  ASSERT_TRUE(office.request_load(ask("r1", mailroom, "mailroom", "book-1", t, 3), rng).accepted);

  auto again = office.request_load(ask("r1", mailroom, "mailroom", "letter-2", t + 1, 3), rng);
  EXPECT_EQ(again.reason, HandoverRejection::robot_busy);
  EXPECT_EQ(again.detail, "robot r1 is already in a handover (load of book-1 at mailroom)");

  auto same_object = office.request_load(ask("r2", mailroom, "mailroom", "book-1", t + 1), rng);
  EXPECT_EQ(same_object.reason, HandoverRejection::object_in_handover);
  EXPECT_EQ(same_object.detail, "object book-1 is being handed over to robot r1");

  auto station_busy = office.request_load(ask("r2", mailroom, "mailroom", "letter-2", t + 1), rng);
  EXPECT_EQ(station_busy.reason, HandoverRejection::helper_busy);
  EXPECT_EQ(station_busy.detail, "everyone at mailroom is handing over to another robot");

  // Once the station is done, r2 is served.
  ASSERT_EQ(office.advance(t + 5, {{"r1", mailroom}, {"r2", mailroom}}).size(), 1u);
  EXPECT_TRUE(office.request_load(ask("r2", mailroom, "mailroom", "letter-2", t + 6), rng).accepted);
}

TEST(OfficeStateHelpers, ASecondPersonAtTheDeskServesWhileTheFirstIsBusy) {
  OfficeSpec s = small_office();
  s.people.push_back({"Carl", "anna-desk", {{9 * 3600.0, 17 * 3600.0}}, HandoverTimeModel::fixed(40.0)});
  s.objects.push_back({"letter-3", "letter", "blue", ObjectLocation::at_place("anna-desk")});
  OfficeState office(s);
  std::mt19937_64 rng(1);
  const double t = at_clock(12, 30);  // Anna is at lunch, Carl is in
  auto first = office.request_load(ask("r1", {2, 2}, "anna-desk", "letter-1", at_clock(10)), rng);
  EXPECT_EQ(first.helper, "Anna");  // declaration order
  auto second = office.request_load(ask("r2", {2, 2}, "anna-desk", "letter-3", at_clock(10)), rng);
  EXPECT_EQ(second.helper, "Carl");
  EXPECT_DOUBLE_EQ(second.completes_at_s, at_clock(10) + 40.0);
  (void)office.advance(at_clock(11), {{"r1", {2, 2}}, {"r2", {2, 2}}});
  EXPECT_EQ(office.people_present("anna-desk", t), std::vector<std::string>{"Carl"});
}

TEST_F(OfficeStateTest, ARobotThatLeavesBeforeCompletionFailsAndNothingChanges) {
  const double t0 = at_clock(9, 30);
  const auto ticket = office.request_load(ask("r1", anna_desk, "anna-desk", "letter-1", t0), rng);
  ASSERT_TRUE(ticket.accepted);
  EXPECT_TRUE(office.advance(t0 + 5, {{"r1", {2.5, 2.0}}}).empty());  // still within 0.8 m
  const auto done = office.advance(t0 + 6, {{"r1", {3.0, 2.0}}});
  ASSERT_EQ(done.size(), 1u);
  EXPECT_FALSE(done[0].succeeded);
  EXPECT_EQ(done[0].failure, HandoverFailure::robot_moved_away);
  EXPECT_DOUBLE_EQ(done[0].finished_at_s, t0 + 6);
  EXPECT_EQ(done[0].detail,
            "robot r1 moved away from anna-desk (1.0 m) before the load of letter-1 completed");
  EXPECT_TRUE(office.object("letter-1")->location.is_at("anna-desk"));
  EXPECT_EQ(office.pending_count(), 0u);
  // Anna is free again.
  EXPECT_TRUE(office.request_load(ask("r1", anna_desk, "anna-desk", "letter-1", t0 + 7), rng).accepted);
}

TEST_F(OfficeStateTest, ARobotRemovedFromTheWorldFails) {
  const double t0 = at_clock(9, 30);
  ASSERT_TRUE(office.request_load(ask("r1", anna_desk, "anna-desk", "letter-1", t0), rng).accepted);
  const auto done = office.advance(t0 + 1, {});
  ASSERT_EQ(done.size(), 1u);
  EXPECT_EQ(done[0].failure, HandoverFailure::robot_gone);
  EXPECT_EQ(done[0].detail, "robot r1 left the world");
}

TEST_F(OfficeStateTest, CompletionsComeInTimeOrderThenFailures) {
  const double t0 = at_clock(10, 10);
  const auto anna = office.request_load(ask("r1", anna_desk, "anna-desk", "letter-1", t0), rng);       // +20 s
  const auto station = office.request_load(ask("r2", mailroom, "mailroom", "book-1", t0 + 2), rng);     // +5 s
  const auto wrong_place = office.request_load(ask("r3", anna_desk, "anna-desk", "envelope-1", t0), rng);  // not there
  EXPECT_FALSE(wrong_place.accepted);
  ASSERT_TRUE(anna.accepted && station.accepted);
  // r3 is away too, but has nothing pending; the call is 30 s later and covers both completions.
  const auto done = office.advance(t0 + 30, {{"r1", anna_desk}, {"r2", mailroom}});
  ASSERT_EQ(done.size(), 2u);
  EXPECT_EQ(done[0].handover_id, station.handover_id);  // completed at t0 + 7
  EXPECT_DOUBLE_EQ(done[0].finished_at_s, t0 + 7);
  EXPECT_EQ(done[1].handover_id, anna.handover_id);     // completed at t0 + 20
  EXPECT_DOUBLE_EQ(done[1].finished_at_s, t0 + 20);
}

TEST_F(OfficeStateTest, AHandoverDueAtTheCallIsCompletedEvenIfTheRobotLeavesThen) {
  const double t0 = at_clock(10);
  const auto t = office.request_load(ask("r1", mailroom, "mailroom", "book-1", t0), rng);
  const auto done = office.advance(t.completes_at_s, {{"r1", {0, 0}}});
  ASSERT_EQ(done.size(), 1u);
  EXPECT_TRUE(done[0].succeeded);
}

TEST(OfficeStateTiming, TheSameSeedGivesTheSameHandoverTimes) {
  auto run = [](uint64_t seed) {
    OfficeState office(small_office());
    std::mt19937_64 rng(seed);
    return office.request_load(ask("r1", {8, 8}, "bob-desk", "letter-1", at_clock(10, 30)), rng);
  };
  // letter-1 is not at bob-desk: rejected before drawing, so the generator is untouched.
  OfficeSpec s = small_office();
  s.objects[0].location = ObjectLocation::at_place("bob-desk");
  auto timed = [&](uint64_t seed) {
    OfficeState office(s);
    std::mt19937_64 rng(seed);
    return office.request_load(ask("r1", {8, 8}, "bob-desk", "letter-1", at_clock(10, 30)), rng).completes_at_s;
  };
  EXPECT_FALSE(run(5).accepted);
  EXPECT_EQ(timed(5), timed(5));
  EXPECT_NE(timed(5), timed(6));
  // Bob: uniform 5..15 s with the generator's first two outputs.
  std::mt19937_64 rng(5);
  const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53;
  EXPECT_DOUBLE_EQ(timed(5), at_clock(10, 30) + 5.0 + 10.0 * u);
}

}  // namespace
}  // namespace autonomy::sim::office
