// The test OpenXR runtime's state, shared by its two files: runtime.cpp (instance, system,
// session, events, frame timing, the checks of xrEndFrame) and swapchains.cpp (Vulkan images
// on the application's device, and reading back what the application wrote into them).
#pragma once

#include <vulkan/vulkan.h>
#define XR_USE_GRAPHICS_API_VULKAN
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>

#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

namespace ocean::test_xr {

// The HMD this runtime pretends to be: two eyes 64 mm apart, square eye images of kEyeSize
// pixels (small, so that lavapipe renders a frame quickly), the head turning slowly about +Y so
// that every frame's poses differ and rolled by kRoll_rad (counter-clockwise as the wearer sees
// it: the left ear down). Each eye's field of view is asymmetric as a real headset's: wider
// outwards than towards the nose and downwards than upwards (the left eye's is the right eye's
// mirrored).
inline constexpr std::uint32_t kEyeSize = 96;
inline constexpr float kIpd_m = 0.064f;
inline constexpr float kOuterFov_rad = 0.90f;  // from the axis to the outer side
inline constexpr float kInnerFov_rad = 0.70f;  // to the side towards the nose
inline constexpr float kUpFov_rad = 0.60f;
inline constexpr float kDownFov_rad = 0.85f;
inline constexpr double kRoll_rad = 0.20;
inline constexpr double kYawRate_rad_per_s = 0.05;
inline constexpr std::int64_t kDefaultPeriod_ns = 11'111'111;  // 90 Hz

struct Swapchain {
  std::uint32_t width = 0, height = 0;
  VkFormat format = VK_FORMAT_UNDEFINED;
  std::vector<VkImage> images;
  std::vector<VkDeviceMemory> memory;
  std::uint32_t next = 0;                 // the next image to acquire
  std::deque<std::uint32_t> acquired;     // acquired, not yet released, oldest first
  std::int64_t released = -1;             // the last released image, read back at xrEndFrame
  bool released_since_end_frame = false;  // an image was released during this frame
};

struct Runtime {
  bool instance = false;
  bool requirements_queried = false;
  // The session and the application's Vulkan objects it was created with.
  bool session = false;
  XrGraphicsBindingVulkanKHR binding{};
  VkQueue queue = VK_NULL_HANDLE;
  VkCommandPool pool = VK_NULL_HANDLE;
  std::deque<XrSessionState> events;
  bool running = false;  // between xrBeginSession and xrEndSession
  std::vector<std::unique_ptr<Swapchain>> swapchains;
  // Frame timing.
  std::int64_t period_ns = kDefaultPeriod_ns;
  std::int64_t next_display_ns = 0;  // the next predicted display time
  std::int64_t predicted_ns = 0;     // what the last xrWaitFrame predicted
  std::int64_t first_predicted_ns = 0;
  bool waited = false, begun = false;
  std::array<XrView, 2> located{};  // xrLocateViews' answer for predicted_ns
  bool located_valid = false;
  // What the checks found; written to $OCEAN_TEST_XR_REPORT at xrDestroyInstance.
  std::int64_t frames = 0, views = 0, images_checked = 0, images_lit = 0;
  double min_lit_fraction = 1.0;
  std::vector<std::string> problems;
  // With $OCEAN_TEST_XR_IMAGES: the folder each frame's eye images are written to (view0.png,
  // view1.png, the last frame's kept) and the views they were drawn for.
  std::string image_dir;
  std::array<XrView, 2> saved{};
  bool images_saved = false;
};

Runtime& runtime();
/// Records a failed check ("frame 3: ..."), kept for the report (at most 50).
void problem(const std::string& text);

// swapchains.cpp
XrResult create_swapchain(const XrSwapchainCreateInfo& info, XrSwapchain* out);
void destroy_swapchain(Swapchain& s);
/// The image's pixels read back from the application's device as RGBA8 (BGRA swapped), top row
/// first; false when reading failed.
bool read_back(Swapchain& s, std::uint32_t image, std::vector<std::uint8_t>& rgba);
/// Writes RGBA8 pixels as a PNG; false when it cannot.
bool write_png(const std::string& path, std::uint32_t width, std::uint32_t height,
               const std::vector<std::uint8_t>& rgba);
/// Command pool on the application's queue family; false when Vulkan fails.
bool open_device_queue();
void close_device_queue();

}  // namespace ocean::test_xr
