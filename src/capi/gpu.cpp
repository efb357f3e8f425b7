// src/capi/gpu.cpp — GPU-resident outputs through the C ABI: a simulator on an engine's own
// Vulkan device (vk::adopt_context under ocean_simulator_create_on_vulkan), its output images as
// Vulkan handles (VulkanBackend::images), and a CUDA simulator's arrays as device pointers
// (CudaBackend::device_output). Each part compiles to an `unsupported` answer in a build without
// its API, so the exported functions are the same in every build.
#include <cstdint>
#include <string>
#include <type_traits>

#include "capi_internal.hpp"
#include "ocean/backends.hpp"
#ifdef OCEAN_HAS_VULKAN
#include "ocean/backends/vulkan.hpp"
#include "ocean/vk.hpp"
#include "ocean/vk/images.hpp"
#endif
#ifdef OCEAN_HAS_CUDA
#include "ocean/backends/cuda.hpp"
#endif

namespace ocean::capi {
namespace {

// "<what>->struct_size = <given> is too small: set it to sizeof(<type>)"
Status require_struct_size(std::size_t given, std::size_t needed, std::string_view function,
                           std::string_view what, std::string_view type) {
  if (given >= needed) return {};
  return invalid_argument(std::string(function) + ": " + std::string(what) +
                          "->struct_size = " + std::to_string(given) +
                          " is too small: set it to sizeof(" + std::string(type) + ")");
}

// The ocean_field values, for a caller's number out of range.
Status require_field(ocean_field field) {
  const auto value = static_cast<long long>(field);
  if (value >= OCEAN_FIELD_DISPLACEMENT && value <= OCEAN_FIELD_VELOCITY) return {};
  return invalid_argument("field = " + std::to_string(value) +
                          " is out of range: must be 0 to 6 (ocean_field)");
}

// "the simulator runs on the '<name>' backend: <what> needs <need>"
Status wrong_backend(const Simulator& simulator, std::string_view what, std::string_view need) {
  return unsupported("the simulator runs on the '" + std::string(simulator.backend().name()) +
                     "' backend: " + std::string(what) + " needs " + std::string(need));
}

#ifdef OCEAN_HAS_VULKAN
// A non-dispatchable handle as ocean_vk_handle: a pointer on 64-bit targets, uint64_t on 32-bit.
template <typename Handle>
ocean_vk_handle to_c(Handle handle) {
  if constexpr (std::is_pointer_v<Handle>) {
    return static_cast<ocean_vk_handle>(reinterpret_cast<std::uintptr_t>(handle));
  } else {
    return static_cast<ocean_vk_handle>(handle);
  }
}

Result<std::unique_ptr<Backend>> vulkan_backend_on(const ocean_vulkan_device& d) {
  const vk::AdoptedDevice adopted{.instance = static_cast<VkInstance>(d.instance),
                                  .physical = static_cast<VkPhysicalDevice>(d.physical_device),
                                  .device = static_cast<VkDevice>(d.device),
                                  .queue_family = d.queue_family,
                                  .queue = static_cast<VkQueue>(d.queue),
                                  .api_version = d.api_version};
  Result<std::unique_ptr<vk::Context>> context = vk::adopt_context(adopted);
  if (!context.ok()) {
    // The C caller knows this function, not the C++ one beneath it.
    constexpr std::string_view cxx = "adopt_context: ";
    std::string message = context.status().message();
    if (message.starts_with(cxx))
      message = "ocean_simulator_create_on_vulkan: " + message.substr(cxx.size());
    return Status(context.status().code(), message);
  }
  return std::unique_ptr<Backend>(std::make_unique<vk::VulkanBackend>(
      std::shared_ptr<vk::Context>(std::move(context).value())));
}
#endif

Status vulkan_image(const Simulator& simulator, ocean_field field, ocean_vulkan_image& out) {
#ifdef OCEAN_HAS_VULKAN
  const auto* backend = dynamic_cast<const vk::VulkanBackend*>(&simulator.backend());
  if (backend == nullptr) {
    return wrong_backend(simulator, "a Vulkan image",
                         "the vulkan backend (ocean_simulator_create_on_vulkan)");
  }
  if (Status s = backend->status(); !s.ok()) return s;
  const vk::SimulationImages images = backend->images();
  const bool displacement = field == OCEAN_FIELD_DISPLACEMENT_HALF;
  if (!displacement && field != OCEAN_FIELD_PACKED) {
    return unsupported(
        "field = " + std::to_string(static_cast<long long>(field)) +
        " has no Vulkan image: only OCEAN_FIELD_DISPLACEMENT_HALF and "
        "OCEAN_FIELD_PACKED are images (read the others with ocean_simulator_field)");
  }
  out.image = to_c(displacement ? images.displacement : images.normal_foam);
  out.view = to_c(displacement ? images.displacement_view : images.normal_foam_view);
  out.format = displacement ? VK_FORMAT_R16G16B16A16_SFLOAT : VK_FORMAT_R8G8B8A8_UNORM;
  out.width = out.height = images.size;
  out.layers = images.layers;
  out.mip_levels = displacement ? 1u : images.mips;
  out.layout = VK_IMAGE_LAYOUT_GENERAL;  // vk/images.hpp: the images never leave it
  // The usage of gpu_state.cpp's output images and the stage and access of their writers (the
  // finalize and mip kernels' imageStore).
  out.usage =
      VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  out.src_stage_mask = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
  out.src_access_mask = VK_ACCESS_SHADER_WRITE_BIT;
  out.frame_index = simulator.frame().index;
  return {};
#else
  (void)field, (void)out;
  return wrong_backend(simulator, "a Vulkan image", "Vulkan, which this build is without");
#endif
}

Status cuda_field(const Simulator& simulator, std::size_t cascade, ocean_field field, int32_t level,
                  ocean_field_view& view, int32_t* device) {
#ifdef OCEAN_HAS_CUDA
  const auto* backend = dynamic_cast<const cuda::CudaBackend*>(&simulator.backend());
  if (backend == nullptr)
    return wrong_backend(simulator, "a CUDA device pointer", "the cuda backend");
  if (Status s = backend->status(); !s.ok()) return s;
  const Frame& frame = simulator.frame();
  if (cascade >= frame.cascades.size()) {
    return invalid_argument("cascade = " + std::to_string(cascade) +
                            " is out of range: must be 0 to " +
                            std::to_string(frame.cascades.size() - 1));
  }
  // The host view gives the layout (and every check of field and level); the device array has
  // the same layout, so only the base address changes.
  ocean_field_view result = view;
  result.patch_size_m = frame.cascades[cascade].patch_size_m;
  if (Status s = field_view(frame.cascades[cascade], field, level, result); !s.ok()) return s;
  cuda::DeviceOutput output{};
  switch (field) {
    case OCEAN_FIELD_DISPLACEMENT: output = cuda::DeviceOutput::displacement; break;
    case OCEAN_FIELD_DISPLACEMENT_HALF: output = cuda::DeviceOutput::displacement_half; break;
    case OCEAN_FIELD_NORMAL: output = cuda::DeviceOutput::normal; break;
    case OCEAN_FIELD_JACOBIAN: output = cuda::DeviceOutput::jacobian; break;
    case OCEAN_FIELD_FOAM: output = cuda::DeviceOutput::foam; break;
    case OCEAN_FIELD_PACKED: output = cuda::DeviceOutput::packed_mips; break;
    case OCEAN_FIELD_VELOCITY:
    case OCEAN_FIELD_MAX_ENUM:
      return unsupported("the CUDA backend does not compute this field on the device");
  }
  Result<const void*> base = backend->device_output(static_cast<int>(cascade), output);
  if (!base.ok()) return base.status();
  const std::size_t offset =
      field == OCEAN_FIELD_PACKED
          ? 4 * mip_offset(frame.cascades[cascade].resolution, static_cast<int>(level))
          : 0;
  result.data = static_cast<const char*>(base.value()) + offset;
  view = result;
  if (device != nullptr) *device = backend->device();
  return {};
#else
  (void)cascade, (void)field, (void)level, (void)view, (void)device;
  return wrong_backend(simulator, "a CUDA device pointer", "CUDA, which this build is without");
#endif
}

}  // namespace
}  // namespace ocean::capi

