// stn_tool FILE: the temporal network alone; prints every timepoint's bounds, or the line that
// closes a negative cycle (exit 1). Format: see stn_text.hpp.
#include <iostream>

#include "planner_language.hpp"
#include "stn_text.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: stn_tool FILE\n";
    return 2;
  }
  autonomy::planner::Diagnostics errors;
  auto text = autonomy::planner::read_text_file(argv[1], &errors);
  if (!text) {
    std::cerr << autonomy::planner::to_string(errors);
    return 2;
  }
  auto report = autonomy::planner::run_stn_text(*text, argv[1]);
  (report.ok && report.consistent ? std::cout : std::cerr)
      << report.text << (report.ok && report.consistent ? "" : "\n");
  return report.ok ? (report.consistent ? 0 : 1) : 2;
}
