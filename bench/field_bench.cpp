// Cost-to-goal fields: the fast exact field (common/grid/cost_to_go) against the textbook
// std::priority_queue Dijkstra with double labels over the same graph, timed in the same run on
// the same maps, for map classes x sizes x goal placements (common/grid/map_classes), and on
// ROS map_server maps given with --map.
//
//   field_bench                          6 classes x 250, 1000, 2000 x 3 goals (a few minutes)
//   field_bench --quick                  250 and 1000 only
//   field_bench --large                  adds 4000 x 4000
//   field_bench --classes slam,maze --sizes 500 --goals corner
//   field_bench --map warehouse.yaml --map depot.yaml     (only those maps; add --classes to mix)
//
// Per row: the textbook time (double labels, the yardstick) and the field's time, both the median
// thread CPU time of the runs (on a shared machine it excludes the time other processes hold the
// core; the median wall time is printed beside it), their ratio, FieldStats::work_bytes per cell
// (peak heap held by the field computation, output included), the largest relative difference
// against the double textbook, and whether the field is bit-identical to the textbook search with
// float labels (computed once, untimed). pass_ms is one plain streaming pass timed in the same
// runs (allocate the output's floats and write +inf: the least any field computation must do) and
// `passes` the field's time in those passes. Nothing passes or fails on time; the exit status is 1
// only if a field differs from the float textbook search, 2 on a map that cannot be loaded.
#include "common/grid/cost_to_go.hpp"
#include "common/grid/map_classes.hpp"
#include "common/grid/map_loader.hpp"

#include <CLI/CLI.hpp>

#include <time.h>
#ifdef __linux__
#include <sys/mman.h>
#endif
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using namespace autonomy::grid;
using Clock = std::chrono::steady_clock;

double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

struct Timing {
  std::vector<double> wall_ms;
  std::vector<double> cpu_ms;

  template <typename F>
  void run(F&& f) {
    const double c0 = thread_cpu_ms();
    const auto t0 = Clock::now();
    f();
    wall_ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    cpu_ms.push_back(thread_cpu_ms() - c0);
  }
};

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const auto n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The memory-pass yardstick: what producing the output alone costs, i.e. allocating the field's
// cells.size() floats and writing +inf into each (one streaming pass; on big maps the kernel
// also zeroes the fresh pages first, as it does for the field's own output). Huge pages are asked
// for as compute_cost_to_go does.
void streaming_pass(std::size_t cells) {
  std::vector<float> v;
  v.reserve(cells);
#ifdef __linux__
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  const auto at = reinterpret_cast<std::uintptr_t>(v.data());
  const auto begin = (at + kHuge - 1) & ~(kHuge - 1);
  const auto end = (at + cells * sizeof(float)) & ~(kHuge - 1);
  if (cells * sizeof(float) >= 2 * kHuge && end > begin)
    ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#endif
  v.assign(cells, kUnreachable);
  asm volatile("" : : "r"(v.data()) : "memory");  // the writes are not optimised away
}

struct Options {
  int fast_runs = 0;       // 0: by size
  int reference_runs = 0;  // 0: by size
};

