// The renderer's samplers and descriptors: one set for the scene (frame uniforms, displacement
// array, normal/foam array with its mips, the sky-view table, the local layer, the damping, the
// objects' reflection, written by reflection.cpp) and one
// for the tone map (the HDR image). Binding numbers: shaders/render_shared.h.
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

void write_scene_images(Renderer::State& st) {
  if (!st.scene_images_ready) return;  // make() writes them once every pass has its images
  const VkDescriptorBufferInfo ubo{st.uniforms.buffer, 0, sizeof(shader::FrameUniforms)};
  SceneImages images;
  if (st.displacement_view != VK_NULL_HANDLE) {
    images.add(OCEAN_RENDER_BINDING_DISPLACEMENT,
               {st.displacement_sampler, st.displacement_view, VK_IMAGE_LAYOUT_GENERAL});
    images.add(OCEAN_RENDER_BINDING_NORMAL,
               {st.normal_sampler, st.normal_view, VK_IMAGE_LAYOUT_GENERAL});
  }
  for_each_pass(st, [&](const auto& p) { p.scene_images(st, images); });
  std::array<VkWriteDescriptorSet, OCEAN_RENDER_SCENE_BINDINGS> writes{};
  writes[0] = {.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
               .dstSet = st.scene_set,
               .dstBinding = OCEAN_RENDER_BINDING_FRAME,
               .descriptorCount = 1,
               .descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
               .pBufferInfo = &ubo};
  for (std::uint32_t i = 0; i < images.count; ++i)
    writes[i + 1] = {.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                     .dstSet = st.scene_set,
                     .dstBinding = images.bindings[i],
                     .descriptorCount = 1,
                     .descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                     .pImageInfo = &images.infos[i]};
  vkUpdateDescriptorSets(st.ctx->device, images.count + 1, writes.data(), 0, nullptr);
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

  // The vertex stages (and the tessellation evaluation stage, R.41) and the fragment stage.
  const VkShaderStageFlags both =
      VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT |
      (ctx.tessellation ? VkShaderStageFlags{VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT} : 0u);
  const VkDescriptorSetLayoutBinding scene_bindings[] = {
      {OCEAN_RENDER_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, both, nullptr},
      {OCEAN_RENDER_BINDING_DISPLACEMENT, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, both,
       nullptr},
      {OCEAN_RENDER_BINDING_NORMAL, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
       VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {OCEAN_RENDER_BINDING_SKY_LUT, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
       VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {OCEAN_RENDER_BINDING_ENVIRONMENT, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
       VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {OCEAN_RENDER_BINDING_LOCAL, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, both, nullptr},
      {OCEAN_RENDER_BINDING_DAMPING, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, both, nullptr},
      {OCEAN_RENDER_BINDING_REFLECTION, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
       VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {OCEAN_RENDER_BINDING_FAR_MAP, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, both, nullptr}};
  const VkDescriptorSetLayoutCreateInfo scene_info{
      .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
      .bindingCount = OCEAN_RENDER_SCENE_BINDINGS,
      .pBindings = scene_bindings};
  if (Status s =
          vk::check(vkCreateDescriptorSetLayout(ctx.device, &scene_info, nullptr, &st.scene_layout),
                    "vkCreateDescriptorSetLayout");
      !s.ok())
    return s;
  const VkDescriptorPoolSize sizes[] = {
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, OCEAN_RENDER_SCENE_BINDINGS - 1}};
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
