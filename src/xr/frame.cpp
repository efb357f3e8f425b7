// The session's frame: xrWaitFrame → xrBeginFrame → xrLocateViews; each eye's picture copied
// into its swapchain image between xrAcquireSwapchainImage and xrReleaseSwapchainImage; and
// xrEndFrame with one projection layer at the predicted display time (OpenXR 1.0
// specification, "Frame Synchronization" and "Compositing").
#include <span>

#include "state.hpp"

namespace ocean::xr {

namespace {

Pose to_pose(const XrPosef& p) {
  return {{p.orientation.x, p.orientation.y, p.orientation.z, p.orientation.w},
          {p.position.x, p.position.y, p.position.z}};
}

// Copies `source` (TRANSFER_SRC_OPTIMAL) into the swapchain image, which the runtime hands over
// and takes back in COLOR_ATTACHMENT_OPTIMAL (XR_KHR_vulkan_enable). A blit, not a copy: the
// runtime may offer BGRA where the renderer writes RGBA.
void record_copy(VkCommandBuffer cmd, VkImage source, std::int32_t source_x, VkImage target,
                 std::int32_t w, std::int32_t h) {
  vk::barrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  vk::image_barrier(cmd, target, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0,
                    VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
  const VkImageBlit region{.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                           .srcOffsets = {{source_x, 0, 0}, {source_x + w, h, 1}},
                           .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                           .dstOffsets = {{0, 0, 0}, {w, h, 1}}};
  vkCmdBlitImage(cmd, source, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_NEAREST);
  vk::image_barrier(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                    VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT);
}

}  // namespace

Result<FrameState> Session::begin_frame() {
  State& st = *state_;
  st.frame = {XR_TYPE_FRAME_STATE};
  const XrFrameWaitInfo wait{XR_TYPE_FRAME_WAIT_INFO};
  if (Status s = check(st.instance, xrWaitFrame(st.session, &wait, &st.frame), "xrWaitFrame");
      !s.ok())
    return s;
  const XrFrameBeginInfo begin{XR_TYPE_FRAME_BEGIN_INFO};
  if (Status s = check(st.instance, xrBeginFrame(st.session, &begin), "xrBeginFrame"); !s.ok())
    return s;
  XrViewLocateInfo locate{XR_TYPE_VIEW_LOCATE_INFO};
  locate.viewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  locate.displayTime = st.frame.predictedDisplayTime;
  locate.space = st.space;
  XrViewState view_state{XR_TYPE_VIEW_STATE};
  st.views.fill({XR_TYPE_VIEW});
  std::uint32_t count = 0;
  if (Status s = check(st.instance,
                       xrLocateViews(st.session, &locate, &view_state, 2, &count, st.views.data()),
                       "xrLocateViews");
      !s.ok())
    return s;
  FrameState out;
  out.predicted_display_time_ns = st.frame.predictedDisplayTime;
  out.predicted_display_period_ns = st.frame.predictedDisplayPeriod;
  // Without a valid orientation the views cannot be drawn; the frame is ended with no layer.
  out.should_render = st.frame.shouldRender == XR_TRUE && count == 2 &&
                      (view_state.viewStateFlags & XR_VIEW_STATE_ORIENTATION_VALID_BIT) != 0;
  st.should_render = out.should_render;
  for (std::size_t i = 0; i < 2; ++i) {
    out.views[i] = {to_pose(st.views[i].pose),
                    {st.views[i].fov.angleLeft, st.views[i].fov.angleRight, st.views[i].fov.angleUp,
                     st.views[i].fov.angleDown}};
    st.layer_views[i] = {XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW};
    st.layer_views[i].pose = st.views[i].pose;
    st.layer_views[i].fov = st.views[i].fov;
    st.layer_views[i].subImage.swapchain = st.eyes[i].swapchain;
    st.layer_views[i].subImage.imageRect = {
        {0, 0}, {static_cast<std::int32_t>(st.width), static_cast<std::int32_t>(st.height)}};
  }
  return out;
}

namespace {

// Acquires the images of `eyes` (one or both), records `record` and a copy of each eye's part
// of `source` (x offset eye·width when `side_by_side`), submits, waits and releases them all.
Status submit_eyes(Session::State& st, std::span<const int> eyes,
                   FunctionRef<Status(VkCommandBuffer)> record, VkImage source, bool side_by_side) {
  std::array<std::uint32_t, 2> index{};
  std::size_t acquired = 0;
  Status status;
  for (; acquired < eyes.size() && status.ok(); ++acquired) {
    const Eye& e = st.eyes[static_cast<std::size_t>(eyes[acquired])];
    const XrSwapchainImageAcquireInfo acquire{XR_TYPE_SWAPCHAIN_IMAGE_ACQUIRE_INFO};
    status = check(st.instance, xrAcquireSwapchainImage(e.swapchain, &acquire, &index[acquired]),
                   "xrAcquireSwapchainImage");
    if (!status.ok()) break;
    XrSwapchainImageWaitInfo wait{XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO};
    wait.timeout = XR_INFINITE_DURATION;
    status = check(st.instance, xrWaitSwapchainImage(e.swapchain, &wait), "xrWaitSwapchainImage");
  }
  const VkDevice device = st.context->device;
  if (status.ok()) {
    vkResetCommandBuffer(st.cmd, 0);
    const VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                         .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    vkBeginCommandBuffer(st.cmd, &begin);
    status = record(st.cmd);
    for (std::size_t i = 0; i < eyes.size() && status.ok(); ++i) {
      const auto w = static_cast<std::int32_t>(st.width);
      record_copy(st.cmd, source, side_by_side ? eyes[i] * w : 0,
                  st.eyes[static_cast<std::size_t>(eyes[i])].images[index[i]], w,
                  static_cast<std::int32_t>(st.height));
    }
    vkEndCommandBuffer(st.cmd);
  }
  if (status.ok()) {
    const VkSubmitInfo submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
                              .commandBufferCount = 1,
                              .pCommandBuffers = &st.cmd};
    status = vk::check(vkQueueSubmit(st.context->queue, 1, &submit, st.fence), "vkQueueSubmit");
    if (status.ok()) {
      status =
          vk::check(vkWaitForFences(device, 1, &st.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
      vkResetFences(device, 1, &st.fence);
    }
  }
  // Released even after a failure: the runtime must get its images back.
  for (std::size_t i = 0; i < acquired; ++i) {
    const XrSwapchainImageReleaseInfo release{XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO};
    const Status released = check(
        st.instance,
        xrReleaseSwapchainImage(st.eyes[static_cast<std::size_t>(eyes[i])].swapchain, &release),
        "xrReleaseSwapchainImage");
    if (status.ok()) status = released;
  }
  return status;
}

}  // namespace

Status Session::submit_eye(int eye, FunctionRef<Status(VkCommandBuffer)> record, VkImage source) {
  const int eyes[] = {eye};
  return submit_eyes(*state_, eyes, record, source, false);
}

Status Session::submit_stereo(FunctionRef<Status(VkCommandBuffer)> record, VkImage source) {
  const int eyes[] = {0, 1};
  return submit_eyes(*state_, eyes, record, source, true);
}

Status Session::end_frame() {
  State& st = *state_;
  XrCompositionLayerProjection layer{XR_TYPE_COMPOSITION_LAYER_PROJECTION};
  layer.space = st.space;
  layer.viewCount = 2;
  layer.views = st.layer_views.data();
  const XrCompositionLayerBaseHeader* layers[] = {
      reinterpret_cast<const XrCompositionLayerBaseHeader*>(&layer)};
  XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
  end.displayTime = st.frame.predictedDisplayTime;
  end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
  end.layerCount = st.should_render ? 1 : 0;
  end.layers = layers;
  return check(st.instance, xrEndFrame(st.session, &end), "xrEndFrame");
}

}  // namespace ocean::xr
