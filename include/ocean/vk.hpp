// ocean/vk.hpp — the small Vulkan layer shared by the compute backend and the renderer: instance
// (optionally with the Khronos validation layer), device enumeration and selection, one compute
// queue, buffers and images with memory-type selection, compute pipelines from SPIR-V words,
// one-shot command submission and timestamp queries. A Context is either the library's own
// (create_context) or wraps an engine's instance, device and queue (adopt_context).
//
// Style: plain C API of <vulkan/vulkan.h>, POD structs and free functions (after zeux/niagara).
// Every function that can fail for environmental reasons (no driver, out of memory, device lost)
// returns Status/Result with a one-line message that says what to do; misuse asserts.
//
// Threading: a Context may be shared; its queue must be used from one thread at a time (see
// "Queue access" at adopt_context for every place the library touches it).
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "ocean/core.hpp"

namespace ocean::vk {

/// A physical device as `ocean info` lists it.
struct DeviceInfo {
  std::string name;         ///< VkPhysicalDeviceProperties::deviceName
  std::string type;         ///< "discrete", "integrated", "virtual", "cpu" or "other"
  std::string api_version;  ///< "1.3.230"
  std::string driver;       ///< driver name and version where known
  bool usable = false;      ///< Vulkan ≥ 1.1 with a compute queue
  std::string reason;       ///< why not usable (empty when usable)
};

struct ContextParams {
  /// Enables VK_LAYER_KHRONOS_validation and a debug messenger that counts its messages.
  /// The environment variable OCEAN_VK_VALIDATION=1 turns it on as well.
  bool validation = false;
  /// Index into list_devices(); −1 picks the best usable one (discrete > integrated > cpu).
  int device_index = -1;
  /// The queue must do graphics as well as compute (the renderer): Vulkan 1.3 with dynamic
  /// rendering, and fillModeNonSolid / samplerAnisotropy / tessellationShader where the device has
  /// them.
  bool graphics = false;
  /// Extra instance extensions (a window system's surface extensions, e.g. from GLFW).
  std::vector<const char*> instance_extensions;
  /// Enables VK_KHR_swapchain on the device (presenting to a window).
  bool swapchain = false;
  /// Extra device extensions (those an OpenXR runtime asks for); `unsupported` naming the
  /// first one the device lacks.
  std::vector<const char*> device_extensions;
  /// With `graphics`: enables multiview (VK_KHR_multiview, core in Vulkan 1.1; stereo in one
  /// pass) where the device has it. false leaves it off, as on a device without it.
  bool multiview = true;
  /// Enables what sharing memory and semaphores with another API on the same GPU needs
  /// (ocean/vk/external.hpp): VK_KHR_external_memory_fd, VK_KHR_external_semaphore_fd and the
  /// timelineSemaphore feature, each where the device has it (Context says which it got).
  bool external_interop = false;
};

/// An instance, a logical device and its compute queue.
struct Context {
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  std::uint32_t queue_family = 0;
  VkPhysicalDeviceProperties properties{};
  VkPhysicalDeviceMemoryProperties memory{};
  /// The largest single allocation the device promises (maxMemoryAllocationSize, Vulkan 1.1):
  /// a larger one is refused before vkAllocateMemory. 0 when the device does not say.
  VkDeviceSize max_allocation_bytes = 0;
  DeviceInfo info;
  bool validation = false;      ///< the validation layer is active
  bool timestamps = false;      ///< the compute queue supports timestamp queries
  bool graphics = false;        ///< the queue does graphics too (ContextParams::graphics)
  bool wireframe = false;       ///< fillModeNonSolid is enabled
  bool tessellation = false;    ///< tessellationShader is enabled (the tessellated mesh)
  float max_anisotropy = 1.0f;  ///< > 1 when samplerAnisotropy is enabled
  bool multiview = false;       ///< VkPhysicalDeviceVulkan11Features::multiview is enabled
  double timestamp_period_ns = 1.0;
  /// Validation warnings and errors reported so far (tests assert zero); performance advice
  /// is not counted.
  std::atomic<std::uint32_t> validation_messages{0};
  /// The last validation message, for test failure output.
  std::string last_validation_message;
  /// The handles belong to the caller (adopt_context): the destructor destroys none of them.
  bool adopted = false;
  /// VkPhysicalDeviceIDProperties::deviceUUID: the same GPU seen from another API (CUDA) has the
  /// same UUID.
  std::array<std::uint8_t, VK_UUID_SIZE> device_uuid{};
  /// Enabled by ContextParams::external_interop where the device has them (never on an adopted
  /// context: the library cannot see which extensions the caller enabled).
  bool external_memory_fd = false;     ///< VK_KHR_external_memory_fd
  bool external_semaphore_fd = false;  ///< VK_KHR_external_semaphore_fd
  bool timeline_semaphore = false;     ///< timelineSemaphore (Vulkan 1.2 feature)
  bool timeline_exportable = false;    ///< ... and a timeline semaphore exports as an opaque fd

