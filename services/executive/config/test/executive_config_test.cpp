// The executive's configuration file: the DS1 example loads, and each kind of mistake is
// reported with file:line:column.
#include "executive_config.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace autonomy::executive {
namespace {

const std::string kExamples = EXECUTIVE_EXAMPLES_DIR;

// The DS1 example (or another) with `from` replaced by `to`, parsed as if it were that file.
std::vector<configfile::FileError> errors_with(const std::string& from, const std::string& to,
                                               const std::string& example = "ds1.pbtxt") {
  std::ifstream in(kExamples + "/" + example);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  std::vector<configfile::FileError> errors;
  EXPECT_FALSE(parse_executive_config(text, kExamples + "/" + example, errors));
  return errors;
}

std::string first(const std::vector<configfile::FileError>& errors) {
  return errors.empty() ? "(no error)" : errors.front().to_string();
}

TEST(ExecutiveConfig, TheDs1ExampleLoads) {
  for (const char* name : {"ds1.pbtxt", "ds1-4h.pbtxt"}) {
    std::vector<configfile::FileError> errors;
    auto c = load_executive_config(kExamples + "/" + name, errors);
    ASSERT_TRUE(c) << configfile::error_text(errors);
    EXPECT_EQ(c->rules.size(), 7u);
    EXPECT_NE(c->model_path.find("services/planner/examples/ds1.model"), std::string::npos) << c->model_path;
    EXPECT_EQ(c->safing.size(), 1u);
    EXPECT_EQ(c->safe_values.at(0).timeline, "dsone.engine");
    EXPECT_EQ(c->devices_of("dsone.camera"), std::vector<std::string>{"camera"});
    EXPECT_TRUE(c->devices_of("dsone.dsn").empty());
    // Stuck devices, resets, mode identification, stuck actuators, unconfirmed commands.
    EXPECT_EQ(c->fault_table().size(), 5u);
    EXPECT_EQ(c->faults.components.size(), 2u);
    EXPECT_EQ(c->request_lead_s, 600);
    const CommandMap map = c->command_map();
    planner::PlanToken turn;
    turn.object = "dsone";
    turn.attribute = "attitude";
    turn.predicate = "turning";
    turn.parameters = {"earth", "vesta", "150"};
    std::string error;
    auto command = map.command_for(turn, 4, 10, &error);
    ASSERT_TRUE(command) << error;
    EXPECT_EQ(command->device, "adcs");
    EXPECT_EQ(command->arguments, std::vector<std::string>{"vesta"});
  }
}

TEST(ExecutiveConfig, MistakesAreReportedWhereTheyAre) {
  const std::string file = kExamples + "/ds1.pbtxt";
  EXPECT_EQ(first(errors_with("problem: \"../../planner/examples/ds1-day.problem\"",
                              "problem: \"nowhere.problem\"")).rfind(file + ":11:1: problem 'nowhere.problem': no such file", 0),
            0u)
      << first(errors_with("problem: \"../../planner/examples/ds1-day.problem\"", "problem: \"nowhere.problem\""));
  EXPECT_NE(first(errors_with("timeline: \"dsone.engine\" predicate: \"off\"", "timeline: \"engine\" predicate: \"off\""))
                .find(":24:12: command rule: timeline 'engine' is not object.attribute"),
            std::string::npos)
      << first(errors_with("timeline: \"dsone.engine\" predicate: \"off\"", "timeline: \"engine\" predicate: \"off\""));
  EXPECT_NE(first(errors_with("arguments: \"?1\"", "arguments: \"?x\"")).find(":18:1: command rule for dsone.attitude == turning:"),
            std::string::npos)
      << first(errors_with("arguments: \"?1\"", "arguments: \"?x\""));
  EXPECT_NE(first(errors_with("component: \"camera_switch\" mode: \"failed_open\"",
                              "component: \"camera_switch\" mode: \"melted\""))
                .find("mode rule: component 'camera_switch' has no mode 'melted'"),
            std::string::npos);
  EXPECT_NE(first(errors_with("request_lead_s: 600", "request_lead_s: 20000"))
                .find(":13:1: request_lead_s must be shorter than horizon_s"),
            std::string::npos)
      << first(errors_with("request_lead_s: 600", "request_lead_s: 20000"));
  // A syntax error comes from protobuf's parser, with its position.
  EXPECT_NE(first(errors_with("horizon_s: 14400", "horizon_s: soon")).find(file + ":12:"), std::string::npos)
      << first(errors_with("horizon_s: 14400", "horizon_s: soon"));
  EXPECT_NE(first(errors_with("otherwise: \"unpowered\"", "otherwise: \"asleep\"")).find("mode identification:"),
            std::string::npos)
      << first(errors_with("otherwise: \"unpowered\"", "otherwise: \"asleep\""));
}

TEST(ExecutiveConfig, TheRoverExampleNamesItsRobotAndSites) {
  std::vector<configfile::FileError> errors;
  auto c = load_executive_config(kExamples + "/field-rover.pbtxt", errors);
  ASSERT_TRUE(c) << first(errors);
  ASSERT_EQ(c->robots.size(), 1u);
  const RobotSpec& rover = c->robots[0];
  EXPECT_EQ(rover.device, "rover");
  EXPECT_EQ(rover.radio_device, "rover_radio");
  EXPECT_EQ(rover.base, "lander");
  ASSERT_TRUE(rover.site("crater"));
  EXPECT_DOUBLE_EQ(rover.site("crater")->x, 29.0);
  EXPECT_FALSE(rover.site("moon"));
  EXPECT_EQ(c->devices_of("rover.location"), std::vector<std::string>{"rover"});
}

TEST(ExecutiveConfig, RobotMistakesAreReportedWhereTheyAre) {
  const std::string file = kExamples + "/field-rover.pbtxt";
  const auto with = [](const std::string& from, const std::string& to) {
    return first(errors_with(from, to, "field-rover.pbtxt"));
  };
  EXPECT_NE(with("sites { name: \"rock2\"", "sites { name: \"rock1\"").find("site 'rock1' is named twice"),
            std::string::npos);
  EXPECT_NE(with("base: \"lander\"", "").find("radio_device needs base"), std::string::npos);
  EXPECT_NE(with("tolerance: 0.5", "tolerance: -1").find("tolerance must be >= 0"), std::string::npos);
  const std::string wrong = with("command: \"go_to\"", "command: \"fly_to\"");
  EXPECT_NE(wrong.find(file + ":16:"), std::string::npos) << wrong;
  EXPECT_NE(wrong.find("robot device 'rover' takes go_to(site), not fly_to"), std::string::npos) << wrong;
  EXPECT_NE(with("radio_device: \"rover_radio\"", "radio_device: \"rover\"").find("device 'rover' is named twice"),
            std::string::npos);
}

}  // namespace
}  // namespace autonomy::executive
