#pragma once
// From a scenario to the simulator's radio: RadioSettings (absent values keep the radio model's
// defaults) onto radio::RadioParameters, and the world's rectangles and polygons plus the declared
// attenuating areas onto attenuators. Occupancy rasters and door leaves do not attenuate.
#include "simulator/radio/radio_model.hpp"
#include "simulator/scenario/scenario_loader.hpp"

namespace autonomy::sim {

radio::RadioParameters radio_parameters(const RadioSettings& settings);
// Throws std::invalid_argument like RadioModel does when the parameters or a shape are unusable.
radio::RadioModel make_radio_model(const Scenario& scenario);

}  // namespace autonomy::sim