  Context() = default;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  ~Context();
};

/// Every physical device of the Vulkan loader; an `unsupported` Status when there is no loader
/// or no device ("no Vulkan device: install mesa-vulkan-drivers or a GPU driver").
Result<std::vector<DeviceInfo>> list_devices();
/// Creates instance, device and queue. Unusable or absent devices give `unsupported`.
Result<std::unique_ptr<Context>> create_context(const ContextParams& params = {});

/// An engine's own Vulkan objects, for adopt_context(). The library cannot query how a device was
/// created, so the caller states the API version and the features it enabled.
struct AdoptedDevice {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;  ///< one of `instance`'s physical devices
  VkDevice device = VK_NULL_HANDLE;            ///< created from `physical`
  /// The family `queue` belongs to: compute, and graphics too with `graphics`.
  std::uint32_t queue_family = 0;
  VkQueue queue = VK_NULL_HANDLE;  ///< vkGetDeviceQueue(device, queue_family, any index)
  /// VkApplicationInfo::apiVersion the instance was created with (VK_API_VERSION_1_2 or later;
  /// 1.3 with `graphics`). 0 = not stated, an error.
  std::uint32_t api_version = 0;
  /// The renderer draws on this context (ContextParams::graphics): Vulkan 1.3 and
  /// `dynamic_rendering` are required.
  bool graphics = false;
  /// VkPhysicalDeviceVulkan13Features::dynamicRendering was enabled at vkCreateDevice.
  bool dynamic_rendering = false;
  /// VkPhysicalDeviceFeatures::fillModeNonSolid was enabled (the wireframe view).
  bool fill_mode_non_solid = false;
  /// VkPhysicalDeviceFeatures::samplerAnisotropy was enabled (anisotropic filtering).
  bool sampler_anisotropy = false;
  /// VkPhysicalDeviceVulkan11Features::multiview was enabled (stereo in one pass).
  bool multiview = false;
  /// VkPhysicalDeviceFeatures::tessellationShader was enabled (the tessellated mesh).
  bool tessellation_shader = false;
};

/// A Context around the caller's instance, physical device, device and queue; the VulkanBackend
/// and the Renderer work on it as on one of create_context().
///
/// Ownership and lifetime: the library destroys none of the adopted handles. The caller keeps
/// them alive, and the device not lost, longer than the Context and everything made on it
/// (backends, renderers, buffers, images, pipelines, command pools); destroy those, then the
/// Context, then your own device and instance.
///
/// Requirements (checked; one-line Status naming what is missing): handles not null; `physical`
/// one of `instance`'s devices with Vulkan ≥ 1.2 and `api_version` ≥ 1.2 (`unsupported` for the
/// device, `invalid_argument` for what the caller passed); `queue_family` in range with compute
/// (and graphics with `graphics`); with `graphics`, Vulkan 1.3 on both sides and
/// `dynamic_rendering`. The library needs no device extension. Handles must come through the
/// system Vulkan loader (the library calls its exported entry points; a loader opened by volk or
/// dlopen is the same loader). The validation counter (Context::validation_messages) stays at 0:
/// install your own VK_EXT_debug_utils messenger on your instance.
///
/// Queue access: Vulkan requires host access to a VkQueue to be externally synchronised. The
/// library touches `queue` only in vk::submit() (vkQueueSubmit of one command buffer with a
/// fence of its own, no semaphores), on the calling thread, from the calls that set up, upload,
/// step, draw or read back: create_static_buffer(), run_once(), VulkanBackend::configure/step/
/// submit, Renderer::prepare/draw/read_srgb/read_hdr, and Renderer::record() only
/// when the patch mesh must change (call prepare() first; record() otherwise leaves submission
/// to you). Each waits for its own fence before returning, except VulkanBackend::submit()
/// (read() waits). Destroying or reconfiguring a backend or renderer, and Renderer::resize, call
/// vkDeviceWaitIdle, which needs every queue of the device externally synchronised. So: do not
/// use `queue` from another thread while one of those calls runs, and use no queue of the device
/// while a backend or renderer is configured, resized or destroyed. Calling the library from the
/// thread that submits your frames satisfies both; giving it a queue of its own (another index
/// of the family) leaves only the second rule.
Result<std::unique_ptr<Context>> adopt_context(const AdoptedDevice& adopted);

/// Maps a failed VkResult to a Status: out of memory and device lost get messages that say what
/// to do; `what` names the operation ("vkQueueSubmit").
Status check(VkResult result, const char* what);

/// A buffer and its own memory allocation. `mapped` is non-null for host-visible buffers.
struct Buffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkDeviceSize size = 0;
  void* mapped = nullptr;
};
enum class MemoryUse {
  device,    ///< device-local, not mapped
  upload,    ///< host-visible and coherent, mapped (CPU writes, GPU reads)
  readback,  ///< host-visible, coherent (cached where possible), mapped (GPU writes, CPU reads)
};
Result<Buffer> create_buffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage,
                             MemoryUse use);
void destroy_buffer(const Context& ctx, Buffer& buffer);

