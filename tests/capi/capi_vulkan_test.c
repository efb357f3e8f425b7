/* The C ABI's GPU-resident outputs on an engine's Vulkan device, in C99 against ocean.h and
 * vulkan.h only: the test makes its own instance and device (no extension, no feature), creates
 * a simulator on them (ocean_simulator_create_on_vulkan), steps it twice, takes the output images
 * (ocean_simulator_vulkan_image), copies every layer and mip level into a host buffer with its own
 * command buffer after the barrier the image describes, and compares them with
 *   - the same simulator's read-back fields (ocean_simulator_field): at most one unit in the last
 *     place (the device's conversion into the image format may round otherwise), and
 *   - a CPU simulator of the same configuration: the backend conformance bounds
 *     (include/ocean/conformance.hpp). The CPU backend behind the C ABI is the fused SIMD
 *     pipeline, itself within kCpuBounds of the scalar reference that kDeviceBounds is measured
 *     against, so by the triangle inequality the allowance is the sum of the two: FP32
 *     displacement 6e-6·Hs + 2e-6·Hs, plus 2^-10·|D| for the half image (conformance.hpp's half4
 *     rule); packed RGBA8 every channel within 1 LSB, a share of differing texels of at most
 *     4e-4 + 2e-4.
 * Then the error paths: wrong backend, fields without an image, bad structs and devices, CUDA on
 * a Vulkan simulator. Prints the measured errors. Exit 77 (skip) without a Vulkan device unless
 * OCEAN_REQUIRE_DEVICES is set (tests/support/require_devices.hpp's policy). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <vulkan/vulkan.h>

#include "capi_check.h"
#include "ocean/ocean.h"

/* Warnings and errors of the Khronos validation layer (where installed) about any call on the
 * test's device, the library's included; the test fails on any. */
static int g_validation_messages = 0;
static char g_last_message[1024];

static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                 VkDebugUtilsMessageTypeFlagsEXT types,
                                                 const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                 void* user) {
  (void)severity, (void)types, (void)user;
  ++g_validation_messages;
  snprintf(g_last_message, sizeof g_last_message, "%s",
           data->pMessage != NULL ? data->pMessage : "");
  return VK_FALSE;
}

static int has_layer(const char* name) {
  VkLayerProperties layers[64];
  uint32_t count = 64, i;
  if (vkEnumerateInstanceLayerProperties(&count, layers) < 0) return 0;
  for (i = 0; i < count; ++i) {
    if (strcmp(layers[i].layerName, name) == 0) return 1;
  }
  return 0;
}

