// The planner process: plans over DDS. Requests on autonomy/planner/request (a model and a
// problem in the planner language or as protobuf messages, an engine, a budget) get one reply
// each on autonomy/planner/reply; see services/planner/README.md, "The service".
#include <spdlog/spdlog.h>

#include <memory>

#include "planner_node.hpp"

using namespace autonomy;

int main(int argc, char** argv) {
  planner::PlannerNodeOptions options;
  return service::run_service(
      argc, argv, "planner", "Planner: flexible plans for models and problems sent over DDS",
      service::InstanceFlag::Instance,
      [&](CLI::App& app) {
        app.add_option("--budget-ms", options.default_budget_ms,
                       "Time budget of a request that gives none, ms")
            ->check(CLI::Range(std::int64_t{1}, std::int64_t{3600000}))
            ->capture_default_str();
        app.add_option("--max-budget-ms", options.limits.max_budget_ms,
                       "Longest budget a request may ask for, ms (longer ones are rejected)")
            ->check(CLI::Range(std::int64_t{1}, std::int64_t{86400000}))
            ->capture_default_str();
        app.add_option("--max-queue", options.max_queue,
                       "Requests that may wait while one is planned (more are answered busy)")
            ->check(CLI::Range(0, 1000))
            ->capture_default_str();
        app.add_option("--workers", options.workers,
                       "Requests planned at once, each on its own thread")
            ->check(CLI::Range(1, 64))
            ->capture_default_str();
        app.add_option("--margin-ms", options.margin_ms,
                       "A running request not answered by its budget plus this is answered "
                       "out_of_time (its search is cancelled)")
            ->check(CLI::Range(std::int64_t{10}, std::int64_t{600000}))
            ->capture_default_str();
      },
      [&](service::Service& service) {
        return std::make_unique<planner::PlannerNode>(service, options);
      });
}
