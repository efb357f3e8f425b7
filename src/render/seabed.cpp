// The seabed's push constants (docs/rendering.md R.22–R.23): View::seabed as the ocean
// pipeline's SeabedPush (shaders/seabed_shared.h), written over the sky pass's push range.
#include "seabed.hpp"

#include "shaders/seabed_shared.h"
#include "state.hpp"

namespace ocean::render {

void SeabedPass::record(Renderer::State& st, VkCommandBuffer cmd, const FrameContext& frame) {
  const Seabed& s = frame.view.seabed;
  const auto f = [](double v) { return static_cast<float>(v); };
  const shader::SeabedPush push{
      .absorption_enabled = {f(s.absorption_per_m[0]), f(s.absorption_per_m[1]),
                             f(s.absorption_per_m[2]), s.enabled ? 1.0f : 0.0f},
      .albedo_depth = {f(s.albedo[0]), f(s.albedo[1]), f(s.albedo[2]), f(s.depth_m)},
      .pattern = {f(s.period_m),
                  f(s.pattern == SeabedPattern::checker ? OCEAN_SEABED_CHECKER : OCEAN_SEABED_SAND),
                  0.0f, 0.0f}};
  vkCmdPushConstants(cmd, st.scene_pipeline_layout, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(push),
                     &push);
}

}  // namespace ocean::render
