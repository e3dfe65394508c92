#include "simulator/report/run_svg.hpp"

#include <algorithm>
#include <cmath>
#include <locale>
#include <sstream>

namespace autonomy::sim {

namespace {

// Distinguishable colours for up to ten robots, then they repeat.
const char* robot_colour(size_t i) {
  static const char* kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                   "#17becf", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22"};
  return kPalette[i % (sizeof(kPalette) / sizeof(kPalette[0]))];
}

// Styles shared by the drawing and its legend.
const char* kAreaFill = "#ff9800";
const char* kAreaText = "#a35f00";
const char* kClosedDoor = "#8b0000";
const char* kOpenDoor = "#2e8b57";
const char* kPlaceStroke = "#607d8b";
const char* kDisconnectedDash = "5 4";

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
  const bool has_flags = std::any_of(pic.path_connected.begin(), pic.path_connected.end(), [&](const auto& f) {
    auto path = pic.paths.find(f.first);
    return path != pic.paths.end() && path->second.size() == f.second.size();
  });
  const bool second_legend_row = has_flags || !pic.doors.empty() || !pic.attenuating_areas.empty();

  // World metres to pixels; y flips so that +y points up as in the world frame.
  const double scale = std::clamp(900.0 / std::max(w.width, w.height), 0.5, 60.0);
  const double margin = 20.0, legend = second_legend_row ? 46.0 : 24.0;
  const double width_px = w.width * scale + 2 * margin;
  const double height_px = w.height * scale + 2 * margin + legend;
  auto px = [&](double x) { return margin + x * scale; };
  auto py = [&](double y) { return margin + legend + (w.height - y) * scale; };
  auto points = [&](const std::vector<geometry::Vec2>& pts) {
    std::ostringstream s;
    s.imbue(std::locale::classic());
    s.precision(6);
    for (const auto& p : pts) s << px(p.x()) << ',' << py(p.y()) << ' ';
    return s.str();
  };

  std::ostringstream svg;
  svg.imbue(std::locale::classic());
  svg.precision(6);
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width_px << "\" height=\"" << height_px
      << "\" font-family=\"sans-serif\" font-size=\"13\">\n";
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg << "<text x=\"" << margin << "\" y=\"" << margin + 4 << "\">" << escape(pic.caption) << "</text>\n";
  svg << "<rect x=\"" << px(0) << "\" y=\"" << py(w.height) << "\" width=\"" << w.width * scale << "\" height=\""
      << w.height * scale << "\" fill=\"#fafafa\" stroke=\"black\"/>\n";

  // Areas under everything else, so walls and paths stay readable through them.
  for (const auto& area : pic.attenuating_areas) {
    if (area.polygon.size() < 3) continue;
    svg << "<polygon points=\"" << points(area.polygon) << "\" fill=\"" << kAreaFill
        << "\" fill-opacity=\"0.22\" stroke=\"" << kAreaFill << "\" stroke-opacity=\"0.7\"/>\n";
    if (!area.name.empty()) {
      geometry::Vec2 c(0.0, 0.0);
      for (const auto& p : area.polygon) c += p;
      c /= static_cast<double>(area.polygon.size());
      svg << "<text x=\"" << px(c.x()) << "\" y=\"" << py(c.y()) << "\" font-size=\"10\" fill=\"" << kAreaText
          << "\" text-anchor=\"middle\">" << escape(area.name) << "</text>\n";
    }
  }
  for (const auto& r : w.obstacles)
    svg << "<rect x=\"" << px(r.min_x) << "\" y=\"" << py(r.max_y) << "\" width=\"" << (r.max_x - r.min_x) * scale
        << "\" height=\"" << (r.max_y - r.min_y) * scale << "\" fill=\"#555\"/>\n";
  for (const auto& polygon : pic.polygon_obstacles)
    if (polygon.size() >= 3) svg << "<polygon points=\"" << points(polygon) << "\" fill=\"#555\"/>\n";

