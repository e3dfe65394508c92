// courier_plot: pictures of a courier run from its scenario, the simulator's trajectory CSV and
// the courier's events file. Exit 2 on bad input, with file:line.
#include "simulator/scenario/scenario_loader.hpp"
#include "tools/courier_plot/courier_svg.hpp"

#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <sstream>

namespace {

using namespace autonomy;

struct BadInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string read(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw BadInput(path + ": cannot be read");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) throw std::runtime_error(path + ": cannot be written");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Pictures of a courier run: trajectory with the paper's numbered steps, and a Gantt of the "
      "jobs"};
  std::string scenario_path, trajectory_path, events_path, trajectory_svg_path, gantt_svg_path,
      caption;
  app.add_option("--scenario", scenario_path, "scenario file (protobuf text)")->required();
  app.add_option("--trajectory", trajectory_path, "simulator --trajectory CSV")->required();
  app.add_option("--events", events_path, "courier --events JSON lines")->required();
  app.add_option("--trajectory-svg", trajectory_svg_path, "write the trajectory picture here");
  app.add_option("--gantt-svg", gantt_svg_path, "write the job timeline here");
  app.add_option("--caption", caption, "title of both pictures");
  CLI11_PARSE(app, argc, argv);
  try {
    const auto scenario = sim::load_scenario_file(scenario_path);
    if (!scenario.ok()) throw BadInput(scenario.error_text());
    const auto trajectory =
        courier_plot::parse_trajectory_csv(read(trajectory_path), trajectory_path);
    if (trajectory.error) throw BadInput(*trajectory.error);
    const auto events = courier_plot::parse_events(read(events_path), events_path);
    if (events.error) throw BadInput(*events.error);
    const sim::Scenario& sc = *scenario.scenario;
    if (caption.empty()) caption = sc.world.name;

    if (!trajectory_svg_path.empty()) {
      sim::RunPicture picture;
      picture.world = &sc.world;
      picture.paths = trajectory.paths;
      picture.caption = caption;
      for (const auto& p : sc.world.polygons) picture.polygon_obstacles.push_back(p.vertices);
      // Doors as the courier saw them last (as the scenario starts them when never seen).
      for (const auto& d : sc.world.doors) {
        bool open = d.angle > 0.0;
        for (const auto& e : events.events)
          if ((e.kind == "door_closed" || e.kind == "door_opened") &&
              e.text.rfind(d.id + " ", 0) == 0)
            open = e.kind == "door_opened";
        picture.doors.push_back({d.leaf(open ? d.max_angle : 0.0).hinge,
                                 d.leaf(open ? d.max_angle : 0.0).tip, open, d.id});
      }
      for (const auto& r : sc.rooms)
        if (r.bounds && r.kind != "hallway")
          picture.places.push_back(
              {r.name, {0.5 * (r.bounds->min_x + r.bounds->max_x), r.bounds->max_y - 0.6}, 0.0});
      for (const auto& p : sc.places) picture.places.push_back({p.name, p.position, 0.3});
      const auto& [robot, path] = *trajectory.paths.begin();
      const auto steps = courier_plot::numbered_steps(events.events, path.front(), robot);
      write(trajectory_svg_path, courier_plot::trajectory_svg(picture, steps));
    }
    if (!gantt_svg_path.empty())
      write(gantt_svg_path,
            courier_plot::gantt_svg(courier_plot::job_timeline(events.events), caption));
  } catch (const BadInput& e) {
    std::cerr << "courier_plot: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "courier_plot: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
