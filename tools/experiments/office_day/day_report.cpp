#include "tools/experiments/office_day/day_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <sstream>

#include "tools/experiments/office_day/strategy.hpp"
#include "tools/experiments/stats/stats.hpp"

namespace autonomy::office_day {

namespace {

using Get = std::function<double(const DayRecord&)>;

std::vector<double> values(const std::vector<DayRecord>& records, const std::string& strategy, const Get& get,
                           int from_day = 0, int to_day = 1 << 30) {
  std::vector<double> out;
  for (const DayRecord& r : records)
    if (r.strategy == strategy && r.day >= from_day && r.day <= to_day) out.push_back(get(r));
  return out;
}

std::string num(double v, int decimals = 1) {
  char s[32];
  std::snprintf(s, sizeof s, "%.*f", decimals, v);
  return s;
}

std::string mean_sd(const std::vector<double>& v, int decimals = 1) {
  if (v.empty()) return "-";
  return num(stats::mean(v), decimals) + " ± " + num(stats::sample_stddev(v), decimals);
}

// `better` holds when mean(a) - mean(b) has the sign `a_higher` asks for and p < 0.05.
Finding compare(const std::string& claim, const std::vector<double>& a, const std::vector<double>& b,
                const std::string& a_name, const std::string& b_name, const std::string& unit, bool a_higher) {
  Finding f;
  f.claim = claim;
  const stats::WelchResult w = stats::welch_t_test(a, b);
  f.evaluated = w.valid;
  if (!w.valid) {
    f.here = "needs two days of each (" + std::to_string(a.size()) + " and " + std::to_string(b.size()) + ")";
    return f;
  }
  const double ma = stats::mean(a), mb = stats::mean(b);
  f.holds = (a_higher ? ma > mb : ma < mb) && w.p < 0.05;
  f.here = a_name + " " + num(ma) + unit + " vs " + b_name + " " + num(mb) + unit + ": t = " + num(w.t, 2) +
           ", df = " + num(w.df, 1) + ", p = " + (w.p < 0.001 ? std::string("< 0.001") : num(w.p, 3));
  return f;
}

const Get kOnTime = [](const DayRecord& r) { return r.on_time_percent; };
const Get kLateness = [](const DayRecord& r) { return r.mean_lateness_s / 60.0; };

int max_day(const std::vector<DayRecord>& records, const std::string& strategy) {
  int n = 0;
  for (const DayRecord& r : records)
    if (r.strategy == strategy) n = std::max(n, r.day);
  return n;
}

}  // namespace

std::vector<Finding> findings(const std::vector<DayRecord>& records) {
  std::vector<Finding> out;
  out.push_back(compare("monitoring + opportunism beats waiting at closed doors (on-time rate, b > a)",
                        values(records, "b", kOnTime), values(records, "a", kOnTime), "b", "a", " %", true));
  out.push_back(compare("exact scheduling beats the paper's heuristic on lateness (mean lateness, c < b)",
                        values(records, "c", kLateness), values(records, "b", kLateness), "c", "b", " min", false));
  out.push_back(compare("learning improves the on-time rate (d > c)", values(records, "d", kOnTime),
                        values(records, "c", kOnTime), "d", "c", " %", true));
  const int days = max_day(records, "d");
  out.push_back(compare("learning improves from day to day (d: second half of the days > first half)",
                        values(records, "d", kOnTime, days / 2 + 1, days), values(records, "d", kOnTime, 1, days / 2),
                        "late days", "early days", " %", true));
  out.push_back(compare("three couriers keep more deadlines than one (e > d)", values(records, "e", kOnTime),
                        values(records, "d", kOnTime), "e", "d", " %", true));
  return out;
}

std::string write_report(const std::vector<DayRecord>& records, const std::string& title,
                         const std::vector<std::string>& notes) {
  std::ostringstream md;
  md << "# " << title << "\n\n";
  for (const std::string& n : notes) md << n << "\n";
  md << "\n| strategy | | days | jobs | on time % | possible on time % | on time of possible % | mean lateness min | max lateness min | distance m | "
        "door blocks | door wait min | refused handovers | reschedules | opportunities | wall s |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Strategy& s : strategies()) {
    const auto v = [&](const Get& g, int d = 1) { return mean_sd(values(records, s.id, g), d); };
    const std::size_t days = values(records, s.id, kOnTime).size();
    if (days == 0) continue;
    md << "| " << s.id << " | " << s.label << " | " << days << " | " << v([](auto& r) { return r.jobs; })
       << " | " << v(kOnTime) << " | " << v([](auto& r) { return r.possible_percent; }) << " | "
       << v([](auto& r) { return r.possible_on_time ? 100.0 * r.on_time / r.possible_on_time : 0.0; }) << " | "
       << v(kLateness) << " | "
       << v([](auto& r) { return r.max_lateness_s / 60; }) << " | " << v([](auto& r) { return r.distance_m; }, 0)
       << " | " << v([](auto& r) { return r.counts.door_blocks; }) << " | "
       << v([](auto& r) { return r.counts.door_wait_s / 60; }) << " | "
       << v([](auto& r) { return r.counts.handover_refusals; }) << " | "
       << v([](auto& r) { return r.counts.reschedules; }) << " | "
       << v([](auto& r) { return r.counts.opportunities; }) << " | " << v([](auto& r) { return r.wall_s; }) << " |\n";
  }
  md << "\nMean ± sample standard deviation over the days. Lateness counts every job; one not done by the "
        "day's end is late by then. Possible on time: the jobs an ideal fleet could have finished by "
        "their deadline with the doors as they were and the people's hours (on_time_bound.hpp), the ceiling of "
        "the on-time rate; on time of possible: the part of that ceiling reached.\n\n## Findings (two-sided Welch t-tests)\n\n| claim | here | holds |\n|---|---|---|\n";
  for (const Finding& f : findings(records))
    md << "| " << f.claim << " | " << f.here << " | " << (!f.evaluated ? "not tested" : f.holds ? "yes" : "no")
       << " |\n";
  return md.str();
}