/// A 2D array image with a full-image view and one view per mip level (for storage writes).
struct Image {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;   ///< all mips and layers (for sampling)
  std::vector<VkImageView> mip_views;  ///< level m, all layers (for imageStore)
  VkFormat format = VK_FORMAT_UNDEFINED;
  std::uint32_t size = 0, layers = 0, mips = 0;
};
Result<Image> create_image_array(const Context& ctx, VkFormat format, std::uint32_t size,
                                 std::uint32_t layers, std::uint32_t mips, VkImageUsageFlags usage);
void destroy_image(const Context& ctx, Image& image);

/// A single 2D image with one view over its only mip level (render targets); with `layers` > 1
/// a layered target (multiview) whose view is a 2D array over every layer. With `mips` > 1 (a
/// target sampled through its mip chain) `view` spans every level and `level0_view` the first,
/// the one to render into.
struct Image2D {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  VkImageView level0_view = VK_NULL_HANDLE;  ///< with mips > 1 only
  VkFormat format = VK_FORMAT_UNDEFINED;
  std::uint32_t width = 0, height = 0;
  std::uint32_t layers = 1, mips = 1;
};
Result<Image2D> create_image_2d(const Context& ctx, VkFormat format, std::uint32_t width,
                                std::uint32_t height, VkImageUsageFlags usage,
                                VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT,
                                std::uint32_t layers = 1, std::uint32_t mips = 1);
/// Fills levels 1… of a mipped Image2D from level 0 by linear blits (each level the mean of 2 × 2
/// texels of the one above at an exact halving), level 0 in COLOR_ATTACHMENT_OPTIMAL after
/// rendering; leaves every level in SHADER_READ_ONLY_OPTIMAL for the fragment shaders. The image
/// needs TRANSFER_SRC and TRANSFER_DST usage.
void generate_mips(VkCommandBuffer cmd, const Image2D& image);
void destroy_image(const Context& ctx, Image2D& image);

/// A compute pipeline, its layout and its shader module.
struct ComputePipeline {
  VkShaderModule module = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
};
/// Builds a pipeline from SPIR-V words; `specialization` sets constant_id 0, 1, ... in order.
Result<ComputePipeline> create_compute_pipeline(const Context& ctx,
                                                std::span<const std::uint32_t> spirv,
                                                VkPipelineLayout layout,
                                                std::span<const std::uint32_t> specialization = {});
void destroy_pipeline(const Context& ctx, ComputePipeline& pipeline);

/// A command pool with one primary command buffer and a fence.
struct Commands {
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandBuffer buffer = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
};
Result<Commands> create_commands(const Context& ctx);
void destroy_commands(const Context& ctx, Commands& commands);
/// Submits commands.buffer (already recorded) and returns without waiting.
Status submit(const Context& ctx, const Commands& commands);
/// Waits for the last submit (timeout in ns) and resets the fence.
Status wait(const Context& ctx, const Commands& commands,
            std::uint64_t timeout_ns = 60'000'000'000);
/// Records with `record`, submits and waits: for uploads and other one-off work.
template <typename F>
Status run_once(const Context& ctx, const Commands& commands, F&& record);
/// A buffer in device-local memory filled with `bytes` through a staging copy on `commands`.
Result<Buffer> create_static_buffer(const Context& ctx, const Commands& commands,
                                    std::span<const std::byte> bytes, VkBufferUsageFlags usage);

/// A global memory barrier from the writes of `src` stages (compute, transfer, host) to the
/// accesses of `dst` stages (those, plus vertex input, vertex/fragment shader reads and all
/// commands): coarse and correct.
void barrier(VkCommandBuffer cmd, VkPipelineStageFlags src = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
             VkPipelineStageFlags dst = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);

/// A layout transition of every mip level and layer of `image`, with explicit stages and
/// accesses (render targets, swapchain images).
void image_barrier(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                   VkPipelineStageFlags src_stage, VkAccessFlags src_access,
                   VkPipelineStageFlags dst_stage, VkAccessFlags dst_access,
                   VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT);

/// A timestamp query pool of `count` queries.
struct Timestamps {
  VkQueryPool pool = VK_NULL_HANDLE;
  std::uint32_t count = 0;
};
Result<Timestamps> create_timestamps(const Context& ctx, std::uint32_t count);
void destroy_timestamps(const Context& ctx, Timestamps& timestamps);
/// Reads every query (after the work finished) as milliseconds since query 0.
Status read_timestamps_ms(const Context& ctx, const Timestamps& timestamps,
                          std::span<double> out_ms);

// ---------------------------------------------------------------------------------------------

template <typename F>
Status run_once(const Context& ctx, const Commands& commands, F&& record) {
  if (Status s = check(vkResetCommandBuffer(commands.buffer, 0), "vkResetCommandBuffer"); !s.ok())
    return s;
  const VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                       .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
  if (Status s = check(vkBeginCommandBuffer(commands.buffer, &begin), "vkBeginCommandBuffer");
      !s.ok())
    return s;
  record(commands.buffer);
  if (Status s = check(vkEndCommandBuffer(commands.buffer), "vkEndCommandBuffer"); !s.ok())
    return s;
  if (Status s = submit(ctx, commands); !s.ok()) return s;
  return wait(ctx, commands);
}

}  // namespace ocean::vk