extern "C" {

using namespace ocean::capi;

OCEAN_API ocean_status ocean_simulator_create_on_vulkan(const ocean_config* config,
                                                        const ocean_vulkan_device* device,
                                                        const ocean_simulator_options* options,
                                                        ocean_simulator** out) {
  return guarded([&]() -> ocean::Status {
    constexpr std::string_view f = "ocean_simulator_create_on_vulkan";
    if (ocean::Status s = require_not_null(config, f, "config"); !s.ok()) return s;
    if (ocean::Status s = require_not_null(device, f, "device"); !s.ok()) return s;
    if (ocean::Status s = require_not_null(out, f, "out"); !s.ok()) return s;
    if (ocean::Status s = require_struct_size(device->struct_size, sizeof(ocean_vulkan_device), f,
                                              "device", "ocean_vulkan_device");
        !s.ok())
      return s;
    ocean_simulator_options defaults;
    ocean_simulator_options_init(&defaults);
    const ocean_simulator_options* o = options != nullptr ? options : &defaults;
#ifdef OCEAN_HAS_VULKAN
    const ocean_vulkan_device d = *device;
    return simulator_with_options(
        *config, *o, f, [&] { return vulkan_backend_on(d); }, *out);
#else
    (void)o;
    return ocean::unsupported(std::string(f) +
                              ": built without Vulkan: the Vulkan backend is not part of this "
                              "build");
#endif
  });
}

OCEAN_API ocean_status ocean_simulator_vulkan_image(const ocean_simulator* simulator,
                                                    ocean_field field, ocean_vulkan_image* image) {
  return guarded([&]() -> ocean::Status {
    constexpr std::string_view f = "ocean_simulator_vulkan_image";
    if (ocean::Status s = require_not_null(simulator, f, "simulator"); !s.ok()) return s;
    if (ocean::Status s = require_not_null(image, f, "image"); !s.ok()) return s;
    if (ocean::Status s = require_struct_size(image->struct_size, sizeof(ocean_vulkan_image), f,
                                              "image", "ocean_vulkan_image");
        !s.ok())
      return s;
    if (ocean::Status s = require_field(field); !s.ok()) return s;
    ocean_vulkan_image result{};
    result.struct_size = image->struct_size;
    if (ocean::Status s = vulkan_image(*simulator->simulator, field, result); !s.ok()) return s;
    *image = result;
    return {};
  });
}

OCEAN_API ocean_status ocean_simulator_cuda_field(const ocean_simulator* simulator, size_t cascade,
                                                  ocean_field field, int32_t level,
                                                  ocean_field_view* view, int32_t* device) {
  return guarded([&]() -> ocean::Status {
    constexpr std::string_view f = "ocean_simulator_cuda_field";
    if (ocean::Status s = require_not_null(simulator, f, "simulator"); !s.ok()) return s;
    if (ocean::Status s = require_not_null(view, f, "view"); !s.ok()) return s;
    if (ocean::Status s = require_struct_size(view->struct_size, sizeof(ocean_field_view), f,
                                              "view", "ocean_field_view");
        !s.ok())
      return s;
    return cuda_field(*simulator->simulator, cascade, field, level, *view, device);
  });
}

}  // extern "C"
