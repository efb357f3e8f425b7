// The far field's per-frame noise map as the renderer samples it (docs/rendering.md R.13b): the
// frame's float3 map (Frame::far_noise, uploaded; or the Vulkan backend's buffer, read where it
// lies) turned on the device into an RGBA16F image of (h, ∂h/∂x, ∂h/∂z, |∇h|²) of the octaves it
// resolves, with its mip chain, and the uniforms that place the map's window and the noise's
// lattice at the frame's origin and time.
//
// This work is based on: VR-GIS FFT+Perlin, §III (the noise height and normal maps the renderer
// reads); Olano, M. & Baker, D. (2010) "LEAN mapping" (the first and second moments of the slope
// filtered together, so the variance the mips remove becomes roughness).
#include "far_map.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <string>

#include "sim/far_noise.h"
#include "spirv.hpp"
#include "state.hpp"

OCEAN_RENDER_SPIRV(far_map)  // the map into its image (shaders/far_map.comp)

namespace ocean::render {

namespace {

constexpr VkFormat kFarMapFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

void write_source(FarFieldPass& pass, const vk::Context& ctx, VkBuffer buffer, VkDeviceSize bytes) {
  const VkDescriptorBufferInfo info{buffer, 0, bytes};
  const VkWriteDescriptorSet write{.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                                   .dstSet = pass.set,
                                   .dstBinding = OCEAN_RENDER_FAR_BINDING_SOURCE,
                                   .descriptorCount = 1,
                                   .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                   .pBufferInfo = &info};
  vkUpdateDescriptorSets(ctx.device, 1, &write, 0, nullptr);
  pass.bound = buffer;
}

// The image (and the upload path's source buffer) for an N × N map; the old ones are destroyed.
Status allocate_far_map(Renderer::State& st, std::uint32_t side) {
  FarFieldPass& pass = render::pass<FarFieldPass>(st);
  vkDeviceWaitIdle(st.ctx->device);
  vk::destroy_image(*st.ctx, pass.image);
  vk::destroy_buffer(*st.ctx, pass.source);
  pass.side = 0;
  pass.bound = VK_NULL_HANDLE;
  const auto mips = static_cast<std::uint32_t>(std::bit_width(side));  // ⌊log2 N⌋ + 1
  Result<vk::Image> image =
      vk::create_image_array(*st.ctx, kFarMapFormat, side, 1, mips,
                             VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                                 VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  if (!image.ok()) return image.status();
  pass.image = image.value();
  const VkDeviceSize bytes = VkDeviceSize{12} * side * side;
  Result<vk::Buffer> source =
      vk::create_buffer(*st.ctx, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::upload);
  if (!source.ok()) return source.status();
  pass.source = source.value();
  std::memset(pass.source.mapped, 0, bytes);
  pass.side = side;
  const VkDescriptorImageInfo level0{VK_NULL_HANDLE, pass.image.mip_views[0],
                                     VK_IMAGE_LAYOUT_GENERAL};
  const VkWriteDescriptorSet write{.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                                   .dstSet = pass.set,
                                   .dstBinding = OCEAN_RENDER_FAR_BINDING_IMAGE,
                                   .descriptorCount = 1,
                                   .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                                   .pImageInfo = &level0};
  vkUpdateDescriptorSets(st.ctx->device, 1, &write, 0, nullptr);
  write_source(pass, *st.ctx, pass.source.buffer, bytes);
  pass.pending = true;
  write_scene_images(st);
  return {};
}

Status create_layouts(FarFieldPass& pass, const vk::Context& ctx) {
  const VkDescriptorSetLayoutBinding bindings[2] = {
      {OCEAN_RENDER_FAR_BINDING_SOURCE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
       VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
      {OCEAN_RENDER_FAR_BINDING_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1,
       VK_SHADER_STAGE_COMPUTE_BIT, nullptr}};
  const VkDescriptorSetLayoutCreateInfo set_info{
      .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
      .bindingCount = 2,
      .pBindings = bindings};
  if (Status s =
          vk::check(vkCreateDescriptorSetLayout(ctx.device, &set_info, nullptr, &pass.set_layout),
                    "vkCreateDescriptorSetLayout");
      !s.ok())
    return s;
  const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(noise::FarNoiseMapParams)};
  const VkPipelineLayoutCreateInfo layout_info{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
      .setLayoutCount = 1,
      .pSetLayouts = &pass.set_layout,
      .pushConstantRangeCount = 1,
      .pPushConstantRanges = &push};
  if (Status s = vk::check(vkCreatePipelineLayout(ctx.device, &layout_info, nullptr, &pass.layout),
                           "vkCreatePipelineLayout");
      !s.ok())
    return s;
  const VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1},
                                         {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1}};
  const VkDescriptorPoolCreateInfo pool_info{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                             .maxSets = 1,
                                             .poolSizeCount = 2,
                                             .pPoolSizes = sizes};
  if (Status s = vk::check(vkCreateDescriptorPool(ctx.device, &pool_info, nullptr, &pass.pool),
                           "vkCreateDescriptorPool");
      !s.ok())
    return s;
  const VkDescriptorSetAllocateInfo alloc{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                          .descriptorPool = pass.pool,
                                          .descriptorSetCount = 1,
                                          .pSetLayouts = &pass.set_layout};
  return vk::check(vkAllocateDescriptorSets(ctx.device, &alloc, &pass.set),
                   "vkAllocateDescriptorSets");
}

// Checks a frame's map against what the renderer takes.
Status check_map(const FarNoiseFrame& map) {
  if (map.resolution == 0) return {};  // no map: the analytic noise everywhere
  if (map.resolution < 16 || map.resolution > 4096 || !std::isfinite(map.size_m) ||
      !(map.size_m > 0.0) || !std::isfinite(map.origin_m[0]) || !std::isfinite(map.origin_m[1]))
    return invalid_argument("renderer: far-field noise map of " + std::to_string(map.resolution) +
                            " texels over " + std::to_string(map.size_m) +
                            " m: needs 0 or [16, 4096] texels over a finite positive size");
  return {};
}

// Whether the map holds octave o (R.13b): its cells span at least four texels. Finer octaves
// alias in the map's point samples; the per-pixel noise draws them.
bool octave_in_map(const FarFieldPass& pass, int o) {
  const double texel = pass.size_m / pass.resolution;
  return pass.noise.cell_m[static_cast<std::size_t>(o)] >= 4.0 * texel;
}

// The octaves the conversion removes from the map: the map's own parameters at its window and
// time (the split of far_noise_lattice, as the simulation's), the kept octaves' amplitudes 0.
noise::FarNoiseMapParams removed_octaves(const FarFieldPass& pass) {
  constexpr std::array<std::uint32_t, 3> kSeeds = {OCEAN_FAR_SEED0, OCEAN_FAR_SEED1,
                                                   OCEAN_FAR_SEED2};
  noise::FarNoiseMapParams p{};
  p.resolution = pass.side;
  const double texel = pass.size_m / pass.resolution;
  for (int o = 0; o < 3; ++o) {
    const auto i = static_cast<std::size_t>(o);
    const double s = pass.noise.cell_m[i];
    const FarNoiseLattice l =
        far_noise_lattice(pass.noise, o, pass.origin_m[0], pass.origin_m[1], pass.time_s);
    p.octave[i] = {.origin_u = l.rest_u,
                   .origin_v = l.rest_v,
                   .shift_u = l.cells_u,
                   .shift_v = l.cells_v,
                   .step = static_cast<float>(texel / s),
                   .amplitude_m = octave_in_map(pass, o)
                                      ? 0.0f
                                      : static_cast<float>(pass.noise.amplitude_m[i]),
                   .inv_cell = static_cast<float>(1.0 / s),
                   .seed = kSeeds[i]};
  }
  return p;
}

void place(FarFieldPass& pass, const FarNoiseFrame& map, double time_s) {
  pass.origin_m = map.origin_m;
  pass.size_m = map.size_m;
  pass.resolution = map.resolution;
  pass.time_s = time_s;
}

}  // namespace

