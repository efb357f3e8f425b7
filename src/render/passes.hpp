// The renderer's passes (src/render, private), one object per feature (pass.hpp), in frame
// order: adding a feature is one line here. The shared state (state.hpp) holds them as a tuple;
// pass<P>(st) reaches one, for_each_pass(st, f) calls f on each in this order.
#pragma once

#include <tuple>
#include <utility>

#include "damping.hpp"
#include "far_map.hpp"
#include "local_layer.hpp"
#include "motion_pass.hpp"
#include "object_pass.hpp"
#include "post.hpp"
#include "seabed.hpp"
#include "sky_pass.hpp"
#include "sphere.hpp"
#include "stereo_pass.hpp"
#include "tessellation.hpp"
#include "underwater.hpp"

namespace ocean::render {

using Passes = std::tuple<SkyPass,  // the sky-view table and the environment map (R.1–R.4, R.17)
                          FarFieldPass,      // the far field and its noise map (R.13, R.13b)
                          LocalSurfacePass,  // the local layer (R.19)
                          DampingPass,       // the damping of the bands (R.24)
                          SpherePass,        // the sea on a sphere (R.30–R.38)
                          TessellationPass,  // the tessellated mesh (R.40–R.42)
                          SeabedPass,        // the seabed's push constants (R.22–R.23)
                          UnderwaterPass,    // the view from below the surface (R.50–R.52)
                          ObjectPass,        // the objects and their reflection (R.20–R.21, R.53)
                          StereoPass,        // both eyes in one multiview pass (R.25)
                          MotionPass,        // motion vectors (R.26)
                          PostPass>;         // the tone map into the sRGB target

}  // namespace ocean::render
