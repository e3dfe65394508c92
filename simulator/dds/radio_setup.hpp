#pragma once
// From a scenario to the simulator's radio: RadioSettings (absent values keep the radio model's
// defaults) onto radio::RadioParameters, and the world's rectangles and polygons plus the declared
// attenuating areas onto attenuators, its occupancy rasters onto raster attenuators (walls of
// blocked cells) and its door leaves onto moving walls (a wall crossing when a path crosses the
// leaf at its current angle; sync_door_leaves keeps them where the World's doors are).
#include "simulator/radio/radio_model.hpp"
#include "simulator/scenario/scenario_loader.hpp"

namespace autonomy::sim {

radio::RadioParameters radio_parameters(const RadioSettings& settings);
// Throws std::invalid_argument like RadioModel does when the parameters or a shape are unusable.
// Moving wall i is door i of scenario.world.doors, at the door's starting angle.
radio::RadioModel make_radio_model(const Scenario& scenario);
// Puts the model's door leaves where `doors` (World::doors(), in spec order) has them now.
void sync_door_leaves(const std::vector<DoorStatus>& doors, radio::RadioModel& model);

}  // namespace autonomy::sim
