#pragma once
// The two pictures of a courier run, as SVG documents (pure: strings out).
//   trajectory: the floor and the path (simulator/report/run_svg), a numbered marker per step,
//               and below it a legend "N  HH:MM:SS  sentence" per step line;
//   gantt:      one row per job with its phase bars on an office-clock axis, door events as
//               vertical marks, the job's outcome at the end of its row.
#include "simulator/report/run_svg.hpp"
#include "tools/courier_plot/courier_story.hpp"

#include <string>
#include <vector>

namespace autonomy::courier_plot {

// `picture` holds floor, doors, places and paths; the steps become its markers.
std::string trajectory_svg(sim::RunPicture picture, const std::vector<Step>& steps);

std::string gantt_svg(const Timeline& timeline, const std::string& caption);

}  // namespace autonomy::courier_plot
