// The surface the simulator publishes as a function of a frame, shared by the height queries
// (queries.cpp) and the local surface (local_surface.cpp). Private to src/sim.
#pragma once

#include <array>

#include "ocean/sim.hpp"
#include "ocean/waves.hpp"

namespace ocean::detail {

/// (Dx, h, Dz) of the surface at the undisplaced point (x, z): every cascade of `frame` bilinear
/// with wrap (M.7.6), weighed by the damping's band weights when `damping` is set (W.13), plus
/// the layer at the frame's time when `layer` is set. Never allocates.
std::array<double, 3> surface_displacement(const Frame& frame, const waves::Damping* damping,
                                           const waves::LocalLayer* layer, double x, double z);

/// ∂(Dx, h, Dz)/∂t of the surface at the undisplaced point (x, z) (M.7.11): the cascades'
/// velocity arrays as surface_displacement weighs their displacement, plus the layer's (a central
/// difference in time). NaN when the frame carries no velocity. Never allocates.
std::array<double, 3> surface_velocity(const Frame& frame, const waves::Damping* damping,
                                       const waves::LocalLayer* layer, double x, double z);

/// Sizes `local` for the layer's area (allocates) and zeroes it.
void allocate_local_surface(const waves::LocalArea& area, LocalSurfaceFrame& local);

/// Computes frame.local (sized by allocate_local_surface) from the frame's cascades, the damping
/// and the layer (M.7.9): displacement at the cell centres, then normal, Jacobian and foam of the
/// sum, the foam accumulated from `previous`'s over dt_s (restarted when `reset_foam`); the
/// layer alone and the sea's normal and foam beside them (M.7.10). Never allocates.
void composite_local_surface(const SimulationPlan& plan, const waves::Damping* damping,
                             const waves::LocalLayer& layer, const LocalSurfaceFrame& previous,
                             double dt_s, bool reset_foam, Frame& frame, TaskRunner& runner);

}  // namespace ocean::detail
