#include "simulator/dds/radio_setup.hpp"

namespace autonomy::sim {

radio::RadioParameters radio_parameters(const RadioSettings& s) {
  radio::RadioParameters p;
  const auto set = [](double& target, const std::optional<double>& value) {
    if (value) target = *value;
  };
  set(p.tx_power_dbm, s.tx_power_dbm);
  set(p.frequency_hz, s.frequency_hz);
  p.distance_model = s.distance_model == RadioSettings::DistanceModel::ItuP1238 ? radio::DistanceModel::kItuP1238
                                                                                 : radio::DistanceModel::kLogDistance;
  set(p.reference_distance_m, s.reference_distance_m);
  set(p.reference_loss_db, s.reference_loss_db);
  set(p.path_loss_exponent, s.path_loss_exponent);
  set(p.p1238_power_loss_coefficient, s.p1238_power_loss_coefficient);
  set(p.p1238_floor_penetration_db, s.p1238_floor_penetration_db);
  set(p.receiver_sensitivity_dbm, s.receiver_sensitivity_dbm);
  set(p.wall_loss_db, s.wall_loss_db);
  set(p.inside_loss_db_per_m, s.inside_loss_db_per_m);
  set(p.delivery.good_margin_db, s.good_margin_db);
  set(p.delivery.loss_exponent, s.loss_exponent);
  set(p.delivery.base_delay_s, s.base_delay_s);
  set(p.delivery.per_hop_delay_s, s.per_hop_delay_s);
  set(p.delivery.weak_link_delay_s, s.weak_link_delay_s);
  set(p.delivery.jitter_s, s.jitter_s);
  return p;
}

radio::RadioModel make_radio_model(const Scenario& scenario) {
  const radio::RadioParameters params = radio_parameters(scenario.radio);
  std::vector<radio::Attenuator> attenuators = radio::obstacles_from_rects(scenario.world.obstacles, params);
  for (size_t i = 0; i < scenario.world.polygons.size(); ++i) {
    const Polygon& p = scenario.world.polygons[i];
    attenuators.push_back(radio::Attenuator::obstacle(radio::Shape::polygon(p.vertices), params,
                                                      p.name.empty() ? "polygon " + std::to_string(i) : p.name));
  }
  for (const auto& a : scenario.radio.areas)
    attenuators.push_back(
        radio::Attenuator::area(radio::Shape::polygon(a.vertices), a.entry_loss_db, a.loss_db_per_m, a.name));
  std::vector<radio::RasterAttenuator> rasters;
  for (const RasterLayer& layer : scenario.world.rasters)
    rasters.push_back(radio::RasterAttenuator::obstacle(layer.raster, params, layer.name));
  std::vector<radio::MovingWall> leaves;
  for (const DoorSpec& d : scenario.world.doors) {
    const DoorLeaf leaf = d.leaf(d.angle);
    leaves.push_back(radio::MovingWall::door_leaf(leaf.hinge, leaf.tip, d.width, params, "door " + d.id));
  }
  return radio::RadioModel(params, std::move(attenuators), std::move(rasters), std::move(leaves));
}

void sync_door_leaves(const std::vector<DoorStatus>& doors, radio::RadioModel& model) {
  for (size_t i = 0; i < doors.size() && i < model.walls().size(); ++i) {
    const radio::MovingWall& w = model.walls()[i];
    if (w.a != doors[i].leaf.hinge || w.b != doors[i].leaf.tip) model.move_wall(i, doors[i].leaf.hinge, doors[i].leaf.tip);
  }
}

}  // namespace autonomy::sim
