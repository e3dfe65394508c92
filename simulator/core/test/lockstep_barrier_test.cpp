#include "simulator/core/lockstep_barrier.hpp"

#include <gtest/gtest.h>

namespace autonomy::sim {
namespace {

using Ack = LockstepBarrier::AckOutcome;
using Names = std::vector<std::string>;

class Barrier : public ::testing::Test {
 protected:
  void SetUp() override {
    barrier.add("a");
    barrier.add("b");
    barrier.begin_tick(1, 100.0);
  }
  LockstepBarrier barrier;
};

TEST_F(Barrier, CompletesAfterAcksAndAnnouncedCommandsArrivingAfterTheAck) {
  EXPECT_EQ(barrier.on_ack("a", 1, 2), Ack::Counted);
  EXPECT_EQ(barrier.on_ack("b", 1, 0), Ack::Counted);
  EXPECT_FALSE(barrier.complete(1));
  EXPECT_TRUE(barrier.on_command("a", 1));
  EXPECT_FALSE(barrier.complete(1));
  EXPECT_TRUE(barrier.on_command("a", 1));
  EXPECT_TRUE(barrier.complete(1));
}

TEST_F(Barrier, CompletesWithCommandsArrivingBeforeTheAck) {
  EXPECT_TRUE(barrier.on_command("a", 1));
  EXPECT_TRUE(barrier.on_command("b", 1));
  EXPECT_FALSE(barrier.complete(1));
  EXPECT_EQ(barrier.on_ack("b", 1, 1), Ack::Counted);
  EXPECT_FALSE(barrier.complete(1));  // a has not acked
  EXPECT_EQ(barrier.on_ack("a", 1, 1), Ack::Counted);
  EXPECT_TRUE(barrier.complete(1));
}

TEST_F(Barrier, OnlyTheCurrentTickCanComplete) {
  EXPECT_EQ(barrier.on_ack("a", 1, 0), Ack::Counted);
  EXPECT_EQ(barrier.on_ack("b", 1, 0), Ack::Counted);
  EXPECT_TRUE(barrier.complete(1));
  EXPECT_FALSE(barrier.complete(2));
  barrier.end_tick(1);
  barrier.begin_tick(2, 100.1);
  EXPECT_FALSE(barrier.complete(2));  // tick 1's acks do not carry over
}

TEST_F(Barrier, ExpireDropsASilentParticipantAfterTheTimeout) {
  EXPECT_EQ(barrier.on_ack("a", 1, 0), Ack::Counted);
  EXPECT_EQ(barrier.expire(1, 101.9, 2.0), Names{});
  EXPECT_EQ(barrier.expire(1, 102.0, 2.0), Names{"b"});
  EXPECT_EQ(barrier.participants(), Names{"a"});
  EXPECT_TRUE(barrier.complete(1));
}

TEST_F(Barrier, ExpireDropsAParticipantStillOwingCommands) {
  EXPECT_EQ(barrier.on_ack("a", 1, 3), Ack::Counted);
  EXPECT_EQ(barrier.on_ack("b", 1, 0), Ack::Counted);
  EXPECT_TRUE(barrier.on_command("a", 1));
  EXPECT_EQ(barrier.expire(1, 105.0, 2.0), Names{"a"});
  EXPECT_TRUE(barrier.complete(1));
}

TEST_F(Barrier, DroppedParticipantRejoinsByAckingTheCurrentTick) {
  EXPECT_EQ(barrier.on_ack("a", 1, 0), Ack::Counted);
  ASSERT_EQ(barrier.expire(1, 103.0, 2.0), Names{"b"});
  barrier.end_tick(1);
  barrier.begin_tick(2, 103.0);
  EXPECT_EQ(barrier.on_ack("b", 1, 0), Ack::IgnoredStale);  // a late ack does not rejoin
  EXPECT_EQ(barrier.participants(), Names{"a"});
  EXPECT_EQ(barrier.on_ack("b", 2, 1), Ack::Rejoined);
  EXPECT_EQ(barrier.participants(), (Names{"a", "b"}));
  EXPECT_EQ(barrier.on_ack("a", 2, 0), Ack::Counted);
  EXPECT_FALSE(barrier.complete(2));  // b's announced command is still owed
  EXPECT_TRUE(barrier.on_command("b", 2));
  EXPECT_TRUE(barrier.complete(2));
}

// The order a dropped participant's samples arrive in when it wakes up: the command for the
// current tick first, then the ack that rejoins it and announces that command.
TEST_F(Barrier, DroppedParticipantsCommandBeforeItsRejoiningAckCounts) {
  EXPECT_EQ(barrier.on_ack("a", 1, 0), Ack::Counted);
  ASSERT_EQ(barrier.expire(1, 103.0, 2.0), Names{"b"});
  barrier.end_tick(1);
  barrier.begin_tick(2, 103.0);
  EXPECT_EQ(barrier.on_ack("a", 2, 0), Ack::Counted);
  EXPECT_TRUE(barrier.on_command("b", 2));
  EXPECT_EQ(barrier.on_ack("b", 2, 1), Ack::Rejoined);
  EXPECT_TRUE(barrier.complete(2));
}

TEST_F(Barrier, CommandsFromStrangersAndRemovedParticipantsAreNotCounted) {
  barrier.remove("b");
  EXPECT_FALSE(barrier.on_command("b", 1));
  EXPECT_FALSE(barrier.on_command("stranger", 1));
  EXPECT_EQ(barrier.on_ack("a", 1, 0), Ack::Counted);
  EXPECT_TRUE(barrier.complete(1));
}

TEST_F(Barrier, OldAcksAndCommandsAreIgnored) {
  barrier.end_tick(1);
  barrier.begin_tick(2, 100.1);
  EXPECT_EQ(barrier.on_ack("a", 1, 0), Ack::IgnoredStale);
  EXPECT_FALSE(barrier.on_command("a", 1));
  EXPECT_EQ(barrier.on_ack("b", 2, 0), Ack::Counted);
  EXPECT_FALSE(barrier.complete(2));
}

TEST_F(Barrier, RemovedParticipantIsNotWaitedForAndCannotRejoinByAck) {
  barrier.remove("b");
  EXPECT_EQ(barrier.on_ack("a", 1, 0), Ack::Counted);
  EXPECT_TRUE(barrier.complete(1));
  EXPECT_EQ(barrier.on_ack("b", 1, 0), Ack::IgnoredUnknown);
  EXPECT_EQ(barrier.on_ack("stranger", 1, 0), Ack::IgnoredUnknown);
  EXPECT_EQ(barrier.participants(), Names{"a"});
}

TEST_F(Barrier, ParticipantAddedDuringATickIsWaitedForFromTheNext) {
  EXPECT_TRUE(barrier.add("c"));
  EXPECT_FALSE(barrier.add("c"));
  EXPECT_EQ(barrier.on_ack("a", 1, 0), Ack::Counted);
  EXPECT_EQ(barrier.on_ack("b", 1, 0), Ack::Counted);
  EXPECT_TRUE(barrier.complete(1));
  EXPECT_EQ(barrier.expire(1, 200.0, 2.0), Names{});
  barrier.end_tick(1);
  barrier.begin_tick(2, 100.1);
  EXPECT_EQ(barrier.on_ack("a", 2, 0), Ack::Counted);
  EXPECT_EQ(barrier.on_ack("b", 2, 0), Ack::Counted);
  EXPECT_FALSE(barrier.complete(2));
  EXPECT_EQ(barrier.on_ack("c", 2, 0), Ack::Counted);
  EXPECT_TRUE(barrier.complete(2));
}

TEST_F(Barrier, ParticipantAddedFromTheCurrentTickIsWaitedForAtOnce) {
  // Registered while the start was held: it takes part in the open tick.
  EXPECT_TRUE(barrier.add("c", true));
  EXPECT_EQ(barrier.on_ack("a", 1, 0), Ack::Counted);
  EXPECT_EQ(barrier.on_ack("b", 1, 0), Ack::Counted);
  EXPECT_FALSE(barrier.complete(1));
  EXPECT_EQ(barrier.on_ack("c", 1, 1), Ack::Counted);
  EXPECT_FALSE(barrier.complete(1));  // its announced command is still owed
  EXPECT_TRUE(barrier.on_command("c", 1));
  EXPECT_TRUE(barrier.complete(1));
}

TEST_F(Barrier, AnAnswerThatOvertookItsRegistrationCountsWhenItIsAddedFromTheCurrentTick) {
  // d read the held tick's clock, sent its command and ack; its registration arrives after.
  EXPECT_FALSE(barrier.on_command("d", 1));  // not registered: applied unsynchronised
  EXPECT_EQ(barrier.on_ack("d", 1, 1), Ack::IgnoredUnknown);
  EXPECT_TRUE(barrier.add("d", true));
  EXPECT_EQ(barrier.on_ack("a", 1, 0), Ack::Counted);
  EXPECT_EQ(barrier.on_ack("b", 1, 0), Ack::Counted);
  EXPECT_TRUE(barrier.complete(1));  // d's answer was kept
}

TEST(BarrierWithoutParticipants, CompletesAtOnce) {
  LockstepBarrier barrier;
  barrier.begin_tick(0, 0.0);
  EXPECT_TRUE(barrier.complete(0));
  EXPECT_EQ(barrier.expire(0, 10.0, 2.0), Names{});
}

TEST_F(Barrier, QuietWhileEveryParticipantDeclaredALaterTick) {
  EXPECT_FALSE(barrier.quiet(1));  // nobody declared anything yet
  barrier.on_ack("a", 1, 0, 10);
  EXPECT_FALSE(barrier.quiet(2));  // b still needs every tick
  barrier.on_ack("b", 1, 0, 5);
  ASSERT_TRUE(barrier.complete(1));
  barrier.end_tick(1);
  for (LockstepBarrier::Tick t = 2; t < 5; ++t) {
    barrier.begin_tick(t, 100.0);
    EXPECT_TRUE(barrier.quiet(t)) << t;
  }
  barrier.begin_tick(5, 100.0);
  EXPECT_FALSE(barrier.quiet(5));  // b wants tick 5 published
}

TEST_F(Barrier, AStaleAckWithoutAQuietTickWakesTheWorld) {
  barrier.on_ack("a", 1, 0, 100);
  barrier.on_ack("b", 1, 0, 100);
  barrier.end_tick(1);
  barrier.begin_tick(2, 100.0);
  ASSERT_TRUE(barrier.quiet(2));
  // a was sent something during the quiet span: it acks its last tick again, not quiet.
  EXPECT_EQ(barrier.on_ack("a", 1, 0, 0), Ack::IgnoredStale);
  EXPECT_FALSE(barrier.quiet(2));
  EXPECT_FALSE(barrier.complete(2));  // and the tick it wakes into is waited for as usual
}

TEST_F(Barrier, ANewcomerIsNeverQuietBeforeItsFirstAck) {
  barrier.on_ack("a", 1, 0, 100);
  barrier.on_ack("b", 1, 0, 100);
  barrier.add("c");  // waited for from tick 2
  barrier.end_tick(1);
  barrier.begin_tick(2, 100.0);
  EXPECT_FALSE(barrier.quiet(2));
  barrier.on_ack("c", 2, 0, 50);
  EXPECT_TRUE(barrier.quiet(2));
}

TEST_F(Barrier, ALeaverOrADroppedParticipantTakesItsQuietDeclarationWithIt) {
  barrier.on_ack("a", 1, 0, 100);
  barrier.on_ack("b", 1, 0, 100);
  barrier.remove("b");
  barrier.end_tick(1);
  barrier.begin_tick(2, 100.0);
  EXPECT_TRUE(barrier.quiet(2));  // a alone, still quiet
  EXPECT_EQ(barrier.expire(2, 200.0, 5.0), Names{"a"});
  EXPECT_FALSE(barrier.quiet(2));  // nobody left to be quiet
  EXPECT_EQ(barrier.on_ack("a", 2, 0, 0), Ack::Rejoined);
  EXPECT_FALSE(barrier.quiet(2));
}

// A process stopped or killed cannot wake the world when sent something: its quiet declaration
// ends when it falls silent, and the world waits for it (until the timeout) instead of jumping.
TEST_F(Barrier, ASilentParticipantIsNoLongerQuietButStillWaitedFor) {
  barrier.on_ack("a", 1, 0, 100);
  barrier.on_ack("b", 1, 0, 100);
  barrier.end_tick(1);
  barrier.begin_tick(2, 100.0);
  ASSERT_TRUE(barrier.quiet(2));
  barrier.silent("b");
  EXPECT_FALSE(barrier.quiet(2));
  EXPECT_EQ(barrier.participants(), (Names{"a", "b"}));
  barrier.on_ack("a", 2, 0, 100);
  EXPECT_FALSE(barrier.complete(2));  // b owes tick 2
  EXPECT_TRUE(barrier.expire(2, 101.0, 5.0).empty());
  EXPECT_EQ(barrier.on_ack("b", 2, 0, 0), Ack::Counted);  // continued: it answers and counts
  EXPECT_TRUE(barrier.complete(2));
}

}  // namespace
}  // namespace autonomy::sim
