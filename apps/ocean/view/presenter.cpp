// The window and swapchain of `ocean view` (see presenter.hpp).
#define GLFW_INCLUDE_VULKAN
#include "view/presenter.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <array>
#include <string>

namespace ocean::cli::view {
namespace {

constexpr const char* kNoDisplay =
    "ocean view needs a display: glfwInit failed (set DISPLAY or run under xvfb-run)";

bool has_features(VkPhysicalDevice physical, VkFormat format, VkFormatFeatureFlags features) {
  VkFormatProperties p;
  vkGetPhysicalDeviceFormatProperties(physical, format, &p);
  return (p.optimalTilingFeatures & features) == features;
}

}  // namespace

// ---- Window ---------------------------------------------------------------------------------

Result<std::unique_ptr<Window>> Window::open(int width, int height, const char* title) {
  // No error callback: GLFW stays silent and a missing display is the one line below.
  glfwSetErrorCallback(nullptr);
  if (glfwInit() != GLFW_TRUE) return unsupported(kNoDisplay);
  auto w = std::unique_ptr<Window>(new Window());
  if (glfwVulkanSupported() != GLFW_TRUE)
    return unsupported(
        "ocean view: GLFW found no Vulkan loader with window-system support "
        "(install libvulkan1 and mesa-vulkan-drivers)");
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  w->window_ = glfwCreateWindow(width, height, title, nullptr, nullptr);
  if (w->window_ == nullptr)
    return unsupported("ocean view: cannot create a " + std::to_string(width) + "x" +
                       std::to_string(height) + " window on this display");
  return w;
}

Window::~Window() {
  if (window_ != nullptr) glfwDestroyWindow(window_);
  glfwTerminate();
}

std::vector<const char*> Window::instance_extensions() const {
  std::uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  return names == nullptr ? std::vector<const char*>{}
                          : std::vector<const char*>(names, names + count);
}

void Window::framebuffer_size(int& width, int& height) const {
  glfwGetFramebufferSize(window_, &width, &height);
}

// ---- Presenter ------------------------------------------------------------------------------

Result<std::unique_ptr<Presenter>> Presenter::make(std::shared_ptr<vk::Context> context,
                                                   const Window& window) {
  auto p = std::unique_ptr<Presenter>(new Presenter());
  p->ctx_ = std::move(context);
  p->window_ = window.handle();
  const vk::Context& ctx = *p->ctx_;
  if (Status s = vk::check(glfwCreateWindowSurface(ctx.instance, p->window_, nullptr, &p->surface_),
                           "glfwCreateWindowSurface");
      !s.ok())
    return s;
  VkBool32 present = VK_FALSE;
  if (Status s = vk::check(vkGetPhysicalDeviceSurfaceSupportKHR(ctx.physical, ctx.queue_family,
                                                                p->surface_, &present),
                           "vkGetPhysicalDeviceSurfaceSupportKHR");
      !s.ok())
    return s;
  if (present != VK_TRUE)
    return unsupported("Vulkan device '" + ctx.info.name +
                       "' cannot present to this window (its graphics queue has no presentation "
                       "support): use another device or display");

  // An sRGB format, so that the blit keeps the tone-mapped values (it converts through linear).
  std::uint32_t count = 0;
  vkGetPhysicalDeviceSurfaceFormatsKHR(ctx.physical, p->surface_, &count, nullptr);
  std::vector<VkSurfaceFormatKHR> formats(count);
  vkGetPhysicalDeviceSurfaceFormatsKHR(ctx.physical, p->surface_, &count, formats.data());
  for (VkFormat want : {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB}) {
    const auto it = std::find_if(formats.begin(), formats.end(), [&](const VkSurfaceFormatKHR& f) {
      return f.format == want && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
    });
    if (it != formats.end()) {
      p->format_ = it->format;
      break;
    }
  }
  if (p->format_ == VK_FORMAT_UNDEFINED)
    return unsupported("ocean view: the window offers no B8G8R8A8_SRGB or R8G8B8A8_SRGB format");
  p->blit_ = has_features(ctx.physical, VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_FEATURE_BLIT_SRC_BIT) &&
             has_features(ctx.physical, p->format_, VK_FORMAT_FEATURE_BLIT_DST_BIT);
  if (!p->blit_ && p->format_ != VK_FORMAT_R8G8B8A8_SRGB)
    return unsupported("ocean view: Vulkan device '" + ctx.info.name +
                       "' cannot blit into the window's format");

  const VkAttachmentDescription colour{.format = p->format_,
                                       .samples = VK_SAMPLE_COUNT_1_BIT,
                                       .loadOp = VK_ATTACHMENT_LOAD_OP_LOAD,
                                       .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                       .stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE,
                                       .stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
                                       .initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                       .finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR};
  const VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  const VkSubpassDescription subpass{.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS,
                                     .colorAttachmentCount = 1,
                                     .pColorAttachments = &ref};
  // The blit's barrier already made the image an attachment; this orders the overlay after it.
  const VkSubpassDependency dependency{
      .srcSubpass = VK_SUBPASS_EXTERNAL,
      .dstSubpass = 0,
      .srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
      .dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
      .srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
      .dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT};
  const VkRenderPassCreateInfo rp{.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO,
                                  .attachmentCount = 1,
                                  .pAttachments = &colour,
                                  .subpassCount = 1,
                                  .pSubpasses = &subpass,
                                  .dependencyCount = 1,
                                  .pDependencies = &dependency};
  if (Status s = vk::check(vkCreateRenderPass(ctx.device, &rp, nullptr, &p->render_pass_),
                           "vkCreateRenderPass");
      !s.ok())
    return s;

  const VkCommandPoolCreateInfo pool{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                     .flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT,
                                     .queueFamilyIndex = ctx.queue_family};
  if (Status s = vk::check(vkCreateCommandPool(ctx.device, &pool, nullptr, &p->pool_),
                           "vkCreateCommandPool");
      !s.ok())
    return s;
  const VkCommandBufferAllocateInfo alloc{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                          .commandPool = p->pool_,
                                          .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                          .commandBufferCount = 1};
  if (Status s = vk::check(vkAllocateCommandBuffers(ctx.device, &alloc, &p->cmd_),
                           "vkAllocateCommandBuffers");
      !s.ok())
    return s;
  const VkFenceCreateInfo fence{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO,
                                .flags = VK_FENCE_CREATE_SIGNALED_BIT};
  if (Status s = vk::check(vkCreateFence(ctx.device, &fence, nullptr, &p->fence_), "vkCreateFence");
      !s.ok())
    return s;
  const VkSemaphoreCreateInfo sem{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  if (Status s = vk::check(vkCreateSemaphore(ctx.device, &sem, nullptr, &p->acquired_),
                           "vkCreateSemaphore");
      !s.ok())
    return s;
  if (Status s = p->create_swapchain(); !s.ok()) return s;
  if (p->swapchain_ == VK_NULL_HANDLE)
    return unsupported("ocean view: the window has no area to draw into");
  return p;
}

Presenter::~Presenter() {
  if (!ctx_) return;
  const VkDevice device = ctx_->device;
  vkDeviceWaitIdle(device);
  destroy_image_objects();
  if (swapchain_ != VK_NULL_HANDLE) vkDestroySwapchainKHR(device, swapchain_, nullptr);
  if (acquired_ != VK_NULL_HANDLE) vkDestroySemaphore(device, acquired_, nullptr);
  if (fence_ != VK_NULL_HANDLE) vkDestroyFence(device, fence_, nullptr);
  if (pool_ != VK_NULL_HANDLE) vkDestroyCommandPool(device, pool_, nullptr);
  if (render_pass_ != VK_NULL_HANDLE) vkDestroyRenderPass(device, render_pass_, nullptr);
  if (surface_ != VK_NULL_HANDLE) vkDestroySurfaceKHR(ctx_->instance, surface_, nullptr);
}

void Presenter::destroy_image_objects() {
  const VkDevice device = ctx_->device;
  for (VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(device, f, nullptr);
  for (VkImageView v : views_) vkDestroyImageView(device, v, nullptr);
  for (VkSemaphore s : rendered_) vkDestroySemaphore(device, s, nullptr);
  framebuffers_.clear(), views_.clear(), rendered_.clear(), images_.clear();
}

// Leaves swapchain_ null (and returns ok) while the window has no area.
Status Presenter::create_swapchain() {
  const vk::Context& ctx = *ctx_;
  VkSurfaceCapabilitiesKHR caps;
  if (Status s = vk::check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx.physical, surface_, &caps),
                           "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
      !s.ok())
    return s;
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  framebuffer_width_ = w, framebuffer_height_ = h;
  VkExtent2D extent = caps.currentExtent;
  if (extent.width == 0xFFFFFFFFu) {  // the surface takes the swapchain's size
    extent.width = std::clamp(static_cast<std::uint32_t>(std::max(w, 0)), caps.minImageExtent.width,
                              caps.maxImageExtent.width);
    extent.height = std::clamp(static_cast<std::uint32_t>(std::max(h, 0)),
                               caps.minImageExtent.height, caps.maxImageExtent.height);
  }
  if (extent.width == 0 || extent.height == 0) return {};
  const VkImageUsageFlags usage =
      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  if ((caps.supportedUsageFlags & usage) != usage)
    return unsupported("ocean view: the window's swapchain images cannot be transfer targets");
  std::uint32_t images = caps.minImageCount + 1;
  if (caps.maxImageCount > 0) images = std::min(images, caps.maxImageCount);
  const VkSwapchainKHR old = swapchain_;
  // FIFO: always available, paced by the display.
  const VkSwapchainCreateInfoKHR info{
      .sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR,
      .surface = surface_,
      .minImageCount = images,
      .imageFormat = format_,
      .imageColorSpace = colour_space_,
      .imageExtent = extent,
      .imageArrayLayers = 1,
      .imageUsage = usage,
      .imageSharingMode = VK_SHARING_MODE_EXCLUSIVE,
      .preTransform = caps.currentTransform,
      .compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR) != 0
                            ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                            : VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR,
      .presentMode = VK_PRESENT_MODE_FIFO_KHR,
      .clipped = VK_TRUE,
      .oldSwapchain = old};
  if (Status s = vk::check(vkCreateSwapchainKHR(ctx.device, &info, nullptr, &swapchain_),
                           "vkCreateSwapchainKHR");
      !s.ok()) {
    swapchain_ = old;
    return s;
  }
  destroy_image_objects();
  if (old != VK_NULL_HANDLE) vkDestroySwapchainKHR(ctx.device, old, nullptr);
  extent_ = extent;
  min_image_count_ = images;
  std::uint32_t count = 0;
  vkGetSwapchainImagesKHR(ctx.device, swapchain_, &count, nullptr);
  images_.resize(count);
  vkGetSwapchainImagesKHR(ctx.device, swapchain_, &count, images_.data());
  for (VkImage image : images_) {
    const VkImageViewCreateInfo vi{.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                                   .image = image,
                                   .viewType = VK_IMAGE_VIEW_TYPE_2D,
                                   .format = format_,
                                   .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1}};
    VkImageView view = VK_NULL_HANDLE;
    if (Status s =
            vk::check(vkCreateImageView(ctx.device, &vi, nullptr, &view), "vkCreateImageView");
        !s.ok())
      return s;
    views_.push_back(view);
    const VkFramebufferCreateInfo fi{.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO,
                                     .renderPass = render_pass_,
                                     .attachmentCount = 1,
                                     .pAttachments = &view,
                                     .width = extent.width,
                                     .height = extent.height,
                                     .layers = 1};
    VkFramebuffer fb = VK_NULL_HANDLE;
    if (Status s =
            vk::check(vkCreateFramebuffer(ctx.device, &fi, nullptr, &fb), "vkCreateFramebuffer");
        !s.ok())
      return s;
    framebuffers_.push_back(fb);
    const VkSemaphoreCreateInfo sem{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore rendered = VK_NULL_HANDLE;
    if (Status s =
            vk::check(vkCreateSemaphore(ctx.device, &sem, nullptr, &rendered), "vkCreateSemaphore");
        !s.ok())
      return s;
    rendered_.push_back(rendered);
  }
  stale_ = false;
  ++generation_;
  return {};
}

Status Presenter::wait_frame() {
  return vk::check(vkWaitForFences(ctx_->device, 1, &fence_, VK_TRUE, 60'000'000'000ull),
                   "vkWaitForFences");
}

Result<bool> Presenter::recreate() {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  if (w == 0 || h == 0) return false;
  vkDeviceWaitIdle(ctx_->device);
  if (Status s = create_swapchain(); !s.ok()) return s;
  return swapchain_ != VK_NULL_HANDLE && !images_.empty();
}

Result<bool> Presenter::acquire() {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  if (w == 0 || h == 0) return false;  // minimised
  // A changed framebuffer size rebuilds even where the driver would not say out of date (X11).
  if (stale_ || swapchain_ == VK_NULL_HANDLE || w != framebuffer_width_ ||
      h != framebuffer_height_) {
    Result<bool> rebuilt = recreate();
    if (!rebuilt.ok() || !rebuilt.value()) return rebuilt;
  }
  const VkResult r = vkAcquireNextImageKHR(ctx_->device, swapchain_, 60'000'000'000ull, acquired_,
                                           VK_NULL_HANDLE, &image_);
  if (r == VK_ERROR_OUT_OF_DATE_KHR) {
    Result<bool> rebuilt = recreate();
    if (!rebuilt.ok()) return rebuilt;
    return false;
  }
  if (r == VK_SUBOPTIMAL_KHR) {
    stale_ = true;  // the image is acquired: use it, rebuild after presenting
    return true;
  }
  if (Status s = vk::check(r, "vkAcquireNextImageKHR"); !s.ok()) return s;
  return true;
}

Result<VkCommandBuffer> Presenter::begin() {
  if (Status s = vk::check(vkResetCommandBuffer(cmd_, 0), "vkResetCommandBuffer"); !s.ok())
    return s;
  const VkCommandBufferBeginInfo info{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                      .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
  if (Status s = vk::check(vkBeginCommandBuffer(cmd_, &info), "vkBeginCommandBuffer"); !s.ok())
    return s;
  return cmd_;
}

void Presenter::blit_and_begin_overlay(VkCommandBuffer cmd, VkImage source, int width, int height) {
  const VkImage target = images_[image_];
  // The acquire semaphore is waited for at the transfer stage (see submit_and_present).
  vk::image_barrier(cmd, target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_ACCESS_TRANSFER_WRITE_BIT);
  const VkImageSubresourceLayers layers{VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  const auto w = static_cast<std::int32_t>(extent_.width);
  const auto h = static_cast<std::int32_t>(extent_.height);
  if (blit_) {
    const VkImageBlit region{.srcSubresource = layers,
                             .srcOffsets = {{0, 0, 0}, {width, height, 1}},
                             .dstSubresource = layers,
                             .dstOffsets = {{0, 0, 0}, {w, h, 1}}};
    vkCmdBlitImage(cmd, source, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_NEAREST);
  } else {
    const VkImageCopy region{.srcSubresource = layers,
                             .dstSubresource = layers,
                             .extent = {static_cast<std::uint32_t>(std::min(width, w)),
                                        static_cast<std::uint32_t>(std::min(height, h)), 1}};
    vkCmdCopyImage(cmd, source, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  }
  vk::image_barrier(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
  const VkRenderPassBeginInfo rp{.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO,
                                 .renderPass = render_pass_,
                                 .framebuffer = framebuffers_[image_],
                                 .renderArea = {{0, 0}, extent_}};
  vkCmdBeginRenderPass(cmd, &rp, VK_SUBPASS_CONTENTS_INLINE);
}

Status Presenter::end_overlay(VkCommandBuffer cmd) {
  vkCmdEndRenderPass(cmd);
  return vk::check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
}

Status Presenter::submit_and_present() {
  if (Status s = vk::check(vkResetFences(ctx_->device, 1, &fence_), "vkResetFences"); !s.ok())
    return s;
  const VkPipelineStageFlags wait_stage = VK_PIPELINE_STAGE_TRANSFER_BIT;
  const VkSubmitInfo submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
                            .waitSemaphoreCount = 1,
                            .pWaitSemaphores = &acquired_,
                            .pWaitDstStageMask = &wait_stage,
                            .commandBufferCount = 1,
                            .pCommandBuffers = &cmd_,
                            .signalSemaphoreCount = 1,
                            .pSignalSemaphores = &rendered_[image_]};
  if (Status s = vk::check(vkQueueSubmit(ctx_->queue, 1, &submit, fence_), "vkQueueSubmit");
      !s.ok())
    return s;
  const VkPresentInfoKHR present{.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR,
                                 .waitSemaphoreCount = 1,
                                 .pWaitSemaphores = &rendered_[image_],
                                 .swapchainCount = 1,
                                 .pSwapchains = &swapchain_,
                                 .pImageIndices = &image_};
  const VkResult r = vkQueuePresentKHR(ctx_->queue, &present);
  if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) {
    stale_ = true;
    return {};
  }
  return vk::check(r, "vkQueuePresentKHR");
}

}  // namespace ocean::cli::view
