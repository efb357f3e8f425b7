// The parts of the ocean._ocean extension module, one function per file that adds its names.
#pragma once

#include <pybind11/pybind11.h>

#include "ocean/sim.hpp"

namespace ocean::python {

void bind_spectrum(pybind11::module_& m);   // spectrum.cpp
void bind_sea_state(pybind11::module_& m);  // sea_state.cpp
void bind_preset(pybind11::module_& m);     // preset.cpp
void bind_simulator(pybind11::module_& m);  // simulator.cpp
void bind_bake(pybind11::module_& m);       // bake.cpp

/// The configuration of a Python preset argument: a Preset object, or a built-in name or a preset
/// file as `--preset` takes it; None is SimulationConfig's defaults. Raises as Preset does.
SimulationConfig config_of(const pybind11::object& preset);

}  // namespace ocean::python
