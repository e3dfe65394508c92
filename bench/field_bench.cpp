// Cost-to-goal fields: the fast exact field (common/grid/cost_to_go) against the textbook
// std::priority_queue Dijkstra over the same graph, measured in the same run on the same maps.
//
//   field_bench            250 x 250, 1000 x 1000 and 4000 x 4000 (about half a minute)
//   field_bench --quick    250 and 1000 only
//   field_bench --sizes 500,2000 --fast-runs 9 --reference-runs 3
//
// Maps: 15 % of the cells blocked by random rectangles (random_rectangles(n, n, 0.15, seed 2024),
// resolution 0.05 m), goal at the centre. Times are medians over the runs (alternating textbook and
// fast runs) and include everything each side allocates (the fast side: move masks, bucket ring,
// the output). Wall-clock and thread CPU time are both printed: on a shared machine the CPU-time
// ratio is the steadier one. bytes/cell is FieldStats::work_bytes / cells: the peak heap the
// computation holds, output included (the 1-bit input raster is listed apart). "match" compares the
// fast field with the textbook float Dijkstra cell by cell (they must be bit-identical) and reports
// the largest relative difference against the same search in double (float rounding accumulated
// along paths). Nothing here passes or fails on time; the exit status is 1 only if the fields
// differ.
#include "common/grid/cost_to_go.hpp"
#include "common/grid/random_map.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <time.h>
#include <vector>

namespace {

using namespace autonomy::grid;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// CPU time of this (single) thread: on a shared machine it excludes the time other processes hold
// the core, so the ratio is steadier than the wall-clock one. Both are printed.
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
    wall_ms.push_back(ms_since(t0));
    cpu_ms.push_back(thread_cpu_ms() - c0);
  }
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const auto n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int runs_for(int size, int requested, int small, int large) {
  if (requested > 0) return requested;
  return size >= 4000 ? large : small;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Cost-to-goal field: fast exact field vs textbook Dijkstra"};
  std::vector<int> sizes{250, 1000, 4000};
  bool quick = false;
  int fast_runs = 0;
  int reference_runs = 0;
  std::uint64_t seed = 2024;
  app.add_flag("--quick", quick, "250 and 1000 only");
  app.add_option("--sizes", sizes, "square map sizes")->delimiter(',');
  app.add_option("--fast-runs", fast_runs,
                 "runs of the fast field per size (default 11, 5 at 4000)");
  app.add_option("--reference-runs", reference_runs,
                 "textbook runs per size (default 5, 1 at 4000)");
  app.add_option("--seed", seed, "map seed");
  CLI11_PARSE(app, argc, argv);
  if (quick)
    sizes.erase(std::remove_if(sizes.begin(), sizes.end(), [](int s) { return s > 1000; }),
                sizes.end());

  std::printf("%-11s %10s %12s %12s %8s %10s %10s %9s %s\n", "map", "reachable", "textbook_ms",
              "fast_ms", "speedup", "bytes/cell", "raster_B/c", "max_rel", "match");
  bool all_match = true;
  for (const int n : sizes) {
    const auto raster = random_rectangles(n, n, 0.15, seed, 0.05);
    const Cell goal = random_map_goal(raster);

    // Runs alternate (textbook, fast, textbook, fast, ...) so that both sides see the same machine
    // load; the first fast run pays the page faults of fresh memory like the first textbook run.
    Timing fast_t;
    Timing ref_t;
    FieldResult fast;
    std::vector<float> reference;
    const int nf = runs_for(n, fast_runs, 11, 5);
    const int nr = runs_for(n, reference_runs, 5, 1);
    for (int i = 0; i < std::max(nf, nr); ++i) {
      if (i < nr) {
        if (n >= 2000)
          std::fprintf(stderr, "  %d x %d: textbook Dijkstra run %d/%d ...\n", n, n, i + 1, nr);
        ref_t.run([&] { reference = reference_dijkstra<float>(raster, goal); });
        if (n >= 2000)
          std::fprintf(stderr, "  %d x %d: textbook run took %.0f ms\n", n, n,
                       ref_t.wall_ms.back());
      }
      if (i < nf) fast_t.run([&] { fast = compute_cost_to_go(raster, goal); });
    }
    if (!fast.ok()) {
      std::fprintf(stderr, "field_bench: %s\n", fast.reason.c_str());
      return 1;
    }
    if (n >= 2000)
      std::fprintf(stderr, "  %d x %d: double-precision reference for the accuracy check ...\n", n,
                   n);
    const auto exact = reference_dijkstra<double>(raster, goal);

    std::size_t mismatches = 0;
    double max_rel = 0.0;
    const auto& c = fast.field.costs();
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (c[i] != reference[i] && !(std::isnan(c[i]) && std::isnan(reference[i]))) ++mismatches;
      if (std::isinf(c[i]) != std::isinf(exact[i])) ++mismatches;
      if (std::isfinite(c[i]) && exact[i] > 0)
        max_rel = std::max(max_rel, std::abs(c[i] - exact[i]) / exact[i]);
    }
    all_match = all_match && mismatches == 0;

    const double t_ref = median(ref_t.wall_ms);
    const double t_fast = median(fast_t.wall_ms);
    const double c_ref = median(ref_t.cpu_ms);
    const double c_fast = median(fast_t.cpu_ms);
    const double cells = static_cast<double>(raster.cell_count());
    char label[32];
    std::snprintf(label, sizeof label, "%dx%d", n, n);
    std::printf(
        "%-11s %10zu %12.2f %12.2f %7.1fx %10.2f %10.3f %9.1e %s\n", label, fast.stats.reachable,
        t_ref, t_fast, t_ref / t_fast, static_cast<double>(fast.stats.work_bytes) / cells,
        static_cast<double>(raster.storage_bytes()) / cells, max_rel,
        mismatches == 0 ? "bit-identical" : ("MISMATCH " + std::to_string(mismatches)).c_str());
    std::printf("%-11s cpu time: textbook %.2f ms, fast %.2f ms, speedup %.1fx\n", "", c_ref,
                c_fast, c_ref / c_fast);
    std::printf("%-11s wall ms per run: fast", "");
    for (double t : fast_t.wall_ms) std::printf(" %.1f", t);
    std::printf("; textbook");
    for (double t : ref_t.wall_ms) std::printf(" %.1f", t);
    std::printf("\n");
    std::printf("%-11s fast runs %d, textbook runs %d; pushes/reachable %.2f, ring %zu buckets\n",
                "", nf, nr,
                static_cast<double>(fast.stats.pushes) / static_cast<double>(fast.stats.reachable),
                fast.stats.buckets);
    std::fflush(stdout);
  }
  return all_match ? 0 : 1;
}
