// World stepping at scale: the stress scenario (deploy/scenarios/stress.pbtxt: 100 robots,
// 1000 x 1000 m, 2000 buildings) stepped at 10 Hz, every robot driving, with and without a
// 32-ray range scan per robot per tick; then the same on a 4000 x 4000-cell occupancy raster
// (0.25 m cells, the same 1000 m). Prints ms per tick and the share of one core the 10 Hz rate
// costs. Baseline: stepping without sensing, measured in the same run.
//
//   world_bench [--ticks N]
#include "common/grid/random_map.hpp"
#include "simulator/core/world.hpp"
#include "simulator/scenario/scenario_loader.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <memory>
#include <string>

using namespace autonomy;

namespace {

double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Each robot drives in a slowly turning direction so robots keep meeting walls and each other.
void command_all(sim::World& world, int tick) {
  for (const sim::RobotStatus& r : world.robots()) {
    const double phase = 0.05 * tick + static_cast<double>(std::hash<std::string>{}(r.id) % 628) / 100.0;
    sim::VelocityCommand c;
    c.robot_id = r.id;
    c.vx = 1.5 * std::cos(phase);
    c.vy = 1.5 * std::sin(phase);
    (void)world.submit(c);
  }
}

struct Figures {
  double ms_per_tick = 0.0;
  double rays = 0.0;
};

Figures run(sim::World world, int ticks, bool sensing) {
  constexpr double kDt = 0.1;
  std::size_t rays = 0;
  volatile float sink = 0.0f;
  const double start = cpu_seconds();
  for (int t = 0; t < ticks; ++t) {
    command_all(world, t);
    world.step(kDt);
    if (sensing) {
      for (const sim::RobotStatus& r : world.robots()) {
        const auto scan = world.sense(r.id);
        rays += scan->ranges.size();
        sink = sink + scan->ranges[0];
      }
    }
  }
  const double cpu = cpu_seconds() - start;
  return {1e3 * cpu / ticks, static_cast<double>(rays) / ticks};
}

void report(const char* name, const Figures& base, const Figures& sensed) {
  std::printf("%-28s step only: %7.3f ms/tick (%5.2f %% of a core at 10 Hz)\n", name, base.ms_per_tick,
              base.ms_per_tick * 10 / 10.0);
  std::printf("%-28s + sensing: %7.3f ms/tick (%5.2f %% of a core at 10 Hz), %.0f rays/tick, "
              "%.3f us/ray, sensing costs %.2fx the step\n",
              "", sensed.ms_per_tick, sensed.ms_per_tick * 10 / 10.0, sensed.rays,
              1e3 * (sensed.ms_per_tick - base.ms_per_tick) / sensed.rays,
              (sensed.ms_per_tick - base.ms_per_tick) / base.ms_per_tick);
}

}  // namespace

int main(int argc, char** argv) {
  int ticks = 600;  // 60 s simulated
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], "--ticks") == 0) ticks = std::atoi(argv[i + 1]);
  }
  const std::string path = std::string(AUTONOMY_SOURCE_DIR) + "/deploy/scenarios/stress.pbtxt";
  const sim::ScenarioLoadResult loaded = sim::load_scenario_file(path);
  if (!loaded.ok()) {
    std::fprintf(stderr, "%s", loaded.error_text().c_str());
    return 1;
  }
  const sim::WorldSpec& spec = loaded.scenario->world;
  std::printf("stress scenario: %zu robots, %zu buildings, %.0f x %.0f m, %d ticks at 10 Hz\n",
              spec.robots_at_start.size(), spec.obstacles.size(), spec.width, spec.height, ticks);
  const Figures base = run(sim::World(spec), ticks, false);
  const Figures sensed = run(sim::World(spec), ticks, true);
  report("vector map (rectangles)", base, sensed);

  // The same robots on a 4000 x 4000 raster of random rectangles (0.25 m cells, ~15 % blocked).
  sim::WorldSpec raster_spec = spec;
  raster_spec.obstacles.clear();
  auto raster = std::make_shared<grid::OccupancyRaster>(grid::random_rectangles(4000, 4000, 0.15, 42, 0.25));
  // Clear a 12 m square around every start so the scenario's robots can be placed.
  for (const sim::RobotSpec& r : raster_spec.robots_at_start) {
    for (int dr = -24; dr <= 24; ++dr) {
      for (int dc = -24; dc <= 24; ++dc) {
        const grid::Cell c{static_cast<int>(r.start.x / 0.25) + dc, static_cast<int>(r.start.y / 0.25) + dr};
        if (raster->contains(c)) raster->set_blocked(c, false);
      }
    }
  }
  raster_spec.rasters = {{"random 4000x4000", raster}};
  const Figures rbase = run(sim::World(raster_spec), ticks, false);
  const Figures rsensed = run(sim::World(raster_spec), ticks, true);
  report("raster 4000 x 4000 (0.25 m)", rbase, rsensed);
  return 0;
}