Status FarFieldPass::create(Renderer::State& st) {
  FarFieldPass& pass = *this;
  const vk::Context& ctx = *st.ctx;
  // Linear with mips, clamped (the window does not repeat), anisotropic where the device is.
  Result<VkSampler> linear = make_sampler(ctx, true, true, false, ctx.max_anisotropy);
  if (!linear.ok()) return linear.status();
  pass.sampler = linear.value();
  if (Status s = create_layouts(pass, ctx); !s.ok()) return s;
  Result<vk::ComputePipeline> compute =
      vk::create_compute_pipeline(ctx, spirv::far_map(), pass.layout);
  if (!compute.ok()) return compute.status();
  pass.pipeline = compute.value();
  return allocate_far_map(st, 1);
}

void FarFieldPass::destroy(Renderer::State& st) {
  FarFieldPass& pass = *this;
  const VkDevice d = st.ctx->device;
  vk::destroy_pipeline(*st.ctx, pass.pipeline);
  vk::destroy_image(*st.ctx, pass.image);
  vk::destroy_buffer(*st.ctx, pass.source);
  if (pass.layout != VK_NULL_HANDLE) vkDestroyPipelineLayout(d, pass.layout, nullptr);
  if (pass.pool != VK_NULL_HANDLE) vkDestroyDescriptorPool(d, pass.pool, nullptr);
  if (pass.set_layout != VK_NULL_HANDLE) vkDestroyDescriptorSetLayout(d, pass.set_layout, nullptr);
  if (pass.sampler != VK_NULL_HANDLE) vkDestroySampler(d, pass.sampler, nullptr);
}

