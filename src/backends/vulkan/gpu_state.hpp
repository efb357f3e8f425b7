// Every Vulkan object of a configured simulation: data buffers, the two output images, the
// pipelines of the four kernels, one descriptor set and the frame's pre-recorded command buffer.
#pragma once

#include <array>
#include <cstddef>
#include <span>

#include "far_noise_pass.hpp"
#include "ocean/backends/vulkan.hpp"
#include "ocean/vk.hpp"
#include "shaders/ocean_shared.h"

namespace ocean::vk::detail {

/// The outputs every frame reads back, in the order of CascadeFrame's arrays.
enum Output : int { displacement, displacement_half, normal, jacobian, foam, packed, kOutputs };

/// Timestamp queries of one frame: start, then the end of each stage.
enum Stamp : std::uint32_t { start, rows, columns, finalized, mipped, copied, kStamps };

struct GpuState {
  const Context* ctx = nullptr;
  std::uint32_t resolution = 0, log2n = 0, cascades = 0, planes = 0;
  Buffer params;  // SimParams, mapped
  Buffer spectrum, phase_rate, twiddle, plane_data, mip_work;
  std::array<Buffer, kOutputs> device;     // written by the kernels
  std::array<Buffer, kOutputs> host;       // read back each frame, mapped (where read_back)
  std::array<bool, kOutputs> read_back{};  // the frame carries the output (FrameOutputs)
  std::array<std::size_t, kOutputs> bytes_per_cascade{};
  Image displacement_image, normal_image;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  VkPipelineLayout pipeline_layout = VK_NULL_HANDLE;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkDescriptorSet set = VK_NULL_HANDLE;
  ComputePipeline rows, columns, finalize, mips;
  Commands frame;  // pre-recorded once, resubmitted every frame
  Timestamps stamps;
  FarNoisePass far_noise;  // the far field's noise map (resolution 0: none)

  GpuState() = default;
  GpuState(const GpuState&) = delete;
  GpuState& operator=(const GpuState&) = delete;
  ~GpuState();
};

/// Host-side data a configuration uploads once (all cascades concatenated).
struct Uploads {
  std::span<const float> spectrum;    // vec4 per texel
  std::span<const float> phase_rate;  // float per texel
  std::span<const float> twiddle;     // vec2 per t ∈ [0, N)
};

/// Allocates every buffer, image, pipeline and descriptor, uploads `data`, transitions the images
/// and records the frame's command buffer. `params` is the initial SimParams. Outputs not in
/// `read_back` are computed on the device (foam is also the accumulation state) but neither
/// copied nor given a host buffer. A far-noise resolution above 0 adds the noise map's dispatch
/// to the frame, beside the cascades' first stage (R.13a).
Status create_gpu_state(GpuState& gpu, const Context& ctx, std::uint32_t resolution,
                        std::uint32_t cascades, std::uint32_t planes, const Uploads& data,
                        const shader::SimParams& params,
                        const std::array<bool, kOutputs>& read_back,
                        std::uint32_t far_noise_resolution);

}  // namespace ocean::vk::detail
