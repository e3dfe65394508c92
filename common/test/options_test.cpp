// The shared command-line options (common/service/options.hpp).
#include "common/service/options.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>
#include <unistd.h>
#include <vector>

namespace autonomy::service {
namespace {

// Saves an environment variable, clears it for the test and restores it afterwards, so that a
// developer's exported AUTONOMY_DOMAIN cannot change the results.
class EnvGuard {
 public:
  explicit EnvGuard(const char* name) : name_(name) {
    if (const char* v = std::getenv(name)) saved_ = v;
    ::unsetenv(name);
  }
  ~EnvGuard() {
    if (saved_)
      ::setenv(name_, saved_->c_str(), 1);
    else
      ::unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> saved_;
};

class OptionsTest : public ::testing::Test {
 protected:
  // Parses args (without the program name) into options_ for the given instance flag.
  void parse(std::vector<std::string> args, InstanceFlag flag = InstanceFlag::Instance) {
    app_ = std::make_unique<CLI::App>("test", "svc");
    options_ = ServiceOptions{};
    options_.service = "svc";
    add_service_options(*app_, options_, flag);
    args.insert(args.begin(), "svc");
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    app_->parse(static_cast<int>(argv.size()), argv.data());
  }

  EnvGuard domain_env_{"AUTONOMY_DOMAIN"};
  EnvGuard log_dir_env_{"AUTONOMY_LOG_DIR"};
  std::unique_ptr<CLI::App> app_;
  ServiceOptions options_;
};

TEST_F(OptionsTest, Defaults) {
  parse({});
  EXPECT_EQ(options_.service, "svc");
  EXPECT_EQ(options_.instance, "main");
  EXPECT_EQ(options_.domain, 0);
  EXPECT_EQ(options_.config_file, "");
  EXPECT_EQ(options_.log_level, "info");
  EXPECT_EQ(options_.log_dir, default_log_dir());
  EXPECT_DOUBLE_EQ(options_.heartbeat_period_s, 0.5);
}

TEST_F(OptionsTest, ParsesEveryOption) {
  char path[] = "/tmp/autonomy-options-test-XXXXXX";
  const int fd = ::mkstemp(path);
  ASSERT_GE(fd, 0);
  ::close(fd);
  parse({"--domain", "42", "--config", path, "--log-level", "debug", "--instance", "second", "--log-dir",
         "/tmp/x-logs", "--heartbeat-period", "0.25"});
  ::unlink(path);
  EXPECT_EQ(options_.domain, 42);
  EXPECT_EQ(options_.config_file, path);
  EXPECT_EQ(options_.log_level, "debug");
  EXPECT_EQ(options_.instance, "second");
  EXPECT_EQ(options_.log_dir, "/tmp/x-logs");
  EXPECT_DOUBLE_EQ(options_.heartbeat_period_s, 0.25);
}

TEST_F(OptionsTest, DomainBounds) {
  parse({"--domain", "232"});
  EXPECT_EQ(options_.domain, 232);
  parse({"--domain", "0"});
  EXPECT_EQ(options_.domain, 0);
  EXPECT_THROW(parse({"--domain", "300"}), CLI::ValidationError);
  EXPECT_THROW(parse({"--domain", "233"}), CLI::ValidationError);
  EXPECT_THROW(parse({"--domain", "-1"}), CLI::ParseError);
  EXPECT_THROW(parse({"--domain", "abc"}), CLI::ParseError);
}

TEST_F(OptionsTest, DomainOutOfRangeExitsWithCliError) {
  try {
    parse({"--domain", "300"});
    FAIL() << "--domain 300 accepted";
  } catch (const CLI::ParseError& e) {
    EXPECT_NE(app_->exit(e), 0);  // what CLI11_PARSE returns from main
  }
}

TEST_F(OptionsTest, LogLevelMustBeKnown) {
  for (const char* level : {"trace", "debug", "info", "warn", "error", "critical", "off"}) {
    parse({"--log-level", level});
    EXPECT_EQ(options_.log_level, level);
  }
  EXPECT_THROW(parse({"--log-level", "loud"}), CLI::ValidationError);
}

TEST_F(OptionsTest, ConfigMustExist) {
  EXPECT_THROW(parse({"--config", "/nonexistent/autonomy/config.txtpb"}), CLI::ValidationError);
}

TEST_F(OptionsTest, HeartbeatPeriodBounds) {
  EXPECT_THROW(parse({"--heartbeat-period", "0"}), CLI::ValidationError);
  EXPECT_THROW(parse({"--heartbeat-period", "61"}), CLI::ValidationError);
}

TEST_F(OptionsTest, RobotFlagIsRequiredAndSetsInstance) {
  parse({"--robot", "r7"}, InstanceFlag::Robot);
  EXPECT_EQ(options_.instance, "r7");
  EXPECT_THROW(parse({}, InstanceFlag::Robot), CLI::RequiredError);
  // --instance does not exist for per-robot processes, --robot not for the others.
  EXPECT_THROW(parse({"--robot", "r7", "--instance", "x"}, InstanceFlag::Robot), CLI::ParseError);
  EXPECT_THROW(parse({"--robot", "r7"}, InstanceFlag::Instance), CLI::ParseError);
}

TEST_F(OptionsTest, DomainFromEnvironmentWhenNoFlag) {
  ::setenv("AUTONOMY_DOMAIN", "17", 1);
  parse({});
  EXPECT_EQ(options_.domain, 17);
  parse({"--domain", "5"});
  EXPECT_EQ(options_.domain, 5);  // the flag wins over the environment
}

TEST_F(OptionsTest, DomainFromEnvironmentIsRangeChecked) {
  ::setenv("AUTONOMY_DOMAIN", "300", 1);
  EXPECT_THROW(parse({}), CLI::ValidationError);
}

TEST_F(OptionsTest, LogDirFromEnvironment) {
  ::setenv("AUTONOMY_LOG_DIR", "/tmp/from-env", 1);
  parse({});
  EXPECT_EQ(options_.log_dir, "/tmp/from-env");
}

TEST(DefaultLogDirTest, UnderHomeOrTmp) {
  std::optional<std::string> home;
  if (const char* h = std::getenv("HOME")) home = h;
  ::setenv("HOME", "/home/tester", 1);
  EXPECT_EQ(default_log_dir(), "/home/tester/.autonomy/log");
  ::unsetenv("HOME");
  EXPECT_EQ(default_log_dir(), "/tmp/autonomy/log");
  if (home) ::setenv("HOME", home->c_str(), 1);
}

}  // namespace
}  // namespace autonomy::service
