#include "anytime_svg.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace autonomy::bench {

std::string anytime_svg(const std::vector<AnytimePanel>& panels, double seconds,
                        double max_gap) {
  constexpr int kWidth = 320, kHeight = 220, kLeft = 46, kTop = 24, kRight = 10, kBottom = 34;
  constexpr int kColumns = 3;
  const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
  const int rows = int(panels.size() + kColumns - 1) / kColumns;
  const double t0 = 0.01, t1 = std::max(seconds, 0.1);
  std::ostringstream svg;
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << kColumns * kWidth << "' height='"
      << rows * kHeight + 30 << "' font-family='sans-serif' font-size='11'>\n"
      << "<rect width='100%' height='100%' fill='white'/>\n";
  // The legend: the solvers of the first panel, in order.
  if (!panels.empty())
    for (std::size_t s = 0; s < panels[0].series.size(); ++s)
      svg << "<text x='" << 10 + 150 * s << "' y='" << rows * kHeight + 20 << "' fill='"
          << colours[s % 6] << "'>&#9644; " << panels[0].series[s].solver << "</text>\n";
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const AnytimePanel& panel = panels[p];
    const int ox = int(p % kColumns) * kWidth, oy = int(p / kColumns) * kHeight;
    const double w = kWidth - kLeft - kRight, h = kHeight - kTop - kBottom;
    auto x = [&](double t) {
      return ox + kLeft + w * std::log(std::clamp(t, t0, t1) / t0) / std::log(t1 / t0);
    };
    auto y = [&](long makespan) {
      const double gap = 100.0 * double(makespan - panel.optimum) / double(panel.optimum);
      return oy + kTop + h * (1 - std::clamp(gap, 0.0, max_gap) / max_gap);
    };
    svg << "<text x='" << ox + kLeft << "' y='" << oy + 16 << "' font-weight='bold'>"
        << panel.instance << " (optimum " << panel.optimum << ")</text>\n"
        << "<rect x='" << ox + kLeft << "' y='" << oy + kTop << "' width='" << w << "' height='"
        << h << "' fill='none' stroke='#999'/>\n";
    for (double t = t0; t <= t1 * 1.001; t *= 10)
      svg << "<text x='" << x(t) - 8 << "' y='" << oy + kTop + h + 14 << "'>" << t << "</text>\n";
    svg << "<text x='" << ox + kLeft + w / 2 - 20 << "' y='" << oy + kTop + h + 28
        << "'>seconds</text>\n";
    for (double g = 0; g <= max_gap; g += max_gap / 3) {
      const double gy = oy + kTop + h * (1 - g / max_gap);
      svg << "<text x='" << ox + 4 << "' y='" << gy + 4 << "'>+" << g << "%</text>\n"
          << "<line x1='" << ox + kLeft << "' x2='" << ox + kLeft + w << "' y1='" << gy
          << "' y2='" << gy << "' stroke='#eee'/>\n";
    }
    for (std::size_t s = 0; s < panel.series.size(); ++s) {
      const auto& pts = panel.series[s].points;
      if (pts.empty()) continue;
      // A step line: each makespan holds until the next improvement, the last to the end.
      svg << "<polyline fill='none' stroke-width='1.6' stroke='" << colours[s % 6]
          << "' points='";
      for (std::size_t i = 0; i < pts.size(); ++i) {
        const double next = i + 1 < pts.size() ? pts[i + 1].first : t1;
        svg << x(pts[i].first) << ',' << y(pts[i].second) << ' ' << x(next) << ','
            << y(pts[i].second) << ' ';
      }
      svg << "'/>\n";
    }
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace autonomy::bench
