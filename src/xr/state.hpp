// The session's OpenXR and Vulkan handles (shared by session.cpp and frame.cpp).
#pragma once

#include <vulkan/vulkan.h>
#define XR_USE_GRAPHICS_API_VULKAN
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>

#include <array>
#include <string>
#include <vector>

#include "ocean/xr.hpp"

namespace ocean::xr {

/// One eye's swapchain and its images.
struct Eye {
  XrSwapchain swapchain = XR_NULL_HANDLE;
  std::vector<VkImage> images;
};

struct Session::State {
  std::shared_ptr<vk::Context> context;
  XrInstance instance = XR_NULL_HANDLE;
  XrSystemId system = XR_NULL_SYSTEM_ID;
  XrSession session = XR_NULL_HANDLE;
  XrSpace space = XR_NULL_HANDLE;
  XrSessionState state = XR_SESSION_STATE_UNKNOWN;
  bool begun = false;    // xrBeginSession succeeded, xrEndSession not yet called
  bool exiting = false;  // EXITING or LOSS_PENDING seen
  std::string runtime_name;
  std::uint32_t width = 0, height = 0;
  std::array<Eye, 2> eyes;
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  // The frame in progress.
  XrFrameState frame{XR_TYPE_FRAME_STATE};
  bool should_render = false;  // FrameState::should_render of the frame in progress
  std::array<XrView, 2> views{};
  std::array<XrCompositionLayerProjectionView, 2> layer_views{};
};

/// "<call> failed: <XrResult name>" as a Status, or ok.
Status check(XrInstance instance, XrResult result, const char* call);

}  // namespace ocean::xr
