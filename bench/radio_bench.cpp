// Radio link table cost: every pair of N robots (N = 10, 50, 100) in a 1000 x 1000 m world with
// 0, 100 or 500 attenuators (rectangular buildings, rotated rectangular buildings and declared
// U-shaped areas, 10 to 40 m across), robots placed uniformly at random.
//
// Figures: microseconds per full table (all N (N - 1) / 2 pairs, through the grid index; wall
// and CPU time), pairs per second, the share of one core a 10 Hz simulator would spend on it,
// and the team
// connectivity (components, BFS) on top. Baseline in the same run: the same table computed by
// testing every attenuator on every pair (RadioModel::obstacle_loss_exhaustive); the two must
// agree (max difference printed).
//
// Then the same robots on an occupancy raster (a map_server map: 1000 x 1000 cells of 1 m) whose
// walls are the outlines of 500 buildings of 10 to 40 m, each with one inner wall across it, drawn
// one cell thick: microseconds per table through RasterAttenuator's grid walk, against the
// definition-based reference walk (traverse_raster_reference) and against the 500-attenuator
// vector case above (ratio of CPU time per table, same robot count, same run).
//
// Usage: radio_bench [--quick] [--seed S] [--cell M]   (--cell: index cell size in m, 0 = auto)
#include "simulator/radio/connectivity.hpp"
#include "simulator/radio/radio_model.hpp"
#include "simulator/radio/raster_attenuator.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <time.h>
#include <vector>

using namespace autonomy::sim::radio;
using autonomy::geometry::Vec2;

namespace {

using Clock = std::chrono::steady_clock;

std::vector<Attenuator> city(const RadioParameters& p, int count, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> pos(0.0, 960.0);
  std::uniform_real_distribution<double> size(10.0, 40.0);
  std::uniform_real_distribution<double> angle(0.0, M_PI);
  std::vector<Attenuator> out;
  for (int i = 0; i < count; ++i) {
    const double x = pos(rng), y = pos(rng), w = size(rng), h = size(rng);
    switch (i % 4) {
      case 0:
      case 1:
        out.push_back(Attenuator::obstacle(Shape::rect({x, y, x + w, y + h}), p));
        break;
      case 2: {
        const double th = angle(rng);
        const Vec2 u(std::cos(th), std::sin(th)), v(-std::sin(th), std::cos(th)), o(x, y);
        out.push_back(Attenuator::obstacle(Shape::polygon({o, o + w * u, o + w * u + h * v, o + h * v}), p));
        break;
      }
      default: {
        const double s = w / 3.0;
        out.push_back(Attenuator::area(
            Shape::polygon({{x, y}, {x + 3 * s, y}, {x + 3 * s, y + h}, {x + 2 * s, y + h},
                            {x + 2 * s, y + h / 2}, {x + s, y + h / 2}, {x + s, y + h}, {x, y + h}}),
            3.0, 0.3));
      }
    }
  }
  return out;
}

// Building outlines (and one inner wall each), one cell thick, on a 1 m raster.
std::shared_ptr<autonomy::grid::OccupancyRaster> walled_city(int buildings, std::mt19937_64& rng) {
  auto g = std::make_shared<autonomy::grid::OccupancyRaster>(1000, 1000, 1.0);
  std::uniform_int_distribution<int> pos(0, 959), size(10, 40), coin(0, 1);
  const auto wall = [&](int c0, int r0, int c1, int r1) {
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c) g->set_blocked({c, r}, true);
  };
  for (int i = 0; i < buildings; ++i) {
    const int c = pos(rng), r = pos(rng), w = size(rng), h = size(rng);
    wall(c, r, c + w, r);
    wall(c, r + h, c + w, r + h);
    wall(c, r, c, r + h);
    wall(c + w, r, c + w, r + h);
    if (coin(rng) == 0) {
      wall(c + w / 2, r, c + w / 2, r + h);
    } else {
      wall(c, r + h / 2, c + w, r + h / 2);
    }
  }
  return g;
}

