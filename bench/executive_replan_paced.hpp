#pragma once
// executive_replan_bench --paced: fault -> new plan executing in paced time, with plans of about
// 100 and about 1,000 tokens in the same run (issue 28). The DS1-like day stretched to `blocks`
// two-hour blocks (ds1_day.py's blocks: a DSN pass, a thrust arc, four pictures, a downlink), the
// ion engine stuck on at the end of its first arc, the real planner, executive and simulator; the
// world in paced time (it does not wait for the planner). See docs/scale.md.
#include <string>

namespace autonomy::bench {

struct PacedOptions {
  std::string repo, folder;
  int domain = 206;
  int runs = 1;
  double warp = 10;        // simulated / wall time: 1 s ticks every 1 / warp wall seconds
  int small_blocks = 4;    // plans of 8 hours: about 85 tokens after the fault (the baseline)
  int large_blocks = 48;   // plans of 96 hours: about 1,000 tokens after the fault
};

// Flies the small and the large plan `runs` times each (alternating), prints a row per flight and
// the medians; returns 0 when every flight measured a replan.
int run_paced(const PacedOptions& options);

}  // namespace autonomy::bench
