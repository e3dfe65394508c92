// The courier scheduler process: takes delivery commands (restricted English or structured) for
// the office of a scenario file and drives its courier robots through their behavior processes
// and the simulator's handovers.
#include "services/courier/dds/courier_node.hpp"

#include <spdlog/spdlog.h>

#include <memory>
#include <stdexcept>

using namespace autonomy;

int main(int argc, char** argv) {
  courier::CourierNodeOptions options;
  std::vector<std::string> robots;
  std::string door_policy = "monitor";
  return service::run_service(
      argc, argv, "courier", "Courier scheduler: delivery jobs for the office's courier robots",
      service::InstanceFlag::Instance,
      [&](CLI::App& app) {
        app.footer("--config names the scenario whose office the couriers work in (e.g. "
                   "deploy/scenarios/office.pbtxt); its robots of kind \"courier\" are driven unless "
                   "--robot names others, each once its behavior process is ready. A robot whose behavior runs "
                   "with --capability courier joins the fleet too; one whose heartbeat is lost leaves it.");
        app.add_option("--robot", robots, "A courier robot to drive (repeatable; default: the scenario's couriers)");
        app.add_option("--robot-lost-after", options.robot_lost_after_s,
                       "Seconds without a heartbeat from a robot's behavior before its jobs go to the others")
            ->check(CLI::Range(0.5, 600.0))
            ->capture_default_str();
        app.add_option("--journal", options.journal_path,
                       "SQLite journal of commands and jobs (default: <log-dir>/courier-<instance>.db)");
        app.add_option("--events", options.events_path,
                       "Append what happens (loads, doors seen, opportunities, ...) as JSON lines to this file, "
                       "for courier_plot");
        app.add_option("--engine", options.engine, "Scheduler engine for small job sets: exact, large or paper")
            ->check(CLI::IsMember({"exact", "large", "paper"}))
            ->capture_default_str();
        app.add_option("--exact-max-jobs", options.exact_max_jobs,
                       "Above this many open jobs the large-scale engine is used instead of exact")
            ->check(CLI::Range(0, 12))
            ->capture_default_str();
        app.add_option("--learning", options.learning,
                       "Learn handover times, presence, door habits and travel times, keep them in the journal "
                       "and schedule with them (autonomy courier knowledge prints them)")
            ->capture_default_str();
        app.add_option("--door-policy", door_policy,
                       "monitor: doors seen closed make their jobs opportunistic and reschedule (the paper's "
                       "controller); wait: doors are not watched, a robot blocked by one waits and tries again")
            ->check(CLI::IsMember({"monitor", "wait"}))
            ->capture_default_str()
            ->each([&](const std::string& v) { options.monitor_doors = v == "monitor"; });
        app.add_option("--budget-ms", options.budget_ms, "Time budget of one schedule, ms")
            ->check(CLI::Range(1.0, 10000.0))
            ->capture_default_str();
      },
      [&](service::Service& service) {
        const auto& config = service.options().config_file;
        if (config.empty()) throw std::runtime_error("--config SCENARIO is required (the office to work in)");
        auto loaded = courier::load_courier_office(config);
        if (!loaded.ok()) throw std::runtime_error(loaded.error);
        options.office = std::move(*loaded.office);
        options.attach_defaults = options.office.attach_defaults;
        if (robots.empty()) {
          options.robots = options.office.robots;
        } else {
          for (const auto& id : robots) {
            courier::CourierRobotSpec spec = options.office.attach_defaults;
            for (const auto& known : options.office.robots)
              if (known.id == id) spec = known;
            spec.id = id;
            options.robots.push_back(spec);
          }
        }
        if (options.journal_path.empty())
          options.journal_path = service.options().log_dir + "/courier-" + service.options().instance + ".db";
        return std::make_unique<courier::CourierNode>(service, std::move(options));
      });
}
