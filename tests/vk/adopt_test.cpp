// adopt_context: the test creates its own instance (with the Khronos validation layer and its own
// messenger where the layer is installed) and device with plain Vulkan calls, hands them to the
// library, runs the Vulkan compute backend on them and compares a frame with the CPU reference
// pipeline (ocean/conformance.hpp), draws with the renderer and compares the pixels with a
// library-created context's, destroys the library objects and then its own device and instance.
// Missing requirements give one clear line. Skips where no Vulkan device exists (fails with
// OCEAN_REQUIRE_DEVICES=1).
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "ocean/backends.hpp"
#include "ocean/backends/cpu.hpp"
#include "ocean/backends/vulkan.hpp"
#include "ocean/conformance.hpp"
#include "ocean/render.hpp"
#include "ocean/vk.hpp"
#include "support/require_devices.hpp"

namespace {

std::atomic<int> g_messages{0};
std::string g_last_message;

VKAPI_ATTR VkBool32 VKAPI_CALL count_message(VkDebugUtilsMessageSeverityFlagBitsEXT /*severity*/,
                                             VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data,
                                             void* /*user*/) {
  ++g_messages;
  g_last_message = data->pMessage != nullptr ? data->pMessage : "";
  return VK_FALSE;
}

bool has_instance_layer(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& l) {
    return std::strcmp(l.layerName, name) == 0;
  });
}

// An engine's Vulkan objects, made without the library: Vulkan 1.3 instance, the first device
// with Vulkan ≥ 1.2 and a compute queue family, one queue, no features, no extensions. With
// graphics(): a Vulkan 1.3 device with a graphics+compute family, dynamic rendering on, and
// fillModeNonSolid and samplerAnisotropy where supported (what create_context enables).
class EngineDevice : public ::testing::Test {
 protected:
  [[nodiscard]] virtual bool graphics() const { return false; }

