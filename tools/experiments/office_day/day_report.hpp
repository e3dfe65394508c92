#pragma once
// The day-in-office experiment's report: per strategy the mean and standard deviation of each
// metric over its days, the findings as Welch t-tests between strategies (tools/experiments/
// stats), and pictures: the on-time rate per strategy, and per day (learning should climb).
// Pure: records in, Markdown and SVG out.
#include <string>
#include <vector>

#include "tools/experiments/office_day/day_record.hpp"

namespace autonomy::office_day {

struct Finding {
  std::string claim;
  std::string here;     // means and the test
  bool evaluated = false;
  bool holds = false;   // the means differ in the claim's direction with p < 0.05
};

std::vector<Finding> findings(const std::vector<DayRecord>& records);
std::string write_report(const std::vector<DayRecord>& records, const std::string& title,
                         const std::vector<std::string>& notes);
std::string on_time_svg(const std::vector<DayRecord>& records);
std::string on_time_by_day_svg(const std::vector<DayRecord>& records);

}  // namespace autonomy::office_day
