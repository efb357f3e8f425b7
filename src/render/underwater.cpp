// The view from below the surface (ocean/underwater.hpp; docs/rendering.md R.50–R.52): the
// water's optics (checked in params.cpp with the rest of the view) handed to the shaders
// (FrameUniforms::underwater).
#include "underwater.hpp"

#include "ocean/underwater.hpp"
#include "state.hpp"

namespace ocean::render {

void UnderwaterPass::fill_uniforms(const Renderer::State& st, const View& view,
                                   shader::FrameUniforms& u) const {
  const auto& a = view.seabed.absorption_per_m;  // one water: the seabed's absorption (R.23)
  u.underwater = {.absorption_per_m = {static_cast<float>(a[0]), static_cast<float>(a[1]),
                                       static_cast<float>(a[2])},
                  .scattering_per_m = static_cast<float>(view.underwater.scattering_per_m),
                  .skirt_extent_m = static_cast<float>(skirt_extent_m(view, st.hs_m)),
                  .bed_enabled = view.seabed.enabled ? 1.0f : 0.0f,
                  .bed_albedo_depth = {static_cast<float>(view.seabed.albedo[0]),
                                       static_cast<float>(view.seabed.albedo[1]),
                                       static_cast<float>(view.seabed.albedo[2]),
                                       static_cast<float>(view.seabed.depth_m)}};
}

}  // namespace ocean::render
