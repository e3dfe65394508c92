#include "simulator/simulator_cli.hpp"

#include "simulator/dds/world_claim.hpp"
#include "simulator/scenario/builtin_scenario.hpp"
#include "simulator/scenario/scenario_loader.hpp"

#include <chrono>
#include <iostream>

namespace autonomy::sim {

void SimulatorCli::add_options(CLI::App& app) {
  app.add_option("--wait-for", wait_for_,
                 "Hold tick 0 until these lockstep participants registered (e.g. behavior/r1; several: "
                 "behavior/r1,behavior/r2 or the option again)")
      ->delimiter(',');
  app.add_option("--max-ticks", max_ticks_, "Stop after this many ticks (0: run until stopped)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--trajectory", trajectory_, "Write every robot's pose per tick to this CSV file");
  app.add_option("--svg", picture_, "Write an SVG picture of the run (map and robot paths) at exit");
  app.add_option("--metrics", metrics_,
                 "Write the run's metrics (time, distance, connectivity, coverage) to PREFIX.csv and "
                 "PREFIX.json at exit")
      ->option_text("PREFIX");
  app.add_option("--radio-period", radio_period_, "Recompute the radio link table every N ticks")
      ->check(CLI::PositiveNumber)
      ->option_text("N (1)");
  app.add_flag("--without-robots", without_robots_,
               "Spawn none of the scenario's robots at the start: controllers attach their own");
  app.add_flag("--stop-when-finished", stop_when_finished_,
               "Stop once every robot reports its mission finished (or its goal reached)");
  app.add_flag("--every-tick", every_tick_,
               "Lockstep: publish every tick, also those all participants declared quiet");
  app.add_option("--world-check", world_check_s_,
                 "Seconds to listen for another world on the domain before starting this one (0: do not)")
      ->check(CLI::NonNegativeNumber)
      ->option_text("S (1)");
  app.add_option("--mode", mode_override_, "Override the scenario's clock mode")
      ->check(CLI::IsMember({"lockstep", "paced"}));
  // A set whose processes respawn holds the world through a restart with a timeout above
  // its respawn time (back-off + start + readiness): the outage then costs no simulated time.
  app.add_option("--ack-timeout", ack_timeout_s_,
                 "Lockstep: wall seconds before a silent participant is dropped (overrides the scenario's "
                 "ack_timeout_s)")
      ->check(CLI::PositiveNumber)
      ->option_text("S");
  app.footer("Without --config the built-in demo scenario (deploy/scenarios/demo.pbtxt) runs.");
}

std::unique_ptr<SimulatorNode> SimulatorCli::make_node(service::Service& service) {
  const auto& config = service.options().config_file;
  sim::ScenarioLoadResult loaded =
      config.empty() ? sim::load_scenario_text(std::string(sim::builtin_default_scenario()),
                                               std::string(sim::kBuiltinScenarioSource))
                     : sim::load_scenario_file(config);
  if (!loaded.ok()) {
    std::cerr << loaded.error_text();
    throw std::runtime_error("scenario has " + std::to_string(loaded.errors.size()) + " error(s)");
  }
  if (without_robots_) loaded.scenario->world.robots_at_start.clear();
  sim::SimulatorRunOptions run;
  run.settings = loaded.scenario->simulation;
  if (mode_override_ == "lockstep") run.settings.mode = sim::ClockMode::Lockstep;
  if (mode_override_ == "paced") run.settings.mode = sim::ClockMode::Paced;
  if (ack_timeout_s_ > 0) run.settings.ack_timeout_s = ack_timeout_s_;
  run.wait_for_participants = wait_for_;
  if (max_ticks_ > 0) run.max_ticks = max_ticks_;
  run.trajectory_csv = trajectory_;
  run.picture_svg = picture_;
  run.metrics_prefix = metrics_;
  run.radio_period_ticks = radio_period_;
  run.stop_when_finished = stop_when_finished_;
  run.quiet_ticks = !every_tick_;
  // One world per domain: refuse before anything of this world is published.
  if (auto other = sim::find_other_world(
          service.participant(), std::chrono::milliseconds(static_cast<int64_t>(world_check_s_ * 1000.0))))
    throw std::runtime_error(sim::describe(*other, static_cast<uint32_t>(service.options().domain)));
  run.world_id = sim::new_world_id();
  service.heartbeat().set_detail(config.empty() ? std::string(sim::kBuiltinScenarioSource) : config);
  service.heartbeat().set_world(run.world_id);
  spdlog::info("world {} on DDS domain {}", run.world_id, service.options().domain);
  return std::make_unique<sim::SimulatorNode>(service, std::move(*loaded.scenario), run);
}

}  // namespace autonomy::sim
