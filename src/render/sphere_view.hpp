// The view of a sphere (src/render, private; docs/rendering.md R.30, R.38): the local axes of
// the surface point a SphereView names and the camera's planet-centred position. No device
// work, so that the flag parsers' fuzz target links it alone.
#pragma once

#include "ocean/render.hpp"

namespace ocean::render {

// The local axes (east, up, north) of (latitude, longitude) as rows in planet axes:
// Paleologue's t₁, n and −t₂ (R.30).
struct LocalAxes {
  lod::Vec3 rows[3];
  // Planet axes → local axes.
  lod::Vec3 apply(lod::Vec3 p) const;
  // Local axes → planet axes.
  lod::Vec3 to_planet(lod::Vec3 l) const;
};
LocalAxes local_axes(const SphereView& sphere);
// The camera's planet-centred position: R·n + the view's camera in the local axes.
lod::Vec3 camera_planet(const View& view, const LocalAxes& axes);

}  // namespace ocean::render