  void SetUp() override {
    g_messages = 0;
    const char* layer = "VK_LAYER_KHRONOS_validation";
    validation_ = has_instance_layer(layer);
    const VkApplicationInfo app{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
                                .pApplicationName = "engine",
                                .apiVersion = kApiVersion};
    const VkDebugUtilsMessengerCreateInfoEXT messenger_info{
        .sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
        .messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                           VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
        .messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT,
        .pfnUserCallback = count_message};
    const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    const VkInstanceCreateInfo info{.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
                                    .pNext = validation_ ? &messenger_info : nullptr,
                                    .pApplicationInfo = &app,
                                    .enabledLayerCount = validation_ ? 1u : 0u,
                                    .ppEnabledLayerNames = &layer,
                                    .enabledExtensionCount = validation_ ? 1u : 0u,
                                    .ppEnabledExtensionNames = &extension};
    if (vkCreateInstance(&info, nullptr, &instance_) != VK_SUCCESS) {
      instance_ = VK_NULL_HANDLE;
      // The loader's own message on the way ("Found no drivers!") is not one about our use of
      // Vulkan, which TearDown counts.
      g_messages = 0;
      OCEAN_SKIP_OR_FAIL("no Vulkan loader or driver");
    }
    if (validation_) {
      auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
      ASSERT_NE(create, nullptr);
      ASSERT_EQ(create(instance_, &messenger_info, nullptr, &messenger_), VK_SUCCESS);
    }
    std::uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance_, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(instance_, &count, devices.data());
    const VkQueueFlags need = VK_QUEUE_COMPUTE_BIT | (graphics() ? VK_QUEUE_GRAPHICS_BIT : 0);
    for (VkPhysicalDevice d : devices) {
      VkPhysicalDeviceProperties p;
      vkGetPhysicalDeviceProperties(d, &p);
      if (p.apiVersion < (graphics() ? VK_API_VERSION_1_3 : VK_API_VERSION_1_2)) continue;
      std::uint32_t n = 0;
      vkGetPhysicalDeviceQueueFamilyProperties(d, &n, nullptr);
      std::vector<VkQueueFamilyProperties> families(n);
      vkGetPhysicalDeviceQueueFamilyProperties(d, &n, families.data());
      for (std::uint32_t f = 0; f < n; ++f) {
        if ((families[f].queueFlags & need) == need) {
          physical_ = d;
          family_ = f;
          families_ = n;
          break;
        }
      }
      if (physical_ != VK_NULL_HANDLE) break;
    }
    if (physical_ == VK_NULL_HANDLE) OCEAN_SKIP_OR_FAIL("no Vulkan device with the queue needed");
    VkPhysicalDeviceVulkan13Features supported13{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceFeatures2 supported{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
                                        .pNext = &supported13};
    vkGetPhysicalDeviceFeatures2(physical_, &supported);
    VkPhysicalDeviceVulkan13Features enabled13{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceFeatures2 enabled{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
                                      .pNext = &enabled13};
    if (graphics()) {
      if (supported13.dynamicRendering != VK_TRUE) OCEAN_SKIP_OR_FAIL("no dynamic rendering");
      enabled13.dynamicRendering = VK_TRUE;
      enabled.features.fillModeNonSolid = supported.features.fillModeNonSolid;
      enabled.features.samplerAnisotropy = supported.features.samplerAnisotropy;
    }
    const float priority = 1.0f;
    const VkDeviceQueueCreateInfo queue{.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
                                        .queueFamilyIndex = family_,
                                        .queueCount = 1,
                                        .pQueuePriorities = &priority};
    const VkDeviceCreateInfo device_info{.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
                                         .pNext = graphics() ? &enabled : nullptr,
                                         .queueCreateInfoCount = 1,
                                         .pQueueCreateInfos = &queue};
    ASSERT_EQ(vkCreateDevice(physical_, &device_info, nullptr, &device_), VK_SUCCESS);
    vkGetDeviceQueue(device_, family_, 0, &queue_);
    features_ = enabled.features;
  }

  void TearDown() override {
    if (device_ != VK_NULL_HANDLE) vkDestroyDevice(device_, nullptr);
    if (messenger_ != VK_NULL_HANDLE) {
      auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
      destroy(instance_, messenger_, nullptr);
    }
    if (instance_ != VK_NULL_HANDLE) vkDestroyInstance(instance_, nullptr);
    EXPECT_EQ(g_messages.load(), 0) << g_last_message;
  }

  [[nodiscard]] ocean::vk::AdoptedDevice handles() const {
    return {.instance = instance_,
            .physical = physical_,
            .device = device_,
            .queue_family = family_,
            .queue = queue_,
            .api_version = kApiVersion,
            .graphics = graphics(),
            .dynamic_rendering = graphics(),
            .fill_mode_non_solid = features_.fillModeNonSolid == VK_TRUE,
            .sampler_anisotropy = features_.samplerAnisotropy == VK_TRUE};
  }

  static constexpr std::uint32_t kApiVersion = VK_API_VERSION_1_3;
  bool validation_ = false;
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  std::uint32_t family_ = 0, families_ = 0;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkPhysicalDeviceFeatures features_{};
};

class EngineGraphicsDevice : public EngineDevice {
 protected:
  [[nodiscard]] bool graphics() const override { return true; }
};

TEST_F(EngineDevice, VulkanBackendOnAnAdoptedDeviceMatchesTheCpuReference) {
  auto adopted = ocean::vk::adopt_context(handles());
  ASSERT_TRUE(adopted.ok()) << adopted.status().message();
  std::shared_ptr<ocean::vk::Context> ctx = std::move(adopted.value());
  EXPECT_TRUE(ctx->adopted);
  EXPECT_EQ(ctx->device, device_);
  EXPECT_EQ(ctx->queue, queue_);
  EXPECT_FALSE(ctx->graphics);
  EXPECT_TRUE(ctx->info.usable);

  ocean::SimulationConfig config;
  config.resolution = 64;
  config.cascade_patch_sizes_m = {500.0, 110.0};
  std::unique_ptr<ocean::TaskRunner> runner = ocean::make_serial_runner();
  // The conformance reference (ocean/conformance.hpp): the scalar CPU pipeline.
  auto reference =
      ocean::cpu::make_cpu_backend({.pipeline = ocean::cpu::CpuPipeline::scalar_reference});
  ASSERT_TRUE(reference->configure(config, *runner).ok());
  ocean::Frame ref, got;
  reference->allocate(ref);
  {
    ocean::vk::VulkanBackend backend(ctx);
    const ocean::Status configured = backend.configure(config, *runner);
    ASSERT_TRUE(configured.ok()) << configured.message();
    backend.allocate(got);
    for (const double t : {3.0, 3.1}) {
      reference->step(t, ref);
      backend.step(t, got);
      ASSERT_TRUE(backend.status().ok()) << backend.status().message();
    }
  }
  ASSERT_EQ(ref.cascades.size(), got.cascades.size());
  for (std::size_t c = 0; c < ref.cascades.size(); ++c) {
    const auto& g = got.cascades[c].displacement;
    ASSERT_EQ(ref.cascades[c].displacement.size(), g.size());
    for (std::size_t i = 0; i < g.size(); ++i)
      ASSERT_TRUE(std::isfinite(g[i])) << "cascade " << c << ", index " << i;
  }
  // Every output within the conformance bounds of a GPU backend.
  const ocean::conformance::Bounds& bounds = ocean::conformance::kDeviceBounds;
  const ocean::conformance::Errors e = ocean::conformance::compare(ref, got, bounds);
  std::printf("adopted '%s' (validation layer %s): displacement error %.3g Hs, normal %.3g\n",
              ctx->info.name.c_str(), validation_ ? "on" : "not installed", e.displacement_rel_hs,
              e.normal);
  EXPECT_LE(e.displacement_rel_hs, bounds.displacement_rel_hs);
  EXPECT_TRUE(e.pass(bounds));

  // The library destroyed none of the adopted handles: the device still works after the
  // context is gone, and the test destroys it (TearDown) under the validation layer.
  ctx.reset();
  EXPECT_EQ(vkDeviceWaitIdle(device_), VK_SUCCESS);
  const VkFenceCreateInfo fence_info{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence = VK_NULL_HANDLE;
  ASSERT_EQ(vkCreateFence(device_, &fence_info, nullptr, &fence), VK_SUCCESS);
  vkDestroyFence(device_, fence, nullptr);
}

// The renderer draws on an adopted graphics device exactly what it draws on a context of its own
// on the same physical device (CPU upload path: the same bytes in, the same pixels out).
TEST_F(EngineGraphicsDevice, RendererOnAnAdoptedDeviceDrawsTheSamePixels) {
  ocean::SimulationConfig config;
  config.resolution = 64;
  config.cascade_patch_sizes_m = {200.0, 47.0};
  std::unique_ptr<ocean::TaskRunner> runner = ocean::make_serial_runner();
  auto backend = ocean::make_backend("cpu");
  ASSERT_TRUE(backend.ok()) << backend.status().message();
  ASSERT_TRUE(backend.value()->configure(config, *runner).ok());
  ocean::Frame frame;
  backend.value()->allocate(frame);
  backend.value()->step(5.0, frame);

  ocean::render::View view;
  view.camera = {.position_m = {0.0, 8.0, 0.0},
                 .target_m = {-100.0, 2.0, -70.0},
                 .fov_y_rad = 0.9,
                 .aspect = 1.5,
                 .near_m = 0.2,
                 .far_m = 2e5};
  view.quality = ocean::lod::quality_preset(ocean::lod::QualityPreset::low);
  view.ocean_size_m = 2048.0;
  const auto draw = [&](std::shared_ptr<ocean::vk::Context> ctx, std::vector<std::uint8_t>& rgba) {
    auto renderer = ocean::render::Renderer::make(std::move(ctx), {.width = 96, .height = 64});
    ASSERT_TRUE(renderer.ok()) << renderer.status().message();
    ASSERT_TRUE(
        renderer.value()->configure(ocean::SimulationPlan::make(config).value().surface()).ok());
    ASSERT_TRUE(renderer.value()->upload(frame).ok());
    const ocean::Status drawn = renderer.value()->draw(view);
    ASSERT_TRUE(drawn.ok()) << drawn.message();
    ASSERT_TRUE(renderer.value()->read_srgb(rgba).ok());
  };

  auto adopted = ocean::vk::adopt_context(handles());
  ASSERT_TRUE(adopted.ok()) << adopted.status().message();
  std::shared_ptr<ocean::vk::Context> ctx = std::move(adopted.value());
  EXPECT_TRUE(ctx->graphics);
  std::vector<std::uint8_t> on_adopted;
  draw(ctx, on_adopted);
  ctx.reset();

  // The library's own context on the same physical device, for the reference pixels.
  auto own = ocean::vk::create_context({.graphics = true});
  ASSERT_TRUE(own.ok()) << own.status().message();
  VkPhysicalDeviceProperties mine;  // handles differ between instances: compare the devices
  vkGetPhysicalDeviceProperties(physical_, &mine);
  const VkPhysicalDeviceProperties& theirs = own.value()->properties;
  if (theirs.vendorID != mine.vendorID || theirs.deviceID != mine.deviceID ||
      std::strcmp(theirs.deviceName, mine.deviceName) != 0)
    GTEST_SKIP() << "the library picks another device";
  std::vector<std::uint8_t> on_own;
  draw(std::move(own.value()), on_own);
  ASSERT_EQ(on_adopted.size(), std::size_t{96 * 64 * 4});
  EXPECT_TRUE(on_adopted == on_own) << "the adopted device drew different pixels";
  const bool lit =
      std::any_of(on_adopted.begin(), on_adopted.end(), [](std::uint8_t v) { return v > 16; });
  EXPECT_TRUE(lit) << "black image";
}

// Each missing requirement is one line of the expected kind that names what to change.
TEST_F(EngineDevice, MissingRequirementsAreOneClearError) {
  struct Bad {
    ocean::vk::AdoptedDevice handles;
    ocean::ErrorCode code;
    std::string names;
  };
  std::vector<Bad> cases;
  ocean::vk::AdoptedDevice no_version = handles();
  no_version.api_version = 0;
  cases.push_back({no_version, ocean::ErrorCode::invalid_argument, "apiVersion"});
  ocean::vk::AdoptedDevice old_version = handles();
  old_version.api_version = VK_API_VERSION_1_1;
  cases.push_back({old_version, ocean::ErrorCode::invalid_argument, "needs 1.2"});
  ocean::vk::AdoptedDevice no_device = handles();
  no_device.device = VK_NULL_HANDLE;
  cases.push_back({no_device, ocean::ErrorCode::invalid_argument, "must all be set"});
  ocean::vk::AdoptedDevice bad_family = handles();
  bad_family.queue_family = families_;
  cases.push_back({bad_family, ocean::ErrorCode::invalid_argument, "out of range"});
  // The device was created without dynamic rendering: the renderer cannot draw on it.
  ocean::vk::AdoptedDevice graphics = handles();
  graphics.graphics = true;
  cases.push_back({graphics, ocean::ErrorCode::invalid_argument, "dynamicRendering"});
  for (const Bad& bad : cases) {
    SCOPED_TRACE(bad.names);
    auto ctx = ocean::vk::adopt_context(bad.handles);
    ASSERT_FALSE(ctx.ok());
    EXPECT_EQ(ctx.status().code(), bad.code);
    EXPECT_NE(ctx.status().message().find(bad.names), std::string::npos) << ctx.status().message();
    EXPECT_EQ(ctx.status().message().find('\n'), std::string::npos);
  }
}

}  // namespace
