// The handover desk: request checks at the network's edge, answers by request id (repeats get the
// same answer and start nothing), completions and failures mapped back to their requests, and the
// objects that moved.
#include "simulator/office/handover_desk.hpp"
#include "simulator/office/test/office_fixture.hpp"

#include <gtest/gtest.h>

namespace autonomy::sim::office {
namespace {

using test::at_clock;
using test::small_office;

DeskRequest desk_ask(const std::string& id, const std::string& robot, HandoverKind kind, const std::string& place,
                const std::string& object) {
  return {id, robot, kind, place, object};
}

const geometry::Vec2 kAnnaDesk{2.0, 2.0};
const geometry::Vec2 kBobDesk{8.0, 8.0};

class HandoverDeskTest : public ::testing::Test {
 protected:
  HandoverDesk desk{small_office(), 42};
};

TEST_F(HandoverDeskTest, LoadIsAcceptedThenCompletedAtItsPlannedTimeAndTheObjectMoves) {
  const double t0 = at_clock(9, 15);
  const DeskAnswer accepted =
      desk.request(desk_ask("q1", "r1", HandoverKind::load, "anna-desk", "letter-1"), RobotAtDesk{kAnnaDesk, 1}, t0);
  EXPECT_EQ(accepted.state, DeskAnswerState::accepted);
  EXPECT_EQ(accepted.request_id, "q1");
  EXPECT_EQ(accepted.helper, "Anna");
  EXPECT_EQ(accepted.reason, "");
  EXPECT_DOUBLE_EQ(accepted.time_s, t0);
  EXPECT_DOUBLE_EQ(accepted.completes_at_s, t0 + 20.0);

  // First call: every object, in declaration order.
  const auto initial = desk.changed_objects();
  ASSERT_EQ(initial.size(), 4u);
  EXPECT_EQ(initial[0].id, "letter-1");
  EXPECT_TRUE(desk.changed_objects().empty());

  EXPECT_TRUE(desk.advance(t0 + 10.0, {{"r1", kAnnaDesk}}).empty());
  const auto done = desk.advance(t0 + 20.0, {{"r1", kAnnaDesk}});
  ASSERT_EQ(done.size(), 1u);
  EXPECT_EQ(done[0].state, DeskAnswerState::completed);
  EXPECT_EQ(done[0].request_id, "q1");
  EXPECT_EQ(done[0].object_id, "letter-1");
  EXPECT_EQ(done[0].helper, "Anna");
  EXPECT_DOUBLE_EQ(done[0].time_s, t0 + 20.0);
  EXPECT_EQ(done[0].detail, "load of letter-1 at anna-desk completed");

  const auto moved = desk.changed_objects();
  ASSERT_EQ(moved.size(), 1u);
  EXPECT_EQ(moved[0].id, "letter-1");
  EXPECT_TRUE(moved[0].location.is_carried_by("r1"));
}

TEST_F(HandoverDeskTest, ARepeatedRequestGetsTheLatestAnswerAndStartsNothing) {
  const double t0 = at_clock(9, 15);
  const auto req = desk_ask("q1", "r1", HandoverKind::load, "anna-desk", "letter-1");
  ASSERT_EQ(desk.request(req, RobotAtDesk{kAnnaDesk, 1}, t0).state, DeskAnswerState::accepted);
  const DeskAnswer again = desk.request(req, RobotAtDesk{kAnnaDesk, 1}, t0 + 1.0);
  EXPECT_EQ(again.state, DeskAnswerState::accepted);
  EXPECT_DOUBLE_EQ(again.time_s, t0);
  EXPECT_EQ(desk.office().pending_count(), 1u);
  ASSERT_EQ(desk.advance(t0 + 20.0, {{"r1", kAnnaDesk}}).size(), 1u);
  EXPECT_EQ(desk.request(req, RobotAtDesk{kAnnaDesk, 1}, t0 + 21.0).state, DeskAnswerState::completed);
  EXPECT_EQ(desk.office().pending_count(), 0u);
}

TEST_F(HandoverDeskTest, MalformedAndUnknownRobotRequestsAreRejectedWithReasons) {
  const double t0 = at_clock(9, 15);
  const RobotAtDesk at_anna{kAnnaDesk, 1};
  const auto reject = [&](const DeskRequest& r, const std::optional<RobotAtDesk>& robot) {
    const DeskAnswer a = desk.request(r, robot, t0);
    EXPECT_EQ(a.state, DeskAnswerState::rejected) << a.detail;
    return a.reason + ": " + a.detail;
  };
  EXPECT_EQ(reject(desk_ask("", "r1", HandoverKind::load, "anna-desk", "letter-1"), at_anna),
            "invalid_request: request_id is empty");
  EXPECT_EQ(reject(desk_ask(std::string(129, 'q'), "r1", HandoverKind::load, "anna-desk", "letter-1"), at_anna),
            "invalid_request: request_id has 129 bytes, more than 128");
  EXPECT_EQ(desk.request(desk_ask(std::string(100000, 'q'), "r1", HandoverKind::load, "anna-desk", "letter-1"), at_anna, t0)
                .request_id,
            std::string(128, 'q'));  // echoed cut to the limit
  EXPECT_EQ(reject(desk_ask("q0", "r1", HandoverKind::load, std::string(65, 'p'), "letter-1"), at_anna),
            "invalid_request: place has 65 bytes, more than 64");
  EXPECT_EQ(reject(desk_ask("q1", "r 1", HandoverKind::load, "anna-desk", "letter-1"), at_anna),
            "invalid_request: robot id 'r 1' has characters outside [A-Za-z0-9_.-]");
  EXPECT_EQ(reject(desk_ask("q2", "r1", static_cast<HandoverKind>(7), "anna-desk", "letter-1"), at_anna),
            "invalid_request: kind is neither load nor unload");
  EXPECT_EQ(reject(desk_ask("q3", "r1", HandoverKind::load, "", "letter-1"), at_anna), "invalid_request: place is empty");
  EXPECT_EQ(reject(desk_ask("q4", "r1", HandoverKind::load, "anna-desk", ""), at_anna),
            "invalid_request: object_id is empty");
  EXPECT_EQ(reject(desk_ask("q5", "ghost", HandoverKind::load, "anna-desk", "letter-1"), std::nullopt),
            "unknown_robot: robot ghost is not in the world");
  EXPECT_EQ(reject(desk_ask("q6", "r1", HandoverKind::load, "nowhere", "letter-1"), at_anna),
            "unknown_place: unknown place nowhere");
  // A rejected request id stays answered: asking again (even from the right place) repeats it.
  EXPECT_EQ(reject(desk_ask("q6", "r1", HandoverKind::load, "anna-desk", "letter-1"), at_anna),
            "unknown_place: unknown place nowhere");
  EXPECT_EQ(desk.office().pending_count(), 0u);
}

TEST_F(HandoverDeskTest, NobodyPresentAndRobotAwayAreRejectedByTheOffice) {
  // Bob is in 10:00-11:00 only.
  const DeskAnswer not_carried = desk.request(desk_ask("q1", "r1", HandoverKind::unload, "bob-desk", "letter-1"),
                                         RobotAtDesk{kBobDesk, 1}, at_clock(9, 0));
  EXPECT_EQ(not_carried.reason, "object_not_carried_by_robot");
  const DeskAnswer load = desk.request(desk_ask("q2", "r1", HandoverKind::load, "anna-desk", "letter-1"),
                                       RobotAtDesk{{6.0, 2.0}, 1}, at_clock(9, 0));
  EXPECT_EQ(load.reason, "robot_not_at_place");
  EXPECT_EQ(load.detail, "robot r1 is 4.0 m from anna-desk (must be within 0.8 m)");
  const DeskAnswer early = desk.request(desk_ask("q3", "r1", HandoverKind::load, "anna-desk", "letter-1"),
                                        RobotAtDesk{kAnnaDesk, 1}, at_clock(8, 45));
  EXPECT_EQ(early.reason, "nobody_present");
  EXPECT_EQ(early.detail, "nobody at anna-desk at 08:45 (somebody is back at 09:00)");
}

TEST_F(HandoverDeskTest, LeavingThePlaceFailsTheHandoverAndTheRequestHearsWhy) {
  const double t0 = at_clock(9, 15);
  ASSERT_EQ(desk.request(desk_ask("q1", "r1", HandoverKind::load, "anna-desk", "letter-1"), RobotAtDesk{kAnnaDesk, 1}, t0)
                .state,
            DeskAnswerState::accepted);
  const auto failed = desk.advance(t0 + 5.0, {{"r1", {5.0, 2.0}}});
  ASSERT_EQ(failed.size(), 1u);
  EXPECT_EQ(failed[0].state, DeskAnswerState::failed);
  EXPECT_EQ(failed[0].request_id, "q1");
  EXPECT_EQ(failed[0].reason, "robot_moved_away");
  EXPECT_DOUBLE_EQ(failed[0].time_s, t0 + 5.0);
  desk.changed_objects();
  EXPECT_TRUE(desk.office().object("letter-1")->location.is_at("anna-desk"));

  ASSERT_EQ(desk.request(desk_ask("q2", "r1", HandoverKind::load, "anna-desk", "letter-1"), RobotAtDesk{kAnnaDesk, 1}, t0 + 6)
                .state,
            DeskAnswerState::accepted);
  const auto gone = desk.advance(t0 + 7.0, {});
  ASSERT_EQ(gone.size(), 1u);
  EXPECT_EQ(gone[0].reason, "robot_gone");
  EXPECT_TRUE(desk.changed_objects().empty());
}

TEST(HandoverDesk, TheRunSeedDecidesTheDrawnDurations) {
  // Anna hands letter-1 over (fixed 20 s); Bob takes it (uniform 5..15 s), drawn from the seed.
  const auto bob_takes = [](uint64_t seed) {
    HandoverDesk d(small_office(), seed);
    const double t0 = at_clock(10, 15);
    EXPECT_EQ(d.request(desk_ask("q1", "r1", HandoverKind::load, "anna-desk", "letter-1"), RobotAtDesk{kAnnaDesk, 1}, t0)
                  .state,
              DeskAnswerState::accepted);
    EXPECT_EQ(d.advance(t0 + 20.0, {{"r1", kAnnaDesk}}).size(), 1u);
    const double t1 = at_clock(10, 30);
    const DeskAnswer a =
        d.request(desk_ask("q2", "r1", HandoverKind::unload, "bob-desk", "letter-1"), RobotAtDesk{kBobDesk, 1}, t1);
    EXPECT_EQ(a.state, DeskAnswerState::accepted) << a.detail;
    EXPECT_EQ(a.helper, "Bob");
    return a.completes_at_s - t1;
  };
  const double once = bob_takes(5);
  EXPECT_GE(once, 5.0);
  EXPECT_LE(once, 15.0);
  EXPECT_DOUBLE_EQ(bob_takes(5), once);
  EXPECT_NE(bob_takes(6), once);
}

}  // namespace
}  // namespace autonomy::sim::office
