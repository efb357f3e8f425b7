// view/imgui_layer.hpp — Dear ImGui on the window of `ocean view`: the GLFW platform backend and
// the Vulkan renderer backend (ImGui 1.86: a VkRenderPass, here the Presenter's overlay pass),
// its descriptor pool and font texture. One per process (ImGui's backends keep global state).
//
// Per frame: new_frame() → ImGui widgets → ImGui::Render() → record(cmd) inside the overlay
// render pass. No imgui.ini is read or written.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>

#include "ocean/vk.hpp"

struct GLFWwindow;

namespace ocean::cli::view {

class ImGuiLayer {
 public:
  /// `images`/`min_images`: the swapchain's (the backend keeps that many vertex buffers).
  /// `srgb_target`: the overlay draws into an sRGB image, so the style's colours (sRGB values)
  /// are converted to linear to look as designed.
  static Result<std::unique_ptr<ImGuiLayer>> make(std::shared_ptr<vk::Context> context,
                                                  GLFWwindow* window, VkRenderPass render_pass,
                                                  std::uint32_t min_images, std::uint32_t images,
                                                  bool srgb_target);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  void new_frame();
  /// Records ImGui::GetDrawData() (after ImGui::Render()) into `cmd`, inside the render pass.
  void record(VkCommandBuffer cmd);
  /// After a swapchain rebuild.
  void set_min_image_count(std::uint32_t min_images);
  /// The first failed VkResult the backend reported, if any.
  [[nodiscard]] Status status() const;

 private:
  ImGuiLayer() = default;
  std::shared_ptr<vk::Context> ctx_;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  bool glfw_ = false, vulkan_ = false;
};

}  // namespace ocean::cli::view
