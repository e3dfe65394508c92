#include "simulator/dds/map_message.hpp"

namespace autonomy::sim {

msg::WorldMap map_message(const WorldSpec& spec) {
  msg::WorldMap m{spec.name, spec.width, spec.height, spec.obstacles, {}, {}, {}};
  for (const Polygon& p : spec.polygons) {
    msg::MapPolygon out{p.name, {}};
    for (const auto& v : p.vertices) out.vertices.push_back({v.x(), v.y()});
    m.polygons.push_back(std::move(out));
  }
  for (const RasterLayer& layer : spec.rasters) {
    const grid::OccupancyRaster& r = *layer.raster;
    msg::MapRaster out{layer.name,
                       r.origin().x,
                       r.origin().y,
                       r.resolution_m(),
                       static_cast<uint32_t>(r.width()),
                       static_cast<uint32_t>(r.height()),
                       {}};
    out.blocked.resize(r.cell_count());
    for (int row = 0; row < r.height(); ++row) {
      for (int col = 0; col < r.width(); ++col) out.blocked[r.index({col, row})] = r.blocked({col, row}) ? 1 : 0;
    }
    m.rasters.push_back(std::move(out));
  }
  for (const DoorSpec& d : spec.doors) {
    // Where the leaf stands open: the angle a random door opens to, else the start angle of a
    // door that starts open, else its widest. Signed so that readers need not know DoorSwing.
    const double open = d.schedule.kind == DoorScheduleSpec::Kind::Random ? d.schedule.random.open_angle
                        : d.angle > 0.0                                    ? d.angle
                                                                           : d.max_angle;
    const double turn = d.swing == DoorSwing::CounterClockwise ? open : -open;
    m.doors.push_back({d.id, d.position.x(), d.position.y(), d.width, d.heading, turn});
  }
  return m;
}

}  // namespace autonomy::sim
