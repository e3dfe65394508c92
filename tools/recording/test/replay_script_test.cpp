#include "tools/recording/replay_script.hpp"

#include <gtest/gtest.h>

namespace autonomy::recording {
namespace {

// log time = when the recorder took it; publish time = when it was written. Here the recorder
// takes in batches, so log times say little and publish times order the samples.
RecordedSample clock(uint64_t published, int64_t tick) {
  return {"autonomy/clock", 1000, published, "", Json{{"tick", tick}, {"world_id", 7}}, tick};
}
RecordedSample input(const std::string& topic, uint64_t published, const std::string& cdr,
                     std::optional<int64_t> tick = std::nullopt, Json value = Json::object()) {
  return {topic, 1000 + published / 10, published, cdr, std::move(value), tick};
}
RecordedSample ack(uint64_t published, const std::string& participant, int64_t tick, const std::string& cdr) {
  return {"autonomy/lockstep/ack", 1000, published, cdr, Json{{"participant", participant}, {"tick", tick}}, tick};
}
RecordedSample state(uint64_t published, const std::string& robot, int64_t tick, double x) {
  return {"autonomy/robot/state", 1000, published, "", Json{{"robot_id", robot}, {"tick", tick}, {"x", x}}, tick};
}

std::vector<std::string> order(const ReplayScript& s) {
  std::vector<std::string> out;
  for (const auto& i : s.inputs()) out.push_back(std::to_string(i.due) + ":" + i.cdr);
  return out;
}

TEST(ReplayScript, InputsAreDueAtTheirTickTheClockShownOrTheWakeAndAcksGoLast) {
  const ReplayScript s(
      {
          input("autonomy/lockstep/registration", 1, "reg"),               // before any clock: at the start
          input("autonomy/sim/spawn_request", 2, "spawn"),                 // likewise
          ack(12, "behavior/r1", 0, "ack0"),                               // written before the command of tick 0
          input("autonomy/robot/cmd_vel", 13, "cmd0", 0),                  // stamped 0
          input("autonomy/sim/door_command", 14, "door"),                  // no tick: the clock shown, 0
          input("autonomy/robot/cmd_vel", 19, "cmd1", 1),                  // stamped 1
          ack(22, "behavior/r1", 1, "ack1quiet"),                          // quiet after tick 1
          input("autonomy/sim/door_command", 30, "door-while-quiet"),      // the world still shows 1
          ack(40, "behavior/r1", 1, "ack1wake"),                           // repeated: woke the world...
          ack(52, "behavior/r1", 9, "ack9"),                               // ...which showed tick 9 next
      },
      {}, {clock(10, 0), clock(20, 1), clock(50, 9)});
  EXPECT_EQ(order(s), (std::vector<std::string>{"-1:reg", "-1:spawn", "0:cmd0", "0:door", "0:ack0", "1:cmd1",
                                                "1:door-while-quiet", "1:ack1quiet", "9:ack1wake", "9:ack9"}));
  EXPECT_EQ(s.clock_ticks(), (std::vector<int64_t>{0, 1, 9}));
  EXPECT_EQ(s.next_clock_after(1), 9);
  EXPECT_EQ(s.next_clock_after(4), 9);
  EXPECT_FALSE(s.next_clock_after(9).has_value());
  EXPECT_EQ(s.last_tick(), 9);
}

TEST(ReplayScript, OutputsAreDueAtTheNextClockAndMatchedExactlyWithoutTheWorldId) {
  ReplayScript s({}, {state(9, "r1", 0, 1.0), state(19, "r1", 1, 1.5), state(19, "r2", 1, 4.0)},
                 {clock(10, 0), clock(20, 1), clock(30, 2)});
  EXPECT_EQ(s.outputs(), 3u);
  // Tick 0's state is due once the fresh world shows tick 1.
  EXPECT_FALSE(s.check_due_by(0).has_value());
  const auto missing = s.check_due_by(1);
  ASSERT_TRUE(missing.has_value());
  EXPECT_EQ(missing->tick, 0);
  EXPECT_NE(missing->describe().find("published nothing"), std::string::npos) << missing->describe();

  s.fresh_output("autonomy/robot/state", 0, Json{{"robot_id", "r1"}, {"tick", 0}, {"x", 1.0}, {"world_id", 99}});
  EXPECT_FALSE(s.check_due_by(1).has_value());
  EXPECT_EQ(s.matched(), 1u);
  // A fresh sample the recorder missed is no mismatch; a different one is.
  s.fresh_output("autonomy/robot/state", 1, Json{{"robot_id", "r3"}, {"tick", 1}, {"x", 0.0}});
  s.fresh_output("autonomy/robot/state", 1, Json{{"robot_id", "r1"}, {"tick", 1}, {"x", 1.5}});
  s.fresh_output("autonomy/robot/state", 1, Json{{"robot_id", "r2"}, {"tick", 1}, {"x", 4.25}});
  const auto different = s.check_due_by(2);
  ASSERT_TRUE(different.has_value());
  EXPECT_EQ(different->topic, "autonomy/robot/state");
  EXPECT_EQ(different->tick, 1);
  EXPECT_EQ(s.matched(), 2u);
  const std::string text = different->describe();
  EXPECT_NE(text.find("/x recorded 4.0, replayed 4.25"), std::string::npos) << text;
  EXPECT_EQ(text.find("/robot_id"), std::string::npos) << "the nearest fresh sample is r2's: " << text;
}

TEST(ReplayScript, RepeatsOfOneSampleAtOneTickAreAnsweredByOneFreshSample) {
  // The recorded world was held at tick 0 for three seconds: its clock 0 three times.
  const std::vector<RecordedSample> clocks = {clock(10, 0), clock(1010, 0), clock(2010, 0), clock(2020, 1), clock(2030, 2)};
  ReplayScript s({}, clocks, clocks);  // the tool checks the clocks as outputs too
  EXPECT_EQ(s.outputs(), 5u);
  s.fresh_output("autonomy/clock", 0, Json{{"tick", 0}, {"world_id", 8}});
  s.fresh_output("autonomy/clock", 1, Json{{"tick", 1}, {"world_id", 8}});
  EXPECT_FALSE(s.check_due_by(1).has_value());
  EXPECT_EQ(s.matched(), 3u);
  // Another value at the same tick is still a difference.
  ReplayScript t({}, {state(9, "r1", 0, 1.0), state(11, "r1", 0, 1.5)}, {clock(10, 0), clock(20, 1)});
  t.fresh_output("autonomy/robot/state", 0, Json{{"robot_id", "r1"}, {"tick", 0}, {"x", 1.0}});
  const auto other = t.check_due_by(1);
  ASSERT_TRUE(other.has_value());
  EXPECT_NE(other->describe().find("/x recorded 1.5, replayed 1.0"), std::string::npos) << other->describe();
}

TEST(ReplayScript, OutputsReceivedAfterTheLastClockAreCheckedAtTheEnd) {
  ReplayScript s({}, {state(39, "r1", 3, 2.0), state(45, "r1", 5, 2.5)}, {clock(40, 3)});
  EXPECT_EQ(s.last_tick(), 5) << "the world must reach the last state recorded, after the last clock";
  EXPECT_FALSE(s.check_due_by(3).has_value());
  EXPECT_TRUE(s.check_due_by(INT64_MAX).has_value());
  s.fresh_output("autonomy/robot/state", 3, Json{{"robot_id", "r1"}, {"tick", 3}, {"x", 2.0}});
  s.fresh_output("autonomy/robot/state", 5, Json{{"robot_id", "r1"}, {"tick", 5}, {"x", 2.5}});
  EXPECT_FALSE(s.check_due_by(INT64_MAX).has_value());
  EXPECT_EQ(s.outputs_by_topic(), (std::map<std::string, std::size_t>{{"autonomy/robot/state", 2}}));
}

TEST(ReplayScript, WorldContentDropsTheWorldIdAtAnyDepth) {
  EXPECT_EQ(world_content(Json{{"world_id", 1}, {"a", {{"world_id", 2}, {"b", 3}}}, {"c", Json::array({Json{{"world_id", 4}}})}}),
            (Json{{"a", {{"b", 3}}}, {"c", Json::array({Json::object()})}}));
}

RecordedSample command(uint64_t published, const std::string& source, int64_t tick) {
  return input("autonomy/robot/cmd_vel", published, "cmd", tick, Json{{"robot_id", "r1"}, {"source", source}, {"tick", tick}});
}
RecordedSample registration(uint64_t published, const std::string& participant, bool active = true) {
  return input("autonomy/lockstep/registration", published, "reg", std::nullopt,
               Json{{"participant", participant}, {"active", active}});
}

TEST(ReplayScript, CommandsOfALockstepParticipantWithoutItsAckOfTheirTickAreNamed) {
  // Complete: every command of the registered behavior/r2 has its ack; a tool's command (not a
  // participant) needs none.
  EXPECT_EQ(unacknowledged_commands({registration(1, "behavior/r2"), command(5, "behavior/r2", 3), ack(6, "behavior/r2", 3, "a"),
                                     command(7, "teleop", 4), command(8, "behavior/r2", 4), ack(9, "behavior/r2", 4, "a")}),
            std::nullopt);
  // The recorder matched the ack writer late: the commands of ticks 3 and 4 have no ack, the
  // one of tick 5 has. The first hole is named by the time it was written.
  const auto holes = unacknowledged_commands({registration(1, "behavior/r2"), command(8, "behavior/r2", 4),
                                              command(5, "behavior/r2", 3), command(10, "behavior/r2", 5),
                                              ack(11, "behavior/r2", 5, "a")});
  ASSERT_TRUE(holes.has_value());
  EXPECT_EQ(*holes,
            "2 recorded command(s) have no acknowledgement of their tick from their lockstep participant in the file "
            "(the first: autonomy/robot/cmd_vel from behavior/r2 at tick 3)");
  // An ack of another participant or another tick does not count; a participant that only left
  // (active false) is not one.
  EXPECT_TRUE(unacknowledged_commands({registration(1, "behavior/r2"), command(5, "behavior/r2", 3), ack(6, "behavior/r1", 3, "a"),
                                       ack(7, "behavior/r2", 2, "a")}).has_value());
  EXPECT_EQ(unacknowledged_commands({registration(1, "behavior/r2", false), command(5, "behavior/r2", 3)}), std::nullopt);
}

}  // namespace
}  // namespace autonomy::recording
