#include "simulator/report/run_svg.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace autonomy::sim {

namespace {

// Distinguishable colours for up to ten robots, then they repeat.
const char* robot_colour(size_t i) {
  static const char* kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                   "#17becf", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22"};
  return kPalette[i % (sizeof(kPalette) / sizeof(kPalette[0]))];
}

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace

std::string render_run_svg(const RunPicture& pic) {
  const WorldSpec& w = *pic.world;
  // World metres to pixels; y flips so that +y points up as in the world frame.
  const double scale = std::clamp(900.0 / std::max(w.width, w.height), 0.5, 60.0);
  const double margin = 20.0, legend = 24.0;
  const double width_px = w.width * scale + 2 * margin;
  const double height_px = w.height * scale + 2 * margin + legend;
  auto px = [&](double x) { return margin + x * scale; };
  auto py = [&](double y) { return margin + legend + (w.height - y) * scale; };

  std::ostringstream svg;
  svg.precision(6);
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width_px << "\" height=\"" << height_px
      << "\" font-family=\"sans-serif\" font-size=\"13\">\n";
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg << "<text x=\"" << margin << "\" y=\"" << margin + 4 << "\">" << escape(pic.caption) << "</text>\n";
  svg << "<rect x=\"" << px(0) << "\" y=\"" << py(w.height) << "\" width=\"" << w.width * scale << "\" height=\""
      << w.height * scale << "\" fill=\"#fafafa\" stroke=\"black\"/>\n";
  for (const auto& r : w.obstacles)
    svg << "<rect x=\"" << px(r.min_x) << "\" y=\"" << py(r.max_y) << "\" width=\"" << (r.max_x - r.min_x) * scale
        << "\" height=\"" << (r.max_y - r.min_y) * scale << "\" fill=\"#555\"/>\n";

  size_t index = 0;
  double legend_x = margin + 260;
  for (const auto& [id, path] : pic.paths) {
    const char* colour = robot_colour(index++);
    if (path.size() > 1) {
      svg << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"2\" points=\"";
      for (const auto& p : path) svg << px(p.x()) << ',' << py(p.y()) << ' ';
      svg << "\"/>\n";
    }
    if (!path.empty())
      svg << "<circle cx=\"" << px(path.front().x()) << "\" cy=\"" << py(path.front().y())
          << "\" r=\"4\" fill=\"white\" stroke=\"" << colour << "\" stroke-width=\"2\"/>\n";
    auto robot = std::find_if(pic.final_robots.begin(), pic.final_robots.end(),
                              [&](const RobotStatus& r) { return r.id == id; });
    if (robot != pic.final_robots.end()) {
      const double x = robot->pose.x, y = robot->pose.y, th = robot->pose.theta;
      svg << "<circle cx=\"" << px(x) << "\" cy=\"" << py(y) << "\" r=\"" << robot->radius * scale << "\" fill=\""
          << colour << "\" fill-opacity=\"0.5\" stroke=\"" << colour << "\"/>\n";
      svg << "<line x1=\"" << px(x) << "\" y1=\"" << py(y) << "\" x2=\"" << px(x + robot->radius * std::cos(th))
          << "\" y2=\"" << py(y + robot->radius * std::sin(th)) << "\" stroke=\"black\"/>\n";
    }
    svg << "<rect x=\"" << legend_x << "\" y=\"" << margin - 6 << "\" width=\"12\" height=\"12\" fill=\"" << colour
        << "\"/><text x=\"" << legend_x + 16 << "\" y=\"" << margin + 4 << "\">" << escape(id) << "</text>\n";
    legend_x += 70;
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace autonomy::sim
