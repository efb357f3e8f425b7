// Dear ImGui's GLFW and Vulkan backends for `ocean view` (see imgui_layer.hpp).
#include "view/imgui_layer.hpp"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>

namespace ocean::cli::view {
namespace {

// The backend reports failures through a callback without context: the first one is kept.
std::atomic<int> g_first_error{VK_SUCCESS};

void on_vk_result(VkResult r) {
  if (r == VK_SUCCESS) return;
  int expected = VK_SUCCESS;
  g_first_error.compare_exchange_strong(expected, static_cast<int>(r));
}

float srgb_to_linear(float c) {  // IEC 61966-2-1
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

Result<std::unique_ptr<ImGuiLayer>> ImGuiLayer::make(std::shared_ptr<vk::Context> context,
                                                     GLFWwindow* window, VkRenderPass render_pass,
                                                     std::uint32_t min_images, std::uint32_t images,
                                                     bool srgb_target) {
  auto layer = std::unique_ptr<ImGuiLayer>(new ImGuiLayer());
  layer->ctx_ = std::move(context);
  const vk::Context& ctx = *layer->ctx_;
  // The font atlas needs one combined image sampler; a few spare sets cost nothing.
  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 8};
  const VkDescriptorPoolCreateInfo pool{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                        .flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT,
                                        .maxSets = 8,
                                        .poolSizeCount = 1,
                                        .pPoolSizes = &size};
  if (Status s = vk::check(vkCreateDescriptorPool(ctx.device, &pool, nullptr, &layer->pool_),
                           "vkCreateDescriptorPool");
      !s.ok())
    return s;

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini in the working directory
  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 4.0f;
  if (srgb_target) {
    for (ImVec4& c : style.Colors) {
      c.x = srgb_to_linear(c.x), c.y = srgb_to_linear(c.y), c.z = srgb_to_linear(c.z);
    }
  }
  if (!ImGui_ImplGlfw_InitForVulkan(window, true))
    return unsupported("ocean view: Dear ImGui's GLFW backend failed to start");
  layer->glfw_ = true;
  g_first_error = VK_SUCCESS;
  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = ctx.instance;
  info.PhysicalDevice = ctx.physical;
  info.Device = ctx.device;
  info.QueueFamily = ctx.queue_family;
  info.Queue = ctx.queue;
  info.DescriptorPool = layer->pool_;
  info.MinImageCount = std::max(min_images, 2u);
  info.ImageCount = std::max(images, info.MinImageCount);
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  info.CheckVkResultFn = on_vk_result;
  if (!ImGui_ImplVulkan_Init(&info, render_pass))
    return unsupported("ocean view: Dear ImGui's Vulkan backend failed to start");
  layer->vulkan_ = true;

  // Font atlas upload on a one-shot command buffer.
  Result<vk::Commands> commands = vk::create_commands(ctx);
  if (!commands.ok()) return commands.status();
  vk::Commands cmds = commands.value();
  const Status uploaded = vk::run_once(
      ctx, cmds, [](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
  vk::destroy_commands(ctx, cmds);
  if (!uploaded.ok()) return uploaded;
  ImGui_ImplVulkan_DestroyFontUploadObjects();
  if (Status s = layer->status(); !s.ok()) return s;
  return layer;
}

ImGuiLayer::~ImGuiLayer() {
  if (ctx_) vkDeviceWaitIdle(ctx_->device);
  if (vulkan_) ImGui_ImplVulkan_Shutdown();
  if (glfw_) ImGui_ImplGlfw_Shutdown();
  if (ImGui::GetCurrentContext() != nullptr) ImGui::DestroyContext();
  if (pool_ != VK_NULL_HANDLE) vkDestroyDescriptorPool(ctx_->device, pool_, nullptr);
}

void ImGuiLayer::new_frame() {
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void ImGuiLayer::record(VkCommandBuffer cmd) {
  ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
}

void ImGuiLayer::set_min_image_count(std::uint32_t min_images) {
  ImGui_ImplVulkan_SetMinImageCount(std::max(min_images, 2u));
}

Status ImGuiLayer::status() const {
  const int r = g_first_error.load();
  if (r == VK_SUCCESS) return {};
  return vk::check(static_cast<VkResult>(r), "Dear ImGui's Vulkan backend");
}

}  // namespace ocean::cli::view