void FarFieldPass::scene_images(const Renderer::State&, SceneImages& images) const {
  images.add(OCEAN_RENDER_BINDING_FAR_MAP, images.surface_stages,
             {sampler, image.view, VK_IMAGE_LAYOUT_GENERAL});
}

Status FarFieldPass::stage(Renderer::State& st, const FarNoiseFrame& map, double map_time_s) {
  if (Status s = check_map(map); !s.ok()) return s;
  const auto n = static_cast<std::size_t>(map.resolution);
  if (map.height_slope.size() != 3 * n * n)
    return invalid_argument("renderer: the far-field noise map holds " +
                            std::to_string(map.height_slope.size()) + " values for " +
                            std::to_string(n) + "² texels (3 each expected)");
  FarFieldPass& pass = *this;
  place(pass, map, map_time_s);
  if (n == 0) return {};
  if (pass.side != n) {
    if (Status s = allocate_far_map(st, static_cast<std::uint32_t>(n)); !s.ok()) {
      pass.resolution = 0;
      return s;
    }
  }
  if (pass.bound != pass.source.buffer) write_source(pass, *st.ctx, pass.source.buffer, 12 * n * n);
  std::memcpy(pass.source.mapped, map.height_slope.data(), 12 * n * n);
  pass.pending = true;
  return {};
}

Status Renderer::set_far_noise(const Frame& frame) {
  return pass<FarFieldPass>(*state_).stage(*state_, frame.far_noise, frame.time_s);
}

Status Renderer::use_simulation_images(const vk::SimulationImages& images, const Frame& frame) {
  State& st = *state_;
  FarFieldPass& pass = render::pass<FarFieldPass>(st);
  const FarNoiseFrame& map = frame.far_noise;
  if (Status s = check_map(map); !s.ok()) return s;
  if (static_cast<std::uint32_t>(map.resolution) != images.far_noise_resolution ||
      (map.resolution > 0 && images.far_noise == VK_NULL_HANDLE))
    return invalid_argument("renderer: the frame's far-field noise map has " +
                            std::to_string(map.resolution) + " texels a side, the images' buffer " +
                            std::to_string(images.far_noise_resolution));
  use_simulation_images(images);
  place(pass, map, frame.time_s);
  const auto n = static_cast<std::uint32_t>(map.resolution);
  if (n == 0) return {};
  if (pass.side != n) {
    if (Status s = allocate_far_map(st, n); !s.ok()) {
      pass.resolution = 0;
      return s;
    }
  }
  if (pass.bound != images.far_noise)
    write_source(pass, *st.ctx, images.far_noise, VkDeviceSize{12} * n * n);
  pass.pending = true;
  return {};
}

