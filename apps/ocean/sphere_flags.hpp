// The flags of the sea on a sphere, shared by `ocean render` and `ocean view` through the view
// flags: --sphere selects it, --latitude/--longitude name the surface point whose local axes
// (east, up, north) --camera and --target then use, --altitude puts the eye that high above it.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "ocean/render.hpp"

namespace ocean::cli {

struct SphereFlags {
  bool enabled = false;         // --sphere
  std::string latitude = "0";   // degrees, [-90, 90]
  std::string longitude = "0";  // degrees
  std::string altitude;         // m; empty: --camera's Y
};
void add_sphere_flags(CLI::App& command, SphereFlags& flags);
/// Fills view.sphere (and the camera's height for --altitude) when --sphere is given; checks
/// the latitude, the longitude and that the camera is outside the planet. Call it after the
/// camera and the planet's radius are in `view`. Without --sphere, --latitude, --longitude and
/// --altitude are refused.
Status parse_sphere_flags(const SphereFlags& flags, render::View& view);

}  // namespace ocean::cli
