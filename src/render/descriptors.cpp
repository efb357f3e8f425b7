// The renderer's shared samplers and the scene set every pass draws with: the frame's uniforms,
// the simulation's displacement and normal/foam arrays, and the images the passes declare
// (pass.hpp's scene_images: the sky table, the far map, the local layer, ...). Binding numbers:
// shaders/render_shared.h.
#include <cassert>

#include "state.hpp"

namespace ocean::render {

Result<VkSampler> make_sampler(const vk::Context& ctx, bool linear, bool mips, bool repeat,
                               float anisotropy, bool repeat_v_too) {
  const VkSamplerAddressMode mode =
      repeat ? VK_SAMPLER_ADDRESS_MODE_REPEAT : VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  const VkSamplerAddressMode mode_v = repeat_v_too ? mode : VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  const VkFilter filter = linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  const VkSamplerCreateInfo info{
      .sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
      .magFilter = filter,
      .minFilter = filter,
      .mipmapMode = mips ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST,
      .addressModeU = mode,
      .addressModeV = mode_v,
      .addressModeW = mode,
      .anisotropyEnable = anisotropy > 1.0f ? VK_TRUE : VK_FALSE,
      .maxAnisotropy = anisotropy,
      .minLod = 0.0f,
      .maxLod = mips ? VK_LOD_CLAMP_NONE : 0.0f};
  VkSampler s = VK_NULL_HANDLE;
  if (Status st = vk::check(vkCreateSampler(ctx.device, &info, nullptr, &s), "vkCreateSampler");
      !st.ok())
    return st;
  return s;
}

namespace {

// The scene set's images: the simulation's (the displacement sampled where the surface is placed
// and shaded, the normal and foam where it is shaded) and each pass's. Their views are null
// before configure() and before a pass has made its images.
SceneImages scene_images(const Renderer::State& st) {
  SceneImages images;
  // The vertex stages (and the tessellation evaluation stage, R.41) and the fragment stage.
  images.surface_stages =
      VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT |
      (st.ctx->tessellation ? VkShaderStageFlags{VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT} : 0u);
  images.add(OCEAN_RENDER_BINDING_DISPLACEMENT, images.surface_stages,
             {st.displacement_sampler, st.displacement_view, VK_IMAGE_LAYOUT_GENERAL});
  images.add(OCEAN_RENDER_BINDING_NORMAL, VK_SHADER_STAGE_FRAGMENT_BIT,
             {st.normal_sampler, st.normal_view, VK_IMAGE_LAYOUT_GENERAL});
  for_each_pass(st, [&](const auto& p) { p.scene_images(st, images); });
  return images;
}

}  // namespace

void write_scene_images(Renderer::State& st) {
  if (!st.scene_images_ready) return;  // make() writes them once every pass has its images
  const VkDescriptorBufferInfo ubo{st.uniforms.buffer, 0, sizeof(shader::FrameUniforms)};
  const SceneImages images = scene_images(st);
  std::array<VkWriteDescriptorSet, OCEAN_RENDER_SCENE_BINDINGS> writes{};
  writes[0] = {.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
               .dstSet = st.scene_set,
               .dstBinding = OCEAN_RENDER_BINDING_FRAME,
               .descriptorCount = 1,
               .descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
               .pBufferInfo = &ubo};
  std::uint32_t count = 1;
  for (std::uint32_t i = 0; i < images.count; ++i) {
    if (images.infos[i].imageView == VK_NULL_HANDLE) continue;  // not made yet (its pass writes it)
    writes[count++] = {.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                       .dstSet = st.scene_set,
                       .dstBinding = images.bindings[i],
                       .descriptorCount = 1,
                       .descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                       .pImageInfo = &images.infos[i]};
  }
  vkUpdateDescriptorSets(st.ctx->device, count, writes.data(), 0, nullptr);
}

void write_rendered_image(const Renderer::State& st, VkDescriptorSet set, std::uint32_t binding,
                          VkImageView view) {
  const VkDescriptorImageInfo image{st.hdr_sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  const VkWriteDescriptorSet write{.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                                   .dstSet = set,
                                   .dstBinding = binding,
                                   .descriptorCount = 1,
                                   .descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                   .pImageInfo = &image};
  vkUpdateDescriptorSets(st.ctx->device, 1, &write, 0, nullptr);
}

Status create_descriptors(Renderer::State& st) {
  const vk::Context& ctx = *st.ctx;
  Result<VkSampler> s1 = make_sampler(ctx, true, false, true, 1.0f);
  if (!s1.ok()) return s1.status();
  st.displacement_sampler = s1.value();
  Result<VkSampler> s2 = make_sampler(ctx, true, true, true, ctx.max_anisotropy);
  if (!s2.ok()) return s2.status();
  st.normal_sampler = s2.value();
  Result<VkSampler> s3 = make_sampler(ctx, false, false, false, 1.0f);
  if (!s3.ok()) return s3.status();
  st.hdr_sampler = s3.value();

  // The frame's uniforms, then the images (the passes' from their not yet created objects: only
  // the bindings and stages are read).
  const SceneImages images = scene_images(st);
  assert(images.count + 1 <= OCEAN_RENDER_SCENE_BINDINGS);
  std::array<VkDescriptorSetLayoutBinding, OCEAN_RENDER_SCENE_BINDINGS> scene_bindings{};
  scene_bindings[0] = {OCEAN_RENDER_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
                       images.surface_stages, nullptr};
  for (std::uint32_t i = 0; i < images.count; ++i)
    scene_bindings[i + 1] = {images.bindings[i], VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                             images.stages[i], nullptr};
  const VkDescriptorSetLayoutCreateInfo scene_info{
      .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
      .bindingCount = images.count + 1,
      .pBindings = scene_bindings.data()};
  if (Status s =
          vk::check(vkCreateDescriptorSetLayout(ctx.device, &scene_info, nullptr, &st.scene_layout),
                    "vkCreateDescriptorSetLayout");
      !s.ok())
    return s;
  const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                                        {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, images.count}};
  const VkDescriptorPoolCreateInfo pool_info{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                             .maxSets = 1,
                                             .poolSizeCount = 2,
                                             .pPoolSizes = sizes};
  if (Status s = vk::check(vkCreateDescriptorPool(ctx.device, &pool_info, nullptr, &st.pool),
                           "vkCreateDescriptorPool");
      !s.ok())
    return s;
  const VkDescriptorSetAllocateInfo alloc{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                          .descriptorPool = st.pool,
                                          .descriptorSetCount = 1,
                                          .pSetLayouts = &st.scene_layout};
  return vk::check(vkAllocateDescriptorSets(ctx.device, &alloc, &st.scene_set),
                   "vkAllocateDescriptorSets");
}

}  // namespace ocean::render
