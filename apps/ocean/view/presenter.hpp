// view/presenter.hpp — the window of `ocean view` and its Vulkan swapchain: a GLFW window
// without a client API, its surface, a FIFO swapchain that the renderer's sRGB image is blitted
// into, a render pass over each swapchain image for the overlay (loadOp LOAD, ends in
// PRESENT_SRC), one command buffer, one frame in flight.
//
// Order per frame: wait_frame() → (simulate, record into the renderer's buffers) → acquire() →
// begin() → renderer.record(cmd) → blit_and_begin_overlay() → overlay draws → end_overlay() →
// submit_and_present(). acquire() answers false when the swapchain was out of date and has been
// recreated (skip that frame; extent() changed). Every Vulkan failure is a Status.
//
// Threading: the thread that created the window drives everything (GLFW's rule).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "ocean/vk.hpp"

struct GLFWwindow;

namespace ocean::cli::view {

/// glfwInit and one window for Vulkan; glfwTerminate when destroyed.
class Window {
 public:
  /// unsupported "ocean view needs a display: glfwInit failed (set DISPLAY or run under
  /// xvfb-run)" when there is no display; unsupported when GLFW finds no Vulkan loader.
  static Result<std::unique_ptr<Window>> open(int width, int height, const char* title);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  /// The instance extensions the window system needs (VK_KHR_surface + the platform's).
  [[nodiscard]] std::vector<const char*> instance_extensions() const;
  [[nodiscard]] GLFWwindow* handle() const { return window_; }
  /// Framebuffer size in pixels (0 × 0 while minimised).
  void framebuffer_size(int& width, int& height) const;

 private:
  Window() = default;
  GLFWwindow* window_ = nullptr;
};

class Presenter {
 public:
  /// Creates the surface for `window` on the context's instance (the context must have been made
  /// with Window::instance_extensions() and ContextParams::swapchain) and the swapchain.
  /// unsupported when the context's queue cannot present to the window.
  static Result<std::unique_ptr<Presenter>> make(std::shared_ptr<vk::Context> context,
                                                 const Window& window);
  ~Presenter();
  Presenter(const Presenter&) = delete;
  Presenter& operator=(const Presenter&) = delete;

  /// Waits until the previous frame's GPU work is done (its buffers may be rewritten).
  Status wait_frame();
  /// Rebuilds the swapchain for the window's current size (waits for the device). Returns
  /// false (and changes nothing) while the window is minimised.
  Result<bool> recreate();
  /// Acquires the next image: true when acquired; false when the swapchain was out of date and
  /// has been recreated (or the window is minimised): skip this frame.
  Result<bool> acquire();
  /// Resets and begins the frame's command buffer.
  Result<VkCommandBuffer> begin();
  /// Copies `source` (width×height, TRANSFER_SRC_OPTIMAL, R8G8B8A8_SRGB) into the acquired image
  /// and begins the overlay render pass on it.
  void blit_and_begin_overlay(VkCommandBuffer cmd, VkImage source, int width, int height);
  /// Ends the render pass (the image ends in PRESENT_SRC_KHR) and the command buffer.
  Status end_overlay(VkCommandBuffer cmd);
  /// Submits (after the acquire, signalling the fence) and presents. A suboptimal or out-of-date
  /// swapchain is recreated after presenting.
  Status submit_and_present();

  [[nodiscard]] VkRenderPass render_pass() const { return render_pass_; }
  [[nodiscard]] VkExtent2D extent() const { return extent_; }
  [[nodiscard]] VkFormat format() const { return format_; }
  [[nodiscard]] std::uint32_t image_count() const {
    return static_cast<std::uint32_t>(images_.size());
  }
  [[nodiscard]] std::uint32_t min_image_count() const { return min_image_count_; }
  /// Increments whenever the swapchain is rebuilt (the caller resizes the renderer).
  [[nodiscard]] std::uint64_t generation() const { return generation_; }

 private:
  Presenter() = default;
  Status create_swapchain();
  void destroy_image_objects();

  std::shared_ptr<vk::Context> ctx_;
  GLFWwindow* window_ = nullptr;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkColorSpaceKHR colour_space_ = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
  VkExtent2D extent_{};
  std::uint32_t min_image_count_ = 2;
  bool blit_ = true;  // false: same format, copy instead of blit
  std::vector<VkImage> images_;
  std::vector<VkImageView> views_;
  std::vector<VkFramebuffer> framebuffers_;
  std::vector<VkSemaphore> rendered_;  // per image: the frame's commands → present
  VkRenderPass render_pass_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  VkSemaphore acquired_ = VK_NULL_HANDLE;
  std::uint32_t image_ = 0;                             // the acquired image
  bool stale_ = false;                                  // present said suboptimal / out of date
  int framebuffer_width_ = 0, framebuffer_height_ = 0;  // the window's size at the last rebuild
  std::uint64_t generation_ = 0;
};

}  // namespace ocean::cli::view