double cpu_now_s() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Median wall-clock seconds per call of f over batches lasting at least min_batch_s each; the
// median CPU seconds per call too when cpu_s is given (on a loaded machine the CPU time is the
// figure to read: wall time then includes waiting for a core).
template <typename F>
double median_seconds(F&& f, int batches, double min_batch_s, double* cpu_s = nullptr) {
  std::vector<double> per_call, cpu_per_call;
  for (int b = 0; b < batches; ++b) {
    int calls = 0;
    const auto start = Clock::now();
    const double cpu_start = cpu_now_s();
    double elapsed = 0.0;
    do {
      f();
      ++calls;
      elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    } while (elapsed < min_batch_s);
    per_call.push_back(elapsed / calls);
    cpu_per_call.push_back((cpu_now_s() - cpu_start) / calls);
  }
  std::sort(per_call.begin(), per_call.end());
  std::sort(cpu_per_call.begin(), cpu_per_call.end());
  if (cpu_s != nullptr) *cpu_s = cpu_per_call[cpu_per_call.size() / 2];
  return per_call[per_call.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  uint64_t seed = 1;
  double cell = 0.0;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) {
      quick = true;
    } else if (std::strcmp(argv[i], "--seed") == 0 && i + 1 < argc) {
      seed = std::strtoull(argv[++i], nullptr, 10);
    } else if (std::strcmp(argv[i], "--cell") == 0 && i + 1 < argc) {
      cell = std::strtod(argv[++i], nullptr);
    } else {
      std::fprintf(stderr, "usage: radio_bench [--quick] [--seed S] [--cell M]\n");
      return 2;
    }
  }
  const int batches = quick ? 3 : 7;
  const double min_batch_s = quick ? 0.02 : 0.1;

  std::printf("radio_bench: 1000 x 1000 m, seed %llu, %s; median of %d batches\n",
              static_cast<unsigned long long>(seed), quick ? "quick" : "full", batches);
  std::printf("%6s %9s %6s %6s %9s %9s %12s %9s %13s %8s %10s %11s %9s\n", "robots",
              "obstacles", "pairs", "cells", "table_us", "cpu_us", "pairs_per_s", "core_10Hz",
              "exhaustive_us", "speedup", "connect_us", "connected", "max_diff");
  const RadioParameters params;
  std::map<int, double> vector_cpu_500;  // robots -> CPU s per table with 500 attenuators
  for (int obstacles : {0, 100, 500}) {
    std::mt19937_64 rng(seed + static_cast<uint64_t>(obstacles));
    const RadioModel model(params, city(params, obstacles, rng), cell);
    for (int robots : {10, 50, 100}) {
      std::uniform_real_distribution<double> pos(0.0, 1000.0);
      std::vector<Vec2> positions;
      for (int i = 0; i < robots; ++i) positions.emplace_back(pos(rng), pos(rng));

      LinkTable table;
      double cpu_index = 0.0;
      const double t_index =
          median_seconds([&] { model.update(positions, table); }, batches, min_batch_s, &cpu_index);

      // Baseline: the same table with every attenuator tested on every pair.
      std::vector<double> brute(table.pair_count());
      const auto exhaustive = [&] {
        size_t k = 0;
        for (size_t i = 0; i < positions.size(); ++i) {
          for (size_t j = i + 1; j < positions.size(); ++j) {
            const double d = (positions[j] - positions[i]).norm();
            brute[k++] = params.tx_power_dbm - model.distance_loss_db(d) -
                         model.obstacle_loss_exhaustive(positions[i], positions[j]).loss_db;
          }
        }
      };
      double cpu_brute = 0.0;
      const double t_brute = median_seconds(exhaustive, batches, min_batch_s, &cpu_brute);

      double max_diff = 0.0;
      size_t k = 0, connected = 0;
      for (size_t i = 0; i < positions.size(); ++i) {
        for (size_t j = i + 1; j < positions.size(); ++j, ++k) {
          max_diff = std::max(max_diff, std::abs(table.at(i, j).signal_dbm - brute[k]));
          connected += table.at(i, j).connected ? 1 : 0;
        }
      }
      size_t components = 0;
      const double t_connect = median_seconds(
          [&] { components = Connectivity(table).components().size(); }, batches, min_batch_s / 4);

      if (obstacles == 500) vector_cpu_500[robots] = cpu_index;
      const double pairs = static_cast<double>(table.pair_count());
      char conn[32];
      std::snprintf(conn, sizeof conn, "%zu/%zu c%zu", connected, table.pair_count(), components);
      std::printf("%6d %9d %6.0f %6d %9.1f %9.1f %12.3g %8.2f%% %13.1f %7.1fx %10.1f %11s %9.1e\n",
                  robots, obstacles, pairs, model.index().columns() * model.index().rows(),
                  t_index * 1e6, cpu_index * 1e6, pairs / cpu_index, cpu_index * 10.0 * 100.0,
                  t_brute * 1e6, cpu_brute / cpu_index, t_connect * 1e6, conn, max_diff);
    }
  }
  std::printf("table_us: wall, cpu_us: CPU time per table (read this one on a loaded machine); "
              "pairs_per_s, core_10Hz (share of one core at 10 ticks/s) and speedup "
              "(exhaustive / indexed) are from CPU time. connected: connected pairs, cN = "
              "components.\n");

  // Occupancy raster: the same radio model with one map of walls instead of vector shapes.
  std::mt19937_64 rng(seed + 1000);
  auto raster = walled_city(500, rng);
  const RadioModel raster_model(params, {}, {RasterAttenuator::obstacle(raster, params, "city")}, {});
  std::printf("\nraster 1000 x 1000 cells of 1 m, 500 walled buildings, %.1f %% of cells blocked\n",
              100.0 * static_cast<double>(raster->blocked_count()) / static_cast<double>(raster->cell_count()));
  std::printf("%6s %6s %9s %9s %12s %9s %12s %8s %11s %10s %14s\n", "robots", "pairs", "table_us", "cpu_us",
              "pairs_per_s", "core_10Hz", "reference_us", "speedup", "walls/pair", "max_diff", "vs_500_vector");
  for (int robots : {10, 50, 100}) {
    std::uniform_real_distribution<double> pos(0.0, 1000.0);
    std::vector<Vec2> positions;
    for (int i = 0; i < robots; ++i) positions.emplace_back(pos(rng), pos(rng));
    LinkTable table;
    double cpu_index = 0.0;
    const double t_index = median_seconds([&] { raster_model.update(positions, table); }, batches, min_batch_s, &cpu_index);
    std::vector<Traversal> reference(table.pair_count());
    const auto slow = [&] {
      size_t k = 0;
      for (size_t i = 0; i < positions.size(); ++i)
        for (size_t j = i + 1; j < positions.size(); ++j)
          reference[k++] = traverse_raster_reference(*raster, positions[i], positions[j]);
    };
    double cpu_slow = 0.0;
    median_seconds(slow, quick ? 1 : 3, min_batch_s, &cpu_slow);
    double max_diff = 0.0, walls = 0.0;
    size_t k = 0;
    for (size_t i = 0; i < positions.size(); ++i) {
      for (size_t j = i + 1; j < positions.size(); ++j, ++k) {
        const LinkQuality& l = table.at(i, j);
        max_diff = std::max({max_diff, std::abs(l.inside_m - reference[k].inside_m),
                             std::abs(static_cast<double>(l.crossings - reference[k].crossings))});
        walls += l.crossings;
      }
    }
    const double pairs = static_cast<double>(table.pair_count());
    std::printf("%6d %6.0f %9.1f %9.1f %12.3g %8.2f%% %12.1f %7.1fx %11.1f %10.1e %13.2fx\n", robots, pairs,
                t_index * 1e6, cpu_index * 1e6, pairs / cpu_index, cpu_index * 10.0 * 100.0, cpu_slow * 1e6,
                cpu_slow / cpu_index, walls / pairs, max_diff, cpu_index / vector_cpu_500[robots]);
  }
  std::printf("reference_us: CPU time of the definition-based walk (every grid-line crossing sorted); "
              "vs_500_vector: CPU time per table on the raster / with 500 vector attenuators above.\n");
  return 0;
}