namespace {

const std::map<std::string, std::string> kColours = {
    {"a", "#999999"}, {"b", "#e6a23c"}, {"c", "#409eff"}, {"d", "#67c23a"}, {"e", "#8e44ad"}};

std::string colour(const std::string& s) {
  const auto it = kColours.find(s);
  return it == kColours.end() ? "#333333" : it->second;
}

}  // namespace

std::string on_time_svg(const std::vector<DayRecord>& records) {
  const double w = 560, h = 300, left = 50, bottom = 250, top = 30, bar = 60;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << left << "\" y=\"18\" font-size=\"14\">On-time rate per strategy (mean ± sd over the days)</text>\n";
  const auto y = [&](double percent) { return bottom - (bottom - top) * percent / 100.0; };
  for (int p = 0; p <= 100; p += 25)
    svg << "<line x1=\"" << left << "\" x2=\"" << w - 10 << "\" y1=\"" << y(p) << "\" y2=\"" << y(p)
        << "\" stroke=\"#eeeeee\"/><text x=\"" << left - 8 << "\" y=\"" << y(p) + 4 << "\" text-anchor=\"end\">" << p
        << "</text>\n";
  double x = left + 20;
  for (const Strategy& s : strategies()) {
    const auto v = values(records, s.id, kOnTime);
    if (v.empty()) continue;
    const double m = stats::mean(v), sd = stats::sample_stddev(v);
    svg << "<rect x=\"" << x << "\" y=\"" << y(m) << "\" width=\"" << bar << "\" height=\"" << bottom - y(m)
        << "\" fill=\"" << colour(s.id) << "\"/>\n<line x1=\"" << x + bar / 2 << "\" x2=\"" << x + bar / 2
        << "\" y1=\"" << y(std::min(100.0, m + sd)) << "\" y2=\"" << y(std::max(0.0, m - sd))
        << "\" stroke=\"black\"/>\n<text x=\"" << x + bar / 2 << "\" y=\"" << bottom + 16
        << "\" text-anchor=\"middle\">(" << s.id << ") " << num(m) << " %</text>\n";
    x += bar + 40;
  }
  svg << "</svg>\n";
  return svg.str();
}

std::string on_time_by_day_svg(const std::vector<DayRecord>& records) {
  const double w = 560, h = 300, left = 50, right = 20, bottom = 250, top = 40;
  int days = 1;
  for (const DayRecord& r : records) days = std::max(days, r.day);
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << left << "\" y=\"18\" font-size=\"14\">On-time rate by day (the same days for every strategy)</text>\n";
  const auto y = [&](double percent) { return bottom - (bottom - top) * percent / 100.0; };
  const auto x = [&](int day) { return left + (w - left - right) * (days == 1 ? 0.5 : (day - 1.0) / (days - 1.0)); };
  for (int p = 0; p <= 100; p += 25)
    svg << "<line x1=\"" << left << "\" x2=\"" << w - right << "\" y1=\"" << y(p) << "\" y2=\"" << y(p)
        << "\" stroke=\"#eeeeee\"/><text x=\"" << left - 8 << "\" y=\"" << y(p) + 4 << "\" text-anchor=\"end\">" << p
        << "</text>\n";
  for (int d = 1; d <= days; ++d)
    svg << "<text x=\"" << x(d) << "\" y=\"" << bottom + 16 << "\" text-anchor=\"middle\">" << d << "</text>\n";
  double legend = left;
  for (const Strategy& s : strategies()) {
    std::string points;
    for (const DayRecord& r : records)
      if (r.strategy == s.id) points += num(x(r.day)) + "," + num(y(r.on_time_percent)) + " ";
    if (points.empty()) continue;
    svg << "<polyline fill=\"none\" stroke=\"" << colour(s.id) << "\" stroke-width=\"2\" points=\"" << points
        << "\"/>\n<text x=\"" << legend << "\" y=\"34\" fill=\"" << colour(s.id) << "\">(" << s.id << ")</text>\n";
    legend += 40;
  }
  svg << "<text x=\"" << w / 2 << "\" y=\"" << bottom + 34 << "\" text-anchor=\"middle\">day</text>\n</svg>\n";
  return svg.str();
}

}  // namespace autonomy::office_day
