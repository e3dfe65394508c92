#pragma once
// Anytime curves as one SVG picture: a panel per instance, the gap to the optimum (%) against
// the time (log scale), a step line per solver.
#include <string>
#include <utility>
#include <vector>

namespace autonomy::bench {

struct AnytimeSeries {
  std::string solver;
  std::vector<std::pair<double, long>> points;  // (seconds, makespan), improving
};

struct AnytimePanel {
  std::string instance;
  long optimum = 0;
  std::vector<AnytimeSeries> series;
};

// Time axis from 0.01 s to `seconds`; gaps above `max_gap` percent are drawn at the top.
std::string anytime_svg(const std::vector<AnytimePanel>& panels, double seconds,
                        double max_gap = 30);

}  // namespace autonomy::bench
