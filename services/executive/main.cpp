// The executive process: flies a mission (a planner model and problem, named by its
// configuration file) by asking the planner for flexible plans over DDS and dispatching them
// to the spacecraft in the simulator, with mode identification and the fault table of the
// Remote Agent Experiment. See docs/executive.md.
#include <spdlog/spdlog.h>

#include <memory>

#include "executive_node.hpp"

using namespace autonomy;

int main(int argc, char** argv) {
  executive::ExecutiveNodeOptions options;
  return service::run_service(
      argc, argv, "executive",
      "Executive: dispatches the planner's flexible plans to the spacecraft, responds to faults, replans",
      service::InstanceFlag::Instance,
      [&](CLI::App& app) {
        app.add_option("--spacecraft", options.spacecraft, "The spacecraft this executive commands: only its telemetry is read (default: the first one heard; none: robots only)");
        app.add_option("--plan-timeout-s", options.plan_timeout_s,
                       "Ask the planner again when a request stays unanswered this long (wall s)")
            ->check(CLI::Range(0.1, 3600.0))
            ->capture_default_str();
        app.add_option("--plan-hold-s", options.plan_hold_s,
                       "In lockstep, hold a tick at most this long while a plan is made (wall s; "
                       "keep it below the simulator's ack timeout)")
            ->check(CLI::Range(0.0, 60.0))
            ->capture_default_str();
        app.add_option("--report-dir", options.report_dir,
                       "Write plan.svg (planned against executed, faults) and report.md here when the mission ends");
        app.add_option("--journal", options.journal_path,
                       "Flight journal (SQLite): goal outcomes, devices given up and the plan's state, so that "
                       "a restarted executive resumes the mission instead of starting it again");
        app.add_option("--watchdog-s", options.watchdog_s,
                       "A tick taking longer than this raises the alarm and safes the spacecraft (wall s)")
            ->check(CLI::Range(0.05, 600.0))
            ->capture_default_str();
      },
      [&](service::Service& service) -> std::unique_ptr<executive::ExecutiveNode> {
        options.config_path = service.options().config_file;
        if (options.config_path.empty()) throw std::runtime_error("--config FILE is required (e.g. services/executive/examples/ds1.pbtxt)");
        std::vector<configfile::FileError> errors;
        auto config = executive::load_executive_config(options.config_path, errors);
        if (!config) throw std::runtime_error("bad configuration:\n" + configfile::error_text(errors));
        std::string error;
        auto mission = executive::Mission::load(config->model_path, config->problem_path, &error);
        if (!mission) throw std::runtime_error("bad mission:\n" + error);
        return std::make_unique<executive::ExecutiveNode>(service, options, std::move(*config),
                                                          std::move(*mission));
      });
}
