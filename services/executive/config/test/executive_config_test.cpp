// The executive's configuration file: the DS1 example loads, and each kind of mistake is
// reported with file:line:column.
#include "executive_config.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace autonomy::executive {
namespace {

const std::string kExamples = EXECUTIVE_EXAMPLES_DIR;

// The DS1 example with `from` replaced by `to`, parsed as if it were the example file.
std::vector<configfile::FileError> errors_with(const std::string& from, const std::string& to) {
  std::ifstream in(kExamples + "/ds1.pbtxt");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  std::vector<configfile::FileError> errors;
  EXPECT_FALSE(parse_executive_config(text, kExamples + "/ds1.pbtxt", errors));
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

}  // namespace
}  // namespace autonomy::executive