// One row: times both sides on (raster, goal), checks exactness. Returns false on a mismatch.
bool measure(const std::string& map, const std::string& size, const std::string& goal_name,
             const OccupancyRaster& raster, Cell goal, const Options& opt) {
  const std::size_t cells = raster.cell_count();
  const int nf = opt.fast_runs > 0 ? opt.fast_runs : (cells > 4'000'000 ? 5 : 9);
  const int nr = opt.reference_runs > 0 ? opt.reference_runs : (cells > 4'000'000 ? 1 : 3);
  Timing fast_t, ref_t, pass_t;
  FieldResult fast;
  std::vector<double> exact;
  // Alternating runs, so all sides see the same machine load.
  for (int i = 0; i < std::max(nf, nr); ++i) {
    if (i < nr) ref_t.run([&] { exact = reference_dijkstra<double>(raster, goal); });
    if (i < nf) fast_t.run([&] { fast = compute_cost_to_go(raster, goal); });
    if (i < nf) pass_t.run([&] { streaming_pass(cells); });
  }
  if (!fast.ok()) {
    std::printf("%-14s %-9s %-7s %s\n", map.c_str(), size.c_str(), goal_name.c_str(),
                fast.reason.c_str());
    return true;
  }
  const auto textbook_float = reference_dijkstra<float>(raster, goal);
  std::size_t mismatches = 0;
  double max_rel = 0.0;
  const auto& c = fast.field.costs();
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c[i] != textbook_float[i]) ++mismatches;
    if (std::isinf(c[i]) != std::isinf(exact[i])) ++mismatches;
    if (std::isfinite(c[i]) && exact[i] > 0)
      max_rel = std::max(max_rel, std::abs(c[i] - exact[i]) / exact[i]);
  }
  const double ref_cpu = median(ref_t.cpu_ms), fast_cpu = median(fast_t.cpu_ms);
  const double pass_cpu = median(pass_t.cpu_ms);
  const double n = static_cast<double>(cells);
  std::printf(
      "%-14s %-9s %-7s %6.1f%% %10.2f %9.2f %7.1fx %10.2f %9.2f %8.2f %6.1f %6.2f %8.1e %s\n",
      map.c_str(), size.c_str(), goal_name.c_str(),
      100.0 * static_cast<double>(fast.stats.reachable) / n, ref_cpu, fast_cpu, ref_cpu / fast_cpu,
      median(ref_t.wall_ms), median(fast_t.wall_ms), pass_cpu, fast_cpu / pass_cpu,
      static_cast<double>(fast.stats.work_bytes) / n, max_rel,
      mismatches == 0 ? "bit-identical" : ("MISMATCH " + std::to_string(mismatches)).c_str());
  std::fflush(stdout);
  return mismatches == 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Cost-to-goal field: fast exact field vs textbook Dijkstra, per map class"};
  std::vector<int> sizes{250, 1000, 2000};
  std::vector<std::string> class_names;
  std::vector<std::string> goal_names;
  std::vector<std::string> map_files;
  bool quick = false, large = false;
  Options opt;
  std::uint64_t seed = 2024;
  app.add_flag("--quick", quick, "sizes 250 and 1000 only");
  app.add_flag("--large", large, "add 4000 x 4000 (textbook runs take seconds each)");
  app.add_option("--sizes", sizes, "square map sizes (cells a side)")->delimiter(',');
  app.add_option("--classes", class_names, "map classes: clutter,blocks,building,slam,maze,arena")
      ->delimiter(',');
  app.add_option("--goals", goal_names, "goal placements: centre,corner,narrow")->delimiter(',');
  app.add_option("--map", map_files, "a ROS map_server YAML to measure (repeatable)");
  app.add_option("--fast-runs", opt.fast_runs, "field runs per row (default 9, 5 above 4 M cells)");
  app.add_option("--reference-runs", opt.reference_runs,
                 "textbook runs per row (default 3, 1 above 4 M cells)");
  app.add_option("--seed", seed, "map seed");
  CLI11_PARSE(app, argc, argv);

  if (quick) sizes = {250, 1000};
  if (large) sizes.push_back(4000);
  for (int s : sizes) {
    if (s < 1 || s > 20000) {
      std::fprintf(stderr, "field_bench: --sizes: %d is not in 1..20000\n", s);
      return 2;
    }
  }
  std::vector<MapClass> classes;
  for (const auto& name : class_names) {
    const auto c = map_class_from_string(name);
    if (!c) {
      std::fprintf(stderr,
                   "field_bench: --classes: unknown class '%s' (clutter, blocks, building, slam, "
                   "maze, arena)\n",
                   name.c_str());
      return 2;
    }
    classes.push_back(*c);
  }
  if (classes.empty() && map_files.empty())
    classes.assign(std::begin(kAllMapClasses), std::end(kAllMapClasses));
  std::vector<GoalPlacement> goals;
  for (const auto& name : goal_names) {
    const auto g = goal_placement_from_string(name);
    if (!g) {
      std::fprintf(stderr,
                   "field_bench: --goals: unknown placement '%s' (centre, corner, narrow)\n",
                   name.c_str());
      return 2;
    }
    goals.push_back(*g);
  }
  if (goals.empty()) goals.assign(std::begin(kAllGoalPlacements), std::end(kAllGoalPlacements));

  std::printf("%-14s %-9s %-7s %7s %10s %9s %8s %10s %9s %8s %6s %6s %8s %s\n", "map", "size",
              "goal", "reach", "textbk_ms", "field_ms", "ratio", "textbk_wall", "field_wall",
              "pass_ms", "passes", "B/cell", "max_rel", "vs float textbook");
  bool all_match = true;
  for (const auto& path : map_files) {
    auto loaded = load_ros_map(path);
    if (!loaded.ok()) {
      std::fprintf(stderr, "field_bench: %s\n", loaded.error.c_str());
      return 2;
    }
    const auto& raster = loaded.map->raster;
    std::string name = path.substr(path.find_last_of('/') + 1);
    name = name.substr(0, name.find_last_of('.'));
    const std::string size = std::to_string(raster.width()) + "x" + std::to_string(raster.height());
    for (GoalPlacement g : goals) {
      const auto goal = place_goal(raster, g);
      if (!goal) {
        std::fprintf(stderr, "field_bench: %s has no free cell\n", path.c_str());
        return 2;
      }
      all_match = measure(name, size, to_string(g), raster, *goal, opt) && all_match;
    }
  }
  for (MapClass c : classes) {
    for (int n : sizes) {
      const auto raster = make_map(c, n, n, seed, 0.05);
      for (GoalPlacement g : goals) {
        const auto goal = place_goal(raster, g);
        if (!goal) continue;  // a map with no free cell: nothing to measure
        all_match =
            measure(to_string(c), std::to_string(n), to_string(g), raster, *goal, opt) && all_match;
      }
    }
  }
  return all_match ? 0 : 1;
}
