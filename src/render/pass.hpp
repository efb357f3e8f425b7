// The common shape of a renderer feature (src/render, private): a pass owns its pipelines,
// descriptors and resources and is called by the renderer at fixed points of its life and of the
// recorded frame. Every hook has a do-nothing default; a pass declares only those it needs, and
// the renderer calls them on the concrete type (no virtual dispatch): passes.hpp lists the passes
// in frame order, for_each_pass walks that list. A pass is a header and a source, or one header
// whose hooks are templates on the state (`template <class State> Status create(State& st)`),
// instantiated where the renderer calls them, with the state complete (temporal.hpp).
//
//   create(st)                  at Renderer::make, after the shared state: pipelines, samplers,
//                               the 1×1 images that keep the scene set valid
//   destroy(st)                 when the renderer goes (the device is idle)
//   resize(st)                  after the targets were made at a new size (st.hdr.width/height)
//   release_targets(st)         before the targets go (a resize, the renderer's end)
//   scene_images(st, images)    the scene set's bindings the pass owns, with their stages and
//                               images: descriptors.cpp builds the set's layout from them (before
//                               create) and writes them with the shared ones whenever one changes
//   fill_uniforms(st, view, u)  the pass's part of the frame's FrameUniforms
//   upload(st, cmd)             before the scene: staged uploads and compute of the frame
//   record(st, cmd, frame)      its draws, at the pass's point of the frame (frame.cpp)
//   check(st, view)             before a mono or stereo frame is recorded: the view's fields the
//                               pass reads, invalid_argument/unsupported naming them
//   after_scene(st, cmd, frame) after the HDR pass and the motion vectors of a mono frame, before
//                               the tone map: st.hdr is in COLOR_ATTACHMENT_OPTIMAL with its
//                               writes done, and is left so (its new writes made available)
#pragma once

#include <array>
#include <cstdint>

#include "ocean/render.hpp"
#include "shaders/render_shared.h"

namespace ocean::render {

// The images of the scene set (shaders/render_shared.h's OCEAN_RENDER_BINDING_*) that the passes
// own, gathered for the set's layout and for one vkUpdateDescriptorSets; no allocation.
struct SceneImages {
  // The stages that place the surface (vertex, tessellation evaluation where the device has it)
  // and shade it: what a binding the displacement reads needs.
  VkShaderStageFlags surface_stages = 0;
  std::array<std::uint32_t, OCEAN_RENDER_SCENE_BINDINGS> bindings{};
  std::array<VkShaderStageFlags, OCEAN_RENDER_SCENE_BINDINGS> stages{};
  std::array<VkDescriptorImageInfo, OCEAN_RENDER_SCENE_BINDINGS> infos{};
  std::uint32_t count = 0;
  void add(std::uint32_t binding, VkShaderStageFlags binding_stages, VkDescriptorImageInfo info) {
    bindings[count] = binding;
    stages[count] = binding_stages;
    infos[count] = info;
    ++count;
  }
};

// What a pass records with: the frame's view, its statistics and the skirt's instance index.
struct FrameContext {
  const View& view;
  RenderStats& stats;
  std::uint32_t skirt_instance = 0;
  int eyes = 1;  // 2: a stereo frame, the eyes side by side in the HDR image (R.25)
};

// The hooks' defaults (see above); a pass derives from it and hides the ones it implements.
struct Pass {
  Status create(Renderer::State&) { return {}; }
  void destroy(Renderer::State&) {}
  Status resize(Renderer::State&) { return {}; }
  void release_targets(Renderer::State&) {}
  void scene_images(const Renderer::State&, SceneImages&) const {}
  void fill_uniforms(const Renderer::State&, const View&, shader::FrameUniforms&) const {}
  void upload(Renderer::State&, VkCommandBuffer) {}
  void record(Renderer::State&, VkCommandBuffer, const FrameContext&) {}
  Status check(const Renderer::State&, const View&) const { return {}; }
  Status after_scene(Renderer::State&, VkCommandBuffer, const FrameContext&) { return {}; }
};

}  // namespace ocean::render
