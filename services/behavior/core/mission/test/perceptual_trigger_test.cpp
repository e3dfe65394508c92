// Every perceptual trigger: when it fires, when it does not, and the words it gives.
#include "services/behavior/core/mission/perceptual_trigger.hpp"

#include <gtest/gtest.h>

namespace autonomy::behavior {
namespace {

using geometry::Vec2;

const std::vector<std::string> kTeam = {"r2", "r3"};

Perception robot_at(double x, double y) {
  Perception p;
  p.pose = {x, y, 0.0};
  p.teammates = {{"r2", Vec2(0, 0), true}, {"r3", Vec2(0, 0), true}};
  return p;
}

std::optional<std::string> fires(const TriggerSpec& spec, const Perception& p, double in_state = 0.0,
                                 std::optional<Vec2> goal = std::nullopt, double tolerance = 0.0) {
  return make_trigger(spec)->fires({p, in_state, goal, tolerance, kTeam});
}

TriggerSpec contact(TriggerSpec::Kind kind, std::string teammate) {
  TriggerSpec t;
  t.kind = kind;
  t.teammate = std::move(teammate);
  return t;
}

TEST(AtGoalTrigger, WithinTheStatesTolerance) {
  TriggerSpec t;
  t.kind = TriggerSpec::Kind::AtGoal;
  EXPECT_EQ(fires(t, robot_at(8.5, 0.0), 0.0, Vec2(10.0, 0.0), 2.0),
            std::optional<std::string>("at goal (10, 0) within 2 m"));
  EXPECT_EQ(fires(t, robot_at(7.0, 0.0), 0.0, Vec2(10.0, 0.0), 2.0), std::nullopt);
  EXPECT_EQ(fires(t, robot_at(10.0, 0.0)), std::nullopt);  // a state without a goal
}

TEST(InAreaTrigger, CircleAndRectangleWithBorders) {
  TriggerSpec circle;
  circle.kind = TriggerSpec::Kind::InArea;
  circle.area.shape = Area::Shape::Circle;
  circle.area.circle = {Vec2(5.0, 5.0), 1.0};
  EXPECT_EQ(fires(circle, robot_at(5.0, 6.0)), std::optional<std::string>("in area: within 1 m of (5, 5)"));
  EXPECT_EQ(fires(circle, robot_at(5.0, 6.01)), std::nullopt);

  TriggerSpec rect;
  rect.kind = TriggerSpec::Kind::InArea;
  rect.area.shape = Area::Shape::Rect;
  rect.area.rect = {0.0, 0.0, 250.0, 50.0};
  EXPECT_EQ(fires(rect, robot_at(250.0, 50.0)), std::optional<std::string>("in area [0, 250] x [0, 50]"));
  EXPECT_EQ(fires(rect, robot_at(100.0, 50.5)), std::nullopt);
}

TEST(LostContactTrigger, NamedTeammate) {
  const TriggerSpec t = contact(TriggerSpec::Kind::LostContact, "r2");
  Perception p = robot_at(0, 0);
  EXPECT_EQ(fires(t, p), std::nullopt);
  p.teammates[0].in_contact = false;
  EXPECT_EQ(fires(t, p), std::optional<std::string>("lost contact with r2"));
  p.teammates.erase(p.teammates.begin());  // never heard of counts as lost
  EXPECT_EQ(fires(t, p), std::optional<std::string>("lost contact with r2"));
}

TEST(LostContactTrigger, AnyTeammate) {
  const TriggerSpec t = contact(TriggerSpec::Kind::LostContact, "");
  Perception p = robot_at(0, 0);
  EXPECT_EQ(fires(t, p), std::nullopt);
  p.teammates[1].in_contact = false;
  EXPECT_EQ(fires(t, p), std::optional<std::string>("lost contact with r3"));
}

TEST(ContactRestoredTrigger, NamedTeammateAndAll) {
  Perception p = robot_at(0, 0);
  p.teammates[0].in_contact = false;
  const TriggerSpec r3 = contact(TriggerSpec::Kind::ContactRestored, "r3");
  const TriggerSpec all = contact(TriggerSpec::Kind::ContactRestored, "");
  EXPECT_EQ(fires(r3, p), std::optional<std::string>("contact restored with r3"));
  EXPECT_EQ(fires(all, p), std::nullopt);
  p.teammates[0].in_contact = true;
  EXPECT_EQ(fires(all, p), std::optional<std::string>("contact restored with all teammates"));
}

TEST(TimeoutTrigger, SecondsInState) {
  TriggerSpec t;
  t.kind = TriggerSpec::Kind::Timeout;
  t.seconds = 30.0;
  EXPECT_EQ(fires(t, robot_at(0, 0), 29.99), std::nullopt);
  EXPECT_EQ(fires(t, robot_at(0, 0), 30.0), std::optional<std::string>("timeout: 30 s in state"));
  t.seconds = 0.0;  // rejected by the loader; never fires here
  EXPECT_EQ(fires(t, robot_at(0, 0), 1e9), std::nullopt);
}

TEST(CombinedTriggers, AllOfAndAnyOf) {
  TriggerSpec timeout;
  timeout.kind = TriggerSpec::Kind::Timeout;
  timeout.seconds = 10.0;
  TriggerSpec all;
  all.kind = TriggerSpec::Kind::AllOf;
  all.children = {contact(TriggerSpec::Kind::LostContact, "r2"), timeout};
  TriggerSpec any = all;
  any.kind = TriggerSpec::Kind::AnyOf;

  Perception p = robot_at(0, 0);
  EXPECT_EQ(fires(all, p, 20.0), std::nullopt);
  EXPECT_EQ(fires(any, p, 20.0), std::optional<std::string>("timeout: 10 s in state"));
  p.teammates[0].in_contact = false;
  EXPECT_EQ(fires(all, p, 20.0),
            std::optional<std::string>("lost contact with r2 and timeout: 10 s in state"));
  EXPECT_EQ(fires(any, p, 0.0), std::optional<std::string>("lost contact with r2"));
  TriggerSpec empty;
  empty.kind = TriggerSpec::Kind::AllOf;
  EXPECT_EQ(fires(empty, p), std::nullopt);
}

}  // namespace
}  // namespace autonomy::behavior