#define REQUIRE_VK(call)                                                                      \
  do {                                                                                        \
    VkResult r_ = (call);                                                                     \
    if (r_ != VK_SUCCESS) {                                                                   \
      fprintf(stderr, "%s:%d: %s failed: VkResult %d\n", __FILE__, __LINE__, #call, (int)r_); \
      exit(1);                                                                                \
    }                                                                                         \
  } while (0)

/* `status` is `expected` and the last error contains `part`. */
static void expect_error(ocean_status status, ocean_status expected, const char* part) {
  if (status != expected || strstr(ocean_last_error(), part) == NULL) {
    fprintf(stderr, "expected %s containing '%s', got %s: '%s'\n", ocean_status_name(expected),
            part, ocean_status_name(status), ocean_last_error());
    ++g_failures;
  }
}

static int skip(const char* why) {
  const char* require = getenv("OCEAN_REQUIRE_DEVICES");
  if (require != NULL && strcmp(require, "") != 0 && strcmp(require, "0") != 0) {
    fprintf(stderr, "no Vulkan device (required): %s\n", why);
    return 1;
  }
  printf("skipped: %s\n", why);
  return 77;
}

/* IEEE 754 binary16 to float, exactly. */
static float half_to_float(uint16_t h) {
  const int sign = (h >> 15) & 1, exponent = (h >> 10) & 31, mantissa = h & 1023;
  float v;
  if (exponent == 0) {
    v = ldexpf((float)mantissa, -24);
  } else if (exponent == 31) {
    v = mantissa != 0 ? NAN : INFINITY;
  } else {
    v = ldexpf((float)(mantissa + 1024), exponent - 25);
  }
  return sign ? -v : v;
}

/* Distance in units in the last place between two finite halves of one sign convention. */
static int half_ulps(uint16_t a, uint16_t b) {
  const int ia = (a & 0x8000) ? -(int)(a & 0x7FFF) : (int)a;
  const int ib = (b & 0x8000) ? -(int)(b & 0x7FFF) : (int)b;
  return abs(ia - ib);
}

typedef struct Engine {
  VkInstance instance;
  VkDebugUtilsMessengerEXT messenger;
  VkPhysicalDevice physical;
  VkDevice device;
  uint32_t family;
  VkQueue queue;
  VkPhysicalDeviceMemoryProperties memory;
  VkCommandPool pool;
  VkCommandBuffer cmd;
  VkFence fence;
  VkBuffer buffer;
  VkDeviceMemory buffer_memory;
  void* mapped;
  VkDeviceSize buffer_bytes;
} Engine;

/* 0 on success, else the reason there is no device. */
static const char* make_engine(Engine* e) {
  const VkApplicationInfo app = {
      VK_STRUCTURE_TYPE_APPLICATION_INFO, NULL, "engine", 1, NULL, 0, VK_API_VERSION_1_2};
  VkInstanceCreateInfo info;
  uint32_t count = 0, d, f;
  VkPhysicalDevice devices[16];
  const char* layer = "VK_LAYER_KHRONOS_validation";
  const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
  const int validation = has_layer(layer);
  VkDebugUtilsMessengerCreateInfoEXT messenger;
  memset(&messenger, 0, sizeof messenger);
  messenger.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
  messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger.messageType =
      VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
  messenger.pfnUserCallback = on_message;
  memset(&info, 0, sizeof info);
  info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  info.pNext = validation ? &messenger : NULL;
  info.pApplicationInfo = &app;
  info.enabledLayerCount = validation ? 1u : 0u;
  info.ppEnabledLayerNames = &layer;
  info.enabledExtensionCount = validation ? 1u : 0u;
  info.ppEnabledExtensionNames = &extension;
  if (vkCreateInstance(&info, NULL, &e->instance) != VK_SUCCESS)
    return "no Vulkan loader or driver";
  printf("validation layer: %s\n", validation ? "on" : "not installed");
  if (validation) {
    PFN_vkCreateDebugUtilsMessengerEXT create =
        (PFN_vkCreateDebugUtilsMessengerEXT)(void (*)(void))vkGetInstanceProcAddr(
            e->instance, "vkCreateDebugUtilsMessengerEXT");
    CHECK(create != NULL);
    if (create != NULL) REQUIRE_VK(create(e->instance, &messenger, NULL, &e->messenger));
  }
  vkEnumeratePhysicalDevices(e->instance, &count, NULL);
  if (count > 16) count = 16;
  vkEnumeratePhysicalDevices(e->instance, &count, devices);
  e->physical = VK_NULL_HANDLE;
  for (d = 0; d < count && e->physical == VK_NULL_HANDLE; ++d) {
    VkPhysicalDeviceProperties p;
    VkQueueFamilyProperties families[16];
    uint32_t n = 16;
    vkGetPhysicalDeviceProperties(devices[d], &p);
    if (p.apiVersion < VK_API_VERSION_1_2) continue;
    vkGetPhysicalDeviceQueueFamilyProperties(devices[d], &n, families);
    for (f = 0; f < n; ++f) {
      if (families[f].queueFlags & VK_QUEUE_COMPUTE_BIT) {
        e->physical = devices[d];
        e->family = f;
        break;
      }
    }
  }
  if (e->physical == VK_NULL_HANDLE) return "no Vulkan 1.2 device with a compute queue";
  {
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue;
    VkDeviceCreateInfo device_info;
    memset(&queue, 0, sizeof queue);
    queue.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    queue.queueFamilyIndex = e->family;
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;
    memset(&device_info, 0, sizeof device_info);
    device_info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    device_info.queueCreateInfoCount = 1;
    device_info.pQueueCreateInfos = &queue;
    REQUIRE_VK(vkCreateDevice(e->physical, &device_info, NULL, &e->device));
  }
  vkGetDeviceQueue(e->device, e->family, 0, &e->queue);
  vkGetPhysicalDeviceMemoryProperties(e->physical, &e->memory);
  {
    VkCommandPoolCreateInfo pool_info;
    VkCommandBufferAllocateInfo alloc;
    VkFenceCreateInfo fence_info;
    memset(&pool_info, 0, sizeof pool_info);
    pool_info.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool_info.queueFamilyIndex = e->family;
    REQUIRE_VK(vkCreateCommandPool(e->device, &pool_info, NULL, &e->pool));
    memset(&alloc, 0, sizeof alloc);
    alloc.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    alloc.commandPool = e->pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    REQUIRE_VK(vkAllocateCommandBuffers(e->device, &alloc, &e->cmd));
    memset(&fence_info, 0, sizeof fence_info);
    fence_info.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    REQUIRE_VK(vkCreateFence(e->device, &fence_info, NULL, &e->fence));
  }
  return NULL;
}

/* A host-visible, coherent buffer of `bytes` for the copies. */
static void make_readback(Engine* e, VkDeviceSize bytes) {
  VkBufferCreateInfo info;
  VkMemoryRequirements req;
  VkMemoryAllocateInfo alloc;
  const VkMemoryPropertyFlags want =
      VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  uint32_t t;
  memset(&info, 0, sizeof info);
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = bytes;
  info.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  REQUIRE_VK(vkCreateBuffer(e->device, &info, NULL, &e->buffer));
  vkGetBufferMemoryRequirements(e->device, e->buffer, &req);
  memset(&alloc, 0, sizeof alloc);
  alloc.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = UINT32_MAX;
  for (t = 0; t < e->memory.memoryTypeCount; ++t) {
    if ((req.memoryTypeBits & (1u << t)) &&
        (e->memory.memoryTypes[t].propertyFlags & want) == want) {
      alloc.memoryTypeIndex = t;
      break;
    }
  }
  CHECK(alloc.memoryTypeIndex != UINT32_MAX);
  REQUIRE_VK(vkAllocateMemory(e->device, &alloc, NULL, &e->buffer_memory));
  REQUIRE_VK(vkBindBufferMemory(e->device, e->buffer, e->buffer_memory, 0));
  REQUIRE_VK(vkMapMemory(e->device, e->buffer_memory, 0, VK_WHOLE_SIZE, 0, &e->mapped));
  e->buffer_bytes = bytes;
}

/* Copies every layer and mip level of `image` into the readback buffer, level by level (level
 * l: every layer's (N >> l)² texels, layer after layer), with the barrier the image asks for
 * first; submits on the engine's queue and waits. Returns the bytes written. */
static VkDeviceSize copy_image(Engine* e, const ocean_vulkan_image* image, uint32_t texel_bytes) {
  VkCommandBufferBeginInfo begin;
  VkImageMemoryBarrier barrier;
  VkSubmitInfo submit;
  VkDeviceSize offset = 0;
  uint32_t level, layer;
  const VkImage handle = (VkImage)(uintptr_t)image->image;
  memset(&begin, 0, sizeof begin);
  begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  REQUIRE_VK(vkResetCommandBuffer(e->cmd, 0));
  REQUIRE_VK(vkBeginCommandBuffer(e->cmd, &begin));
  memset(&barrier, 0, sizeof barrier);
  barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
  barrier.srcAccessMask = image->src_access_mask;
  barrier.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  barrier.oldLayout = (VkImageLayout)image->layout;
  barrier.newLayout = (VkImageLayout)image->layout;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = handle;
  barrier.subresourceRange.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
  barrier.subresourceRange.levelCount = image->mip_levels;
  barrier.subresourceRange.layerCount = image->layers;
  vkCmdPipelineBarrier(e->cmd, image->src_stage_mask, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, NULL, 0,
                       NULL, 1, &barrier);
  for (level = 0; level < image->mip_levels; ++level) {
    const uint32_t size = image->width >> level;
    for (layer = 0; layer < image->layers; ++layer) {
      VkBufferImageCopy region;
      memset(&region, 0, sizeof region);
      region.bufferOffset = offset;
      region.imageSubresource.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
      region.imageSubresource.mipLevel = level;
      region.imageSubresource.baseArrayLayer = layer;
      region.imageSubresource.layerCount = 1;
      region.imageExtent.width = size;
      region.imageExtent.height = size;
      region.imageExtent.depth = 1;
      vkCmdCopyImageToBuffer(e->cmd, handle, (VkImageLayout)image->layout, e->buffer, 1, &region);
      offset += (VkDeviceSize)size * size * texel_bytes;
    }
  }
  {
    VkMemoryBarrier to_host;
    memset(&to_host, 0, sizeof to_host);
    to_host.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(e->cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &to_host, 0, NULL, 0, NULL);
  }
  REQUIRE_VK(vkEndCommandBuffer(e->cmd));
  memset(&submit, 0, sizeof submit);
  submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &e->cmd;
  REQUIRE_VK(vkQueueSubmit(e->queue, 1, &submit, e->fence));
  REQUIRE_VK(vkWaitForFences(e->device, 1, &e->fence, VK_TRUE, UINT64_MAX));
  REQUIRE_VK(vkResetFences(e->device, 1, &e->fence));
  CHECK(offset <= e->buffer_bytes);
  return offset;
}

static ocean_field_view field_of(const ocean_simulator* sim, size_t cascade, ocean_field field,
                                 int32_t level) {
  ocean_field_view v;
  memset(&v, 0, sizeof v);
  v.struct_size = sizeof v;
  REQUIRE_OK(ocean_simulator_field(sim, cascade, field, level, &v));
  return v;
}

/* Hs = 4·√(Σ_c var h_c) of the CPU frame (conformance.hpp). */
static double significant_height(const ocean_simulator* cpu, size_t cascades) {
  double variance = 0.0;
  size_t c, i;
  for (c = 0; c < cascades; ++c) {
    const ocean_field_view v = field_of(cpu, c, OCEAN_FIELD_DISPLACEMENT, 0);
    const float* d = (const float*)v.data;
    const size_t n = (size_t)v.width * (size_t)v.height;
    double sum = 0.0, sum2 = 0.0;
    for (i = 0; i < n; ++i) {
      sum += d[3 * i + 1];
      sum2 += (double)d[3 * i + 1] * d[3 * i + 1];
    }
    variance += sum2 / (double)n - (sum / (double)n) * (sum / (double)n);
  }
  return 4.0 * sqrt(variance);
}

/* Compares both images of `gpu` with its own fields and with `cpu`'s at the published frame. */
static void compare_frame(Engine* e, const ocean_simulator* gpu, const ocean_simulator* cpu,
                          size_t cascades) {
  ocean_vulkan_image disp, packed;
  uint64_t index = 0;
  size_t c, i;
  int32_t level;
  const double hs = significant_height(cpu, cascades);
  double worst_disp = 0.0; /* max |ΔD| / (2^-10·|D| + 8e-6·Hs) against the CPU */
  int worst_half_ulps = 0, worst_lsb_cpu = 0, worst_lsb_self = 0;
  size_t packed_texels = 0, packed_differ = 0;
  memset(&disp, 0, sizeof disp);
  memset(&packed, 0, sizeof packed);
  disp.struct_size = packed.struct_size = sizeof disp;
  REQUIRE_OK(ocean_simulator_vulkan_image(gpu, OCEAN_FIELD_DISPLACEMENT_HALF, &disp));
  REQUIRE_OK(ocean_simulator_vulkan_image(gpu, OCEAN_FIELD_PACKED, &packed));
  REQUIRE_OK(ocean_simulator_frame_time(gpu, NULL, &index));
  CHECK(disp.frame_index == index && packed.frame_index == index);
  CHECK(disp.format == VK_FORMAT_R16G16B16A16_SFLOAT && packed.format == VK_FORMAT_R8G8B8A8_UNORM);
  CHECK(disp.layout == VK_IMAGE_LAYOUT_GENERAL && packed.layout == VK_IMAGE_LAYOUT_GENERAL);
  CHECK(disp.layers == cascades && packed.layers == cascades);
  CHECK(disp.mip_levels == 1 && (1u << (packed.mip_levels - 1)) == packed.width);
  CHECK(disp.view != 0 && packed.view != 0 && disp.image != packed.image);
  CHECK((disp.usage & VK_IMAGE_USAGE_SAMPLED_BIT) &&
        (packed.usage & VK_IMAGE_USAGE_TRANSFER_SRC_BIT));

  /* Displacement: layer c is cascade c, N² half4 texels. */
  copy_image(e, &disp, 8);
  for (c = 0; c < cascades; ++c) {
    const uint16_t* image = (const uint16_t*)e->mapped + (size_t)4 * disp.width * disp.height * c;
    const ocean_field_view self = field_of(gpu, c, OCEAN_FIELD_DISPLACEMENT_HALF, 0);
    const ocean_field_view ref = field_of(cpu, c, OCEAN_FIELD_DISPLACEMENT, 0);
    const uint16_t* own = (const uint16_t*)self.data;
    const float* d = (const float*)ref.data;
    CHECK(self.width == (int32_t)disp.width && ref.width == (int32_t)disp.width);
    for (i = 0; i < (size_t)disp.width * disp.height; ++i) {
      int k;
      for (k = 0; k < 3; ++k) {
        const double got = half_to_float(image[4 * i + (size_t)k]);
        const double want = d[3 * i + (size_t)k];
        const double ratio = fabs(got - want) / (ldexp(fabs(want), -10) + 8e-6 * hs);
        const int ulps = half_ulps(image[4 * i + (size_t)k], own[4 * i + (size_t)k]);
        if (ratio > worst_disp) worst_disp = ratio;
        if (ulps > worst_half_ulps) worst_half_ulps = ulps;
      }
    }
  }
  /* Packed: level by level, layer by layer in the copy; the field's level l of cascade c. */
  copy_image(e, &packed, 4);
  {
    const uint8_t* image = (const uint8_t*)e->mapped;
    for (level = 0; level < (int32_t)packed.mip_levels; ++level) {
      const size_t size = packed.width >> level;
      for (c = 0; c < cascades; ++c) {
        const uint8_t* own = (const uint8_t*)field_of(gpu, c, OCEAN_FIELD_PACKED, level).data;
        const uint8_t* ref = (const uint8_t*)field_of(cpu, c, OCEAN_FIELD_PACKED, level).data;
        for (i = 0; i < size * size; ++i) {
          int k, differs = 0;
          for (k = 0; k < 4; ++k) {
            const int to_cpu = abs((int)image[4 * i + (size_t)k] - (int)ref[4 * i + (size_t)k]);
            const int to_self = abs((int)image[4 * i + (size_t)k] - (int)own[4 * i + (size_t)k]);
            if (to_cpu > worst_lsb_cpu) worst_lsb_cpu = to_cpu;
            if (to_self > worst_lsb_self) worst_lsb_self = to_self;
            if (to_cpu != 0) differs = 1;
          }
          packed_differ += (size_t)differs;
          ++packed_texels;
        }
        image += 4 * size * size;
      }
    }
  }
  printf(
      "frame %llu: Hs %.4f m; half displacement vs CPU max |dD|/(2^-10|D| + 8e-6 Hs) = %.3g; "
      "vs its own readback %d ulp; packed vs CPU %d LSB, %zu of %zu texels differ (%.2g); "
      "vs its own readback %d LSB\n",
      (unsigned long long)index, hs, worst_disp, worst_half_ulps, worst_lsb_cpu, packed_differ,
      packed_texels, (double)packed_differ / (double)packed_texels, worst_lsb_self);
  CHECK(hs > 0.1);
  CHECK(worst_disp <= 1.0);
  CHECK(worst_half_ulps <= 1);
  CHECK(worst_lsb_cpu <= 1);
  CHECK((double)packed_differ <= 6e-4 * (double)packed_texels);
  CHECK(worst_lsb_self <= 1);
}

int main(void) {
  Engine e;
  ocean_config* config = NULL;
  ocean_simulator *gpu = NULL, *cpu = NULL, *bad = NULL;
  ocean_simulator_options options;
  ocean_vulkan_device device;
  ocean_vulkan_image image;
  ocean_field_view view;
  size_t cascades = 0, other = 0;
  const char* why;
  memset(&e, 0, sizeof e);
  why = make_engine(&e);
  if (why != NULL) return skip(why);

  REQUIRE_OK(ocean_config_create(&config));
  REQUIRE_OK(ocean_config_merge_preset(config, "moderate"));
  REQUIRE_OK(ocean_config_set(config, "resolution=64"));
  memset(&device, 0, sizeof device);
  device.struct_size = sizeof device;
  device.instance = e.instance;
  device.physical_device = e.physical;
  device.device = e.device;
  device.queue_family = e.family;
  device.queue = e.queue;
  device.api_version = VK_API_VERSION_1_2;
  ocean_simulator_options_init(&options);
  options.threads = 1;
  REQUIRE_OK(ocean_simulator_create_on_vulkan(config, &device, &options, &gpu));
  REQUIRE_OK(ocean_simulator_create_with_options(config, &options, &cpu));
  REQUIRE_OK(ocean_simulator_cascade_count(gpu, &cascades));
  REQUIRE_OK(ocean_simulator_cascade_count(cpu, &other));
  CHECK(cascades >= 2 && cascades == other);
  make_readback(&e, (VkDeviceSize)8 * 64 * 64 * cascades * 2);

  /* Two frames: the images follow the published frame (foam accumulates between them). */
  REQUIRE_OK(ocean_simulator_step(gpu, 1.7));
  REQUIRE_OK(ocean_simulator_step(cpu, 1.7));
  compare_frame(&e, gpu, cpu, cascades);
  REQUIRE_OK(ocean_simulator_kick(gpu, 2.3));
  REQUIRE_OK(ocean_simulator_wait(gpu));
  REQUIRE_OK(ocean_simulator_step(cpu, 2.3));
  compare_frame(&e, gpu, cpu, cascades);

  /* Errors: one line each, outputs untouched. */
  memset(&image, 0, sizeof image);
  image.struct_size = sizeof image;
  expect_error(ocean_simulator_vulkan_image(cpu, OCEAN_FIELD_PACKED, &image), OCEAN_UNSUPPORTED,
               "runs on the 'cpu' backend");
  expect_error(ocean_simulator_vulkan_image(gpu, OCEAN_FIELD_NORMAL, &image), OCEAN_UNSUPPORTED,
               "ocean_simulator_field");
  expect_error(ocean_simulator_vulkan_image(gpu, (ocean_field)42, &image), OCEAN_INVALID_ARGUMENT,
               "field = 42 is out of range");
  CHECK(image.image == 0 && image.view == 0);
  image.struct_size = 8;
  expect_error(ocean_simulator_vulkan_image(gpu, OCEAN_FIELD_PACKED, &image),
               OCEAN_INVALID_ARGUMENT, "image->struct_size = 8 is too small");
  expect_error(ocean_simulator_vulkan_image(gpu, OCEAN_FIELD_PACKED, NULL), OCEAN_INVALID_ARGUMENT,
               "image is NULL");
  memset(&view, 0, sizeof view);
  view.struct_size = sizeof view;
  expect_error(ocean_simulator_cuda_field(gpu, 0, OCEAN_FIELD_DISPLACEMENT, 0, &view, NULL),
               OCEAN_UNSUPPORTED, "runs on the 'vulkan' backend");
  CHECK(view.data == NULL);
  expect_error(ocean_simulator_cuda_field(NULL, 0, OCEAN_FIELD_DISPLACEMENT, 0, &view, NULL),
               OCEAN_INVALID_ARGUMENT, "simulator is NULL");
  expect_error(ocean_simulator_create_on_vulkan(config, NULL, NULL, &bad), OCEAN_INVALID_ARGUMENT,
               "device is NULL");
  device.api_version = 0;
  expect_error(ocean_simulator_create_on_vulkan(config, &device, NULL, &bad),
               OCEAN_INVALID_ARGUMENT, "ocean_simulator_create_on_vulkan: api_version not stated");
  device.api_version = VK_API_VERSION_1_2;
  device.queue_family = 1000;
  expect_error(ocean_simulator_create_on_vulkan(config, &device, NULL, &bad),
               OCEAN_INVALID_ARGUMENT, "queue family 1000 is out of range");
  device.queue_family = e.family;
  device.struct_size = 4;
  expect_error(ocean_simulator_create_on_vulkan(config, &device, NULL, &bad),
               OCEAN_INVALID_ARGUMENT, "device->struct_size = 4 is too small");
  device.struct_size = sizeof device;
  options.outputs = OCEAN_OUTPUT_DEFAULT | OCEAN_OUTPUT_VELOCITY;
  expect_error(ocean_simulator_create_on_vulkan(config, &device, &options, &bad), OCEAN_UNSUPPORTED,
               "velocity");
  CHECK(bad == NULL);

  /* The library's objects first, then the engine's device and instance. */
  ocean_simulator_destroy(gpu);
  ocean_simulator_destroy(cpu);
  ocean_config_destroy(config);
  vkUnmapMemory(e.device, e.buffer_memory);
  vkDestroyBuffer(e.device, e.buffer, NULL);
  vkFreeMemory(e.device, e.buffer_memory, NULL);
  vkDestroyFence(e.device, e.fence, NULL);
  vkDestroyCommandPool(e.device, e.pool, NULL);
  vkDestroyDevice(e.device, NULL);
  if (e.messenger != VK_NULL_HANDLE) {
    PFN_vkDestroyDebugUtilsMessengerEXT destroy =
        (PFN_vkDestroyDebugUtilsMessengerEXT)(void (*)(void))vkGetInstanceProcAddr(
            e.instance, "vkDestroyDebugUtilsMessengerEXT");
    if (destroy != NULL) destroy(e.instance, e.messenger, NULL);
  }
  vkDestroyInstance(e.instance, NULL);
  if (g_validation_messages != 0) {
    fprintf(stderr, "%d validation message(s), the last: %s\n", g_validation_messages,
            g_last_message);
    ++g_failures;
  }
  if (g_failures != 0) {
    fprintf(stderr, "%d check(s) failed\n", g_failures);
    return 1;
  }
  printf("ok\n");
  return 0;
}
