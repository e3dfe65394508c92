#include "tools/courier_plot/courier_svg.hpp"

#include <algorithm>
#include <cmath>
#include <locale>
#include <regex>
#include <sstream>

namespace autonomy::courier_plot {

namespace {

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::ostringstream svg_stream() {
  std::ostringstream s;
  s.imbue(std::locale::classic());
  s.precision(6);
  return s;
}

const char* phase_colour(Phase p) {
  switch (p) {
    case Phase::Waiting:
      return "#cfd8dc";
    case Phase::Carried:
      return "#1f77b4";
    case Phase::Opportunistic:
      return "#ff9800";
    case Phase::Returning:
      return "#8b0000";
  }
  return "#000";
}

}  // namespace

std::string trajectory_svg(sim::RunPicture picture, const std::vector<Step>& steps) {
  // Steps at one spot (a door seen closed where the robot then turns) are spread sideways so
  // every number stays readable.
  std::vector<geometry::Vec2> placed;
  const double scale =
      std::clamp(900.0 / std::max(picture.world->width, picture.world->height), 0.5, 60.0);
  const double spread_m = 20.0 / scale;
  for (const auto& s : steps) {
    if (!s.has_position) continue;
    geometry::Vec2 p = s.position;
    while (std::any_of(placed.begin(), placed.end(),
                       [&](const geometry::Vec2& q) { return (q - p).norm() < spread_m; }))
      p.x() += spread_m;
    placed.push_back(p);
    picture.markers.push_back({p, std::to_string(s.number)});
  }
  const std::string floor = sim::render_run_svg(picture);
  std::smatch m;
  double width = 900, height = 600;
  if (std::regex_search(floor, m, std::regex(R"re(width="([0-9.]+)" height="([0-9.]+)")re"))) {
    width = std::stod(m[1]);
    height = std::stod(m[2]);
  }
  size_t lines = 0;
  for (const auto& s : steps) lines += s.lines.size();
  const double line_h = 17.0, legend_h = 16.0 + line_h * static_cast<double>(lines);
  auto svg = svg_stream();
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\""
      << height + legend_h
      << "\" font-family=\"sans-serif\" font-size=\"13\">\n<rect width=\"100%\" height=\"100%\" "
         "fill=\"white\"/>\n";
  // The floor picture as it is, nested (its own coordinates stay valid).
  const size_t body = floor.find("<svg");
  svg << floor.substr(body);
  double y = height + 12.0;
  for (const auto& s : steps) {
    bool first = true;
    for (const auto& l : s.lines) {
      svg << "<text x=\"20\" y=\"" << y << "\" font-weight=\"bold\">"
          << (first ? std::to_string(s.number) : "") << "</text><text x=\"48\" y=\"" << y << "\">"
          << escape(l.time) << "</text><text x=\"120\" y=\"" << y << "\">" << escape(l.text)
          << "</text>\n";
      first = false;
      y += line_h;
    }
  }
  svg << "</svg>\n";
  return svg.str();
}

std::string gantt_svg(const Timeline& t, const std::string& caption) {
  const double left = 90, right = 430, top = 60, row_h = 46, width_px = 1100;
  const double plot_w = width_px - left - right;
  const double span = std::max(1.0, t.end_s - t.start_s);
  auto x = [&](double s) { return left + (s - t.start_s) / span * plot_w; };
  const double rows_bottom = top + row_h * static_cast<double>(std::max<size_t>(1, t.jobs.size()));
  const double height_px = rows_bottom + 70;
  auto svg = svg_stream();
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width_px << "\" height=\""
      << height_px
      << "\" font-family=\"sans-serif\" font-size=\"13\">\n<rect width=\"100%\" height=\"100%\" "
         "fill=\"white\"/>\n";
  svg << "<text x=\"20\" y=\"22\">" << escape(caption) << "</text>\n";
  // Legend of the phases.
  double lx = 20;
  for (Phase p : {Phase::Waiting, Phase::Carried, Phase::Opportunistic, Phase::Returning}) {
    svg << "<rect x=\"" << lx << "\" y=\"32\" width=\"14\" height=\"10\" fill=\"" << phase_colour(p)
        << "\"/><text x=\"" << lx + 18 << "\" y=\"42\" font-size=\"11\">" << phase_name(p)
        << "</text>\n";
    lx += 30 + 7.0 * std::string(phase_name(p)).size() + 10;
  }
  // Time axis: ticks every 10, 15, 30 or 60 s, whichever gives at most 12.
  double step = 10;
  for (double s : {10.0, 15.0, 30.0, 60.0, 120.0, 300.0}) {
    step = s;
    if (span / s <= 12) break;
  }
  svg << "<line x1=\"" << left << "\" y1=\"" << rows_bottom << "\" x2=\"" << left + plot_w
      << "\" y2=\"" << rows_bottom << "\" stroke=\"black\"/>\n";
  for (double s = std::ceil(t.start_s / step) * step; s <= t.end_s + 1e-9; s += step) {
    svg << "<line x1=\"" << x(s) << "\" y1=\"" << top - 6 << "\" x2=\"" << x(s) << "\" y2=\""
        << rows_bottom + 4 << "\" stroke=\"#eee\"/><text x=\"" << x(s) << "\" y=\""
        << rows_bottom + 18 << "\" font-size=\"10\" text-anchor=\"middle\">"
        << clock_text(t.clock_offset_s + s) << "</text>\n";
  }
  // Rows.
  for (size_t i = 0; i < t.jobs.size(); ++i) {
    const JobRow& r = t.jobs[i];
    const double y0 = top + row_h * static_cast<double>(i);
    svg << "<text x=\"10\" y=\"" << y0 + 18 << "\" font-weight=\"bold\">" << escape(r.id)
        << "</text><text x=\"10\" y=\"" << y0 + 33 << "\" font-size=\"10\">" << escape(r.object)
        << "</text>\n";
    for (const auto& b : r.bars) {
      // Opportunistic is a state beside the others (the object may be aboard): a thin band below.
      const bool band = b.phase == Phase::Opportunistic;
      const double by = band ? y0 + 30 : y0 + 8, bh = band ? 8 : 20;
      svg << "<rect x=\"" << x(b.from_s) << "\" y=\"" << by << "\" width=\""
          << std::max(1.0, x(b.to_s) - x(b.from_s)) << "\" height=\"" << bh << "\" fill=\""
          << phase_colour(b.phase) << "\"><title>" << phase_name(b.phase) << ' '
          << clock_text(t.clock_offset_s + b.from_s) << "-" << clock_text(t.clock_offset_s + b.to_s)
          << "</title></rect>\n";
    }
    svg << "<text x=\"" << left + plot_w + 10 << "\" y=\"" << y0 + 22
        << "\" font-size=\"11\" fill=\"" << (r.failed ? "#8b0000" : "#1b5e20") << "\">"
        << escape(r.outcome) << "</text>\n";
  }
  // Door events across all rows.
  for (size_t k = 0; k < t.doors.size(); ++k) {
    const DoorMark& d = t.doors[k];
    const char* colour = d.open ? "#2e8b57" : "#8b0000";
    svg << "<line x1=\"" << x(d.at_s) << "\" y1=\"" << top - 4 << "\" x2=\"" << x(d.at_s)
        << "\" y2=\"" << rows_bottom << "\" stroke=\"" << colour
        << "\" stroke-dasharray=\"4 3\"/><text x=\"" << x(d.at_s) << "\" y=\""
        << rows_bottom + 34 + 14.0 * static_cast<double>(k % 2)
        << "\" font-size=\"10\" text-anchor=\"middle\" fill=\"" << colour << "\">" << escape(d.door)
        << (d.open ? " open " : " closed ") << clock_text(t.clock_offset_s + d.at_s) << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace autonomy::courier_plot