  const double door_width = std::max(3.0, 0.12 * scale);
  for (const auto& d : pic.doors) {
    svg << "<line x1=\"" << px(d.a.x()) << "\" y1=\"" << py(d.a.y()) << "\" x2=\"" << px(d.b.x()) << "\" y2=\""
        << py(d.b.y()) << "\" stroke=\"" << (d.open ? kOpenDoor : kClosedDoor) << "\" stroke-width=\""
        << (d.open ? door_width * 0.5 : door_width) << '"' << (d.open ? " stroke-dasharray=\"3 3\"" : "")
        << " stroke-linecap=\"butt\"/>\n";
    if (!d.name.empty()) {
      const geometry::Vec2 m = 0.5 * (d.a + d.b);
      svg << "<text x=\"" << px(m.x()) + 4 << "\" y=\"" << py(m.y()) - 4 << "\" font-size=\"10\" fill=\""
          << (d.open ? kOpenDoor : kClosedDoor) << "\">" << escape(d.name) << "</text>\n";
    }
  }
  for (const auto& place : pic.places) {
    if (place.radius > 0.0)
      svg << "<circle cx=\"" << px(place.position.x()) << "\" cy=\"" << py(place.position.y()) << "\" r=\""
          << place.radius * scale << "\" fill=\"none\" stroke=\"" << kPlaceStroke
          << "\" stroke-dasharray=\"2 2\"/>\n";
    svg << "<text x=\"" << px(place.position.x()) << "\" y=\"" << py(place.position.y()) + 3
        << "\" font-size=\"10\" fill=\"" << kPlaceStroke << "\" text-anchor=\"middle\">" << escape(place.name)
        << "</text>\n";
  }

  size_t index = 0;
  double legend_x = margin + 260;
  for (const auto& [id, path] : pic.paths) {
    const char* colour = robot_colour(index++);
    auto flags_it = pic.path_connected.find(id);
    const std::vector<bool>* flags =
        flags_it != pic.path_connected.end() && flags_it->second.size() == path.size() ? &flags_it->second : nullptr;
    if (path.size() > 1 && !flags) {
      svg << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"2\" points=\"" << points(path)
          << "\"/>\n";
    } else if (path.size() > 1) {
      // Runs of segments with the same flag (the flag of each segment's end point) as one polyline.
      size_t k = 1;
      while (k < path.size()) {
        const bool connected = (*flags)[k];
        size_t end = k;
        while (end + 1 < path.size() && (*flags)[end + 1] == connected) ++end;
        const std::vector<geometry::Vec2> run(path.begin() + static_cast<long>(k - 1),
                                              path.begin() + static_cast<long>(end + 1));
        if (connected)
          svg << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"2\" points=\"" << points(run)
              << "\"/>\n";
        else
          svg << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"1.5\" stroke-opacity=\"0.55\""
              << " stroke-dasharray=\"" << kDisconnectedDash << "\" points=\"" << points(run) << "\"/>\n";
        k = end + 1;
      }
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

  for (const auto& m : pic.markers)
    svg << "<circle cx=\"" << px(m.position.x()) << "\" cy=\"" << py(m.position.y())
        << "\" r=\"9\" fill=\"white\" stroke=\"black\" stroke-width=\"1.5\"/><text x=\"" << px(m.position.x())
        << "\" y=\"" << py(m.position.y()) + 4 << "\" font-size=\"11\" font-weight=\"bold\" text-anchor=\"middle\">"
        << escape(m.label) << "</text>\n";

  // Second legend row: what the line styles, doors and areas mean (only those drawn).
  if (second_legend_row) {
    const double y = margin + 26;  // text baseline
    double x = margin;
    auto sample_line = [&](const std::string& attributes, const std::string& label) {
      svg << "<line x1=\"" << x << "\" y1=\"" << y - 4 << "\" x2=\"" << x + 26 << "\" y2=\"" << y - 4 << "\" "
          << attributes << "/><text x=\"" << x + 32 << "\" y=\"" << y << "\" font-size=\"11\">" << escape(label)
          << "</text>\n";
      x += 32 + 7.0 * static_cast<double>(label.size()) + 18;
    };
    if (has_flags) {
      sample_line("stroke=\"#333\" stroke-width=\"2\"", "connected to a teammate");
      sample_line(std::string("stroke=\"#333\" stroke-width=\"1.5\" stroke-opacity=\"0.55\" stroke-dasharray=\"") +
                      kDisconnectedDash + "\"",
                  "no teammate in reach");
    }
    if (std::any_of(pic.doors.begin(), pic.doors.end(), [](const PictureDoor& d) { return d.open; }))
      sample_line(std::string("stroke=\"") + kOpenDoor + "\" stroke-width=\"3\" stroke-dasharray=\"3 3\"",
                  "open door");
    if (std::any_of(pic.doors.begin(), pic.doors.end(), [](const PictureDoor& d) { return !d.open; }))
      sample_line(std::string("stroke=\"") + kClosedDoor + "\" stroke-width=\"5\"", "closed door");
    if (!pic.attenuating_areas.empty())
      svg << "<polygon points=\"" << x << ',' << y - 10 << ' ' << x + 26 << ',' << y - 10 << ' ' << x + 26 << ','
          << y + 2 << ' ' << x << ',' << y + 2 << "\" fill=\"" << kAreaFill << "\" fill-opacity=\"0.22\" stroke=\""
          << kAreaFill << "\"/><text x=\"" << x + 32 << "\" y=\"" << y
          << "\" font-size=\"11\">attenuating area</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace autonomy::sim