void FarFieldPass::upload(Renderer::State&, VkCommandBuffer cmd) {
  FarFieldPass& pass = *this;
  if (!pass.pending) return;
  pass.pending = false;
  const std::uint32_t n = pass.side;
  // Earlier reads of the image are done (one frame in flight) and its content is rebuilt.
  vk::image_barrier(cmd, pass.image.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                    VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0,
                    VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT);
  if (n == 1) {  // no map yet: zeros behind the descriptor
    const VkClearColorValue zero{};
    const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, pass.image.image, VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &all);
    vk::barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
    return;
  }
  if (pass.resolution == 0) return;  // the map went before it was drawn
  // The source's writes (the host's, or the backend's compute and copies) → the conversion.
  vk::barrier(cmd,
              VK_PIPELINE_STAGE_HOST_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT |
                  VK_PIPELINE_STAGE_TRANSFER_BIT,
              VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.pipeline.pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.layout, 0, 1, &pass.set, 0,
                          nullptr);
  const noise::FarNoiseMapParams removed = removed_octaves(pass);
  vkCmdPushConstants(cmd, pass.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(removed), &removed);
  const std::uint32_t groups = (n + OCEAN_RENDER_FAR_TILE - 1) / OCEAN_RENDER_FAR_TILE;
  vkCmdDispatch(cmd, groups, groups, 1);
  vk::barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  // Level l from level l − 1 by a linear blit: at an exact halving, the mean of 2 × 2 texels.
  for (std::uint32_t level = 1; level < pass.image.mips; ++level) {
    const auto from = static_cast<std::int32_t>(std::max(n >> (level - 1), 1u));
    const auto to = static_cast<std::int32_t>(std::max(n >> level, 1u));
    const VkImageBlit blit{.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, 1},
                           .srcOffsets = {{0, 0, 0}, {from, from, 1}},
                           .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1},
                           .dstOffsets = {{0, 0, 0}, {to, to, 1}}};
    vkCmdBlitImage(cmd, pass.image.image, VK_IMAGE_LAYOUT_GENERAL, pass.image.image,
                   VK_IMAGE_LAYOUT_GENERAL, 1, &blit, VK_FILTER_LINEAR);
    vk::barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  }
  vk::barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
              VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
}

void FarFieldPass::fill_uniforms(const Renderer::State& st, const View& view,
                                 shader::FrameUniforms& u) const {
  const FarFieldNoise& far = noise;
  const auto f = [](double x) { return static_cast<float>(x); };
  u.far_field = {
      .cell_m = {f(far.cell_m[0]), f(far.cell_m[1]), f(far.cell_m[2]), 0.0f},
      .amplitude_m = {f(far.amplitude_m[0]), f(far.amplitude_m[1]), f(far.amplitude_m[2]), 0.0f},
      .slope_variance = {f(far.slope_variance[0]), f(far.slope_variance[1]),
                         f(far.slope_variance[2]), 0.0f},
      .near_m = f(view.far_field.near_m),
      .far_m = f(view.far_field.far_m),
      .enabled = u.cascade_count > 0.0f ? 1.0f : 0.0f,
      .far_pad = 0.0f};
  const FarFieldPass& pass = *this;
  const double ox = st.selection.grid_centre_x_m, oz = st.selection.grid_centre_z_m;
  for (int o = 0; o < 3; ++o) {  // the lattice at the frame's origin O and time t (R.13b)
    const FarNoiseLattice l = far_noise_lattice(noise, o, ox, oz, pass.time_s);
    u.far_octaves[o] = {
        .rest_u = l.rest_u, .rest_v = l.rest_v, .cells_u = l.cells_u, .cells_v = l.cells_v};
  }
  const bool on = pass.resolution > 0 && pass.side == static_cast<std::uint32_t>(pass.resolution);
  const auto in_map = [&](int o) { return on && octave_in_map(pass, o) ? 1.0f : 0.0f; };
  u.far_map = {.in_map = {in_map(0), in_map(1), in_map(2), 0.0f},
               .origin_m = {static_cast<float>(pass.origin_m[0] - ox),
                            static_cast<float>(pass.origin_m[1] - oz)},
               .size_m = static_cast<float>(pass.size_m),
               .resolution = on ? static_cast<float>(pass.resolution) : 0.0f,
               .fade_texels = static_cast<float>(kFarNoiseFadeTexels),
               .coarsest_mip = static_cast<float>(pass.image.mips - 1),
               .map_pad0 = 0.0f,
               .map_pad1 = 0.0f};
}

}  // namespace ocean::render
