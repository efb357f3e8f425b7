// The OpenXR session's set-up and events: instance (with XR_KHR_vulkan_enable), the HMD
// system, the Vulkan context on the runtime's device, the session, the LOCAL space and one
// swapchain per eye; the session state machine (OpenXR 1.0 specification, "Session
// Lifecycle": READY → xrBeginSession, STOPPING → xrEndSession, EXITING → leave).
#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <system_error>

#include "ocean/io.hpp"
#include "state.hpp"

namespace ocean::xr {

namespace {

constexpr const char* kValidationLayer = "XR_APILAYER_LUNARG_core_validation";

// Splits the runtime's space-separated Vulkan extension list.
std::vector<std::string> split_names(const std::string& text) {
  std::vector<std::string> names;
  std::istringstream in(text);
  for (std::string name; in >> name;) names.push_back(name);
  return names;
}

// An extension function of the runtime.
template <typename Fn>
Status proc(XrInstance instance, const char* name, Fn& out) {
  PFN_xrVoidFunction fn = nullptr;
  if (Status s = check(instance, xrGetInstanceProcAddr(instance, name, &fn), name); !s.ok())
    return s;
  out = reinterpret_cast<Fn>(fn);
  return {};
}

// The runtime's Vulkan extensions (instance or device) through the two-call idiom.
Result<std::vector<std::string>> vulkan_extensions(XrInstance instance, XrSystemId system,
                                                   XrResult(XRAPI_PTR* get)(XrInstance, XrSystemId,
                                                                            std::uint32_t,
                                                                            std::uint32_t*, char*),
                                                   const char* name) {
  std::uint32_t count = 0;
  if (Status s = check(instance, get(instance, system, 0, &count, nullptr), name); !s.ok())
    return s;
  std::string text(count, '\0');
  if (Status s = check(instance, get(instance, system, count, &count, text.data()), name); !s.ok())
    return s;
  text.resize(std::strlen(text.c_str()));
  return split_names(text);
}

// The manifest XR_RUNTIME_JSON names, checked before the loader reads it whole with no bound of
// its own: a regular file of at most kRuntimeManifestMaxBytes. An unset or empty variable is
// the loader's to resolve (the system's active runtime), and so is a name where nothing is: the
// loader finds no runtime there, which make() reports as such.
Status check_runtime_manifest() {
  const char* named = std::getenv("XR_RUNTIME_JSON");
  if (named == nullptr || *named == '\0') return {};
  std::error_code ec;
  if (!std::filesystem::exists(named, ec) && !ec) return {};
  Result<std::string> read = io::read_bounded(
      named,
      {.max_bytes = kRuntimeManifestMaxBytes, .what = "runtime manifest", .regular_only = true});
  if (read.ok()) return {};
  std::string message = "XR_RUNTIME_JSON: " + read.status().message();
  if (read.status().code() != ErrorCode::invalid_argument)  // the size message states the limit
    message += "; a runtime manifest is a regular file of at most " +
               io::byte_limit_text(kRuntimeManifestMaxBytes);
  return io_error(message);
}

Status create_instance(const SessionParams& params, Session::State& st) {
  if (Status s = check_runtime_manifest(); !s.ok()) return s;
  std::vector<const char*> layers;
  if (params.validation) {
    std::uint32_t count = 0;
    xrEnumerateApiLayerProperties(0, &count, nullptr);
    std::vector<XrApiLayerProperties> props(count, {XR_TYPE_API_LAYER_PROPERTIES});
    xrEnumerateApiLayerProperties(count, &count, props.data());
    if (std::none_of(props.begin(), props.end(),
                     [](const auto& p) { return std::strcmp(p.layerName, kValidationLayer) == 0; }))
      return unsupported(std::string("the OpenXR layer ") + kValidationLayer +
                         " is not installed (Debian: openxr-layer-corevalidation)");
    layers.push_back(kValidationLayer);
  }
  const char* extensions[] = {XR_KHR_VULKAN_ENABLE_EXTENSION_NAME};
  XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
  info.applicationInfo.applicationVersion = 1;
  info.applicationInfo.engineVersion = 1;
  info.applicationInfo.apiVersion = XR_CURRENT_API_VERSION;
  std::strncpy(info.applicationInfo.applicationName, params.application_name.c_str(),
               XR_MAX_APPLICATION_NAME_SIZE - 1);
  std::strncpy(info.applicationInfo.engineName, "ocean", XR_MAX_ENGINE_NAME_SIZE - 1);
  info.enabledApiLayerCount = static_cast<std::uint32_t>(layers.size());
  info.enabledApiLayerNames = layers.data();
  info.enabledExtensionCount = 1;
  info.enabledExtensionNames = extensions;
  const XrResult r = xrCreateInstance(&info, &st.instance);
  if (r == XR_ERROR_RUNTIME_UNAVAILABLE || r == XR_ERROR_RUNTIME_FAILURE ||
      r == XR_ERROR_INSTANCE_LOST)
    return unsupported(
        "no OpenXR runtime: install one (Monado, SteamVR) or name its manifest in "
        "XR_RUNTIME_JSON");
  if (r == XR_ERROR_EXTENSION_NOT_PRESENT)
    return unsupported("the OpenXR runtime lacks XR_KHR_vulkan_enable: ocean renders with Vulkan");
  if (Status s = check(XR_NULL_HANDLE, r, "xrCreateInstance"); !s.ok()) return s;
  XrInstanceProperties props{XR_TYPE_INSTANCE_PROPERTIES};
  if (Status s = check(st.instance, xrGetInstanceProperties(st.instance, &props),
                       "xrGetInstanceProperties");
      !s.ok())
    return s;
  st.runtime_name = props.runtimeName;
  XrSystemGetInfo system{XR_TYPE_SYSTEM_GET_INFO};
  system.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
  const XrResult rs = xrGetSystem(st.instance, &system, &st.system);
  if (rs == XR_ERROR_FORM_FACTOR_UNAVAILABLE)
    return unsupported("the OpenXR runtime '" + excerpt(st.runtime_name) +
                       "' has no headset connected");
  return check(st.instance, rs, "xrGetSystem");
}

// The eye size, a Vulkan context the runtime accepts, and the session on it.
Status create_session(const SessionParams& params, Session::State& st) {
  std::uint32_t count = 0;
  std::array<XrViewConfigurationView, 2> views{};
  views.fill({XR_TYPE_VIEW_CONFIGURATION_VIEW});
  if (Status s = check(st.instance,
                       xrEnumerateViewConfigurationViews(st.instance, st.system,
                                                         XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO,
                                                         2, &count, views.data()),
                       "xrEnumerateViewConfigurationViews");
      !s.ok())
    return s;
  st.width = views[0].recommendedImageRectWidth;
  st.height = views[0].recommendedImageRectHeight;

  PFN_xrGetVulkanGraphicsRequirementsKHR requirements = nullptr;
  PFN_xrGetVulkanInstanceExtensionsKHR instance_ext = nullptr;
  PFN_xrGetVulkanDeviceExtensionsKHR device_ext = nullptr;
  PFN_xrGetVulkanGraphicsDeviceKHR device = nullptr;
  for (const Status& s : {proc(st.instance, "xrGetVulkanGraphicsRequirementsKHR", requirements),
                          proc(st.instance, "xrGetVulkanInstanceExtensionsKHR", instance_ext),
                          proc(st.instance, "xrGetVulkanDeviceExtensionsKHR", device_ext),
                          proc(st.instance, "xrGetVulkanGraphicsDeviceKHR", device)})
    if (!s.ok()) return s;
  XrGraphicsRequirementsVulkanKHR req{XR_TYPE_GRAPHICS_REQUIREMENTS_VULKAN_KHR};
  if (Status s = check(st.instance, requirements(st.instance, st.system, &req),
                       "xrGetVulkanGraphicsRequirementsKHR");
      !s.ok())
    return s;
  Result<std::vector<std::string>> inst =
      vulkan_extensions(st.instance, st.system, instance_ext, "xrGetVulkanInstanceExtensionsKHR");
  if (!inst.ok()) return inst.status();
  Result<std::vector<std::string>> dev =
      vulkan_extensions(st.instance, st.system, device_ext, "xrGetVulkanDeviceExtensionsKHR");
  if (!dev.ok()) return dev.status();
  vk::ContextParams cp{.validation = params.validation, .graphics = true};
  for (const std::string& e : inst.value()) cp.instance_extensions.push_back(e.c_str());
  for (const std::string& e : dev.value()) cp.device_extensions.push_back(e.c_str());
  Result<std::unique_ptr<vk::Context>> ctx = vk::create_context(cp);
  if (!ctx.ok()) return ctx.status();
  st.context = std::move(ctx).value();
  const vk::Context& c = *st.context;
  if (XR_MAKE_VERSION(VK_API_VERSION_MAJOR(c.properties.apiVersion),
                      VK_API_VERSION_MINOR(c.properties.apiVersion),
                      0) < req.minApiVersionSupported)
    return unsupported("the OpenXR runtime needs a newer Vulkan than device '" +
                       excerpt(c.info.name) + "' has");
  VkPhysicalDevice wanted = VK_NULL_HANDLE;
  if (Status s = check(st.instance, device(st.instance, st.system, c.instance, &wanted),
                       "xrGetVulkanGraphicsDeviceKHR");
      !s.ok())
    return s;
  if (wanted != c.physical)
    return unsupported("the OpenXR runtime renders on another Vulkan device than '" +
                       excerpt(c.info.name) + "', the one ocean chose");

  XrGraphicsBindingVulkanKHR binding{XR_TYPE_GRAPHICS_BINDING_VULKAN_KHR};
  binding.instance = c.instance;
  binding.physicalDevice = c.physical;
  binding.device = c.device;
  binding.queueFamilyIndex = c.queue_family;
  binding.queueIndex = 0;
  XrSessionCreateInfo info{XR_TYPE_SESSION_CREATE_INFO};
  info.next = &binding;
  info.systemId = st.system;
  if (Status s =
          check(st.instance, xrCreateSession(st.instance, &info, &st.session), "xrCreateSession");
      !s.ok())
    return s;
  XrReferenceSpaceCreateInfo space{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
  space.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
  space.poseInReferenceSpace.orientation.w = 1.0f;
  return check(st.instance, xrCreateReferenceSpace(st.session, &space, &st.space),
               "xrCreateReferenceSpace");
}

// One swapchain per eye in an sRGB RGBA8 format, and the command buffer that fills them.
Status create_swapchains(Session::State& st) {
  std::uint32_t count = 0;
  xrEnumerateSwapchainFormats(st.session, 0, &count, nullptr);
  std::vector<std::int64_t> formats(count);
  if (Status s =
          check(st.instance, xrEnumerateSwapchainFormats(st.session, count, &count, formats.data()),
                "xrEnumerateSwapchainFormats");
      !s.ok())
    return s;
  const auto pick = std::find_if(formats.begin(), formats.end(), [](std::int64_t f) {
    return f == VK_FORMAT_R8G8B8A8_SRGB || f == VK_FORMAT_B8G8R8A8_SRGB;
  });
  if (pick == formats.end())
    return unsupported("the OpenXR runtime offers no sRGB RGBA8 or BGRA8 swapchain format");
  for (Eye& eye : st.eyes) {
    XrSwapchainCreateInfo info{XR_TYPE_SWAPCHAIN_CREATE_INFO};
    info.usageFlags = XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT | XR_SWAPCHAIN_USAGE_TRANSFER_DST_BIT;
    info.format = *pick;
    info.sampleCount = 1;
    info.width = st.width;
    info.height = st.height;
    info.faceCount = 1;
    info.arraySize = 1;
    info.mipCount = 1;
    if (Status s = check(st.instance, xrCreateSwapchain(st.session, &info, &eye.swapchain),
                         "xrCreateSwapchain");
        !s.ok())
      return s;
    xrEnumerateSwapchainImages(eye.swapchain, 0, &count, nullptr);
    std::vector<XrSwapchainImageVulkanKHR> images(count, {XR_TYPE_SWAPCHAIN_IMAGE_VULKAN_KHR});
    if (Status s = check(st.instance,
                         xrEnumerateSwapchainImages(
                             eye.swapchain, count, &count,
                             reinterpret_cast<XrSwapchainImageBaseHeader*>(images.data())),
                         "xrEnumerateSwapchainImages");
        !s.ok())
      return s;
    for (const auto& image : images) eye.images.push_back(image.image);
  }
  const VkDevice device = st.context->device;
  const VkCommandPoolCreateInfo pool{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                     .flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT,
                                     .queueFamilyIndex = st.context->queue_family};
  if (Status s =
          vk::check(vkCreateCommandPool(device, &pool, nullptr, &st.pool), "vkCreateCommandPool");
      !s.ok())
    return s;
  const VkCommandBufferAllocateInfo alloc{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                          .commandPool = st.pool,
                                          .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                          .commandBufferCount = 1};
  if (Status s =
          vk::check(vkAllocateCommandBuffers(device, &alloc, &st.cmd), "vkAllocateCommandBuffers");
      !s.ok())
    return s;
  const VkFenceCreateInfo fence{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  return vk::check(vkCreateFence(device, &fence, nullptr, &st.fence), "vkCreateFence");
}

}  // namespace

Status check(XrInstance instance, XrResult result, const char* call) {
  if (XR_SUCCEEDED(result)) return {};
  char name[XR_MAX_RESULT_STRING_SIZE] = {};
  if (instance == XR_NULL_HANDLE || XR_FAILED(xrResultToString(instance, result, name)))
    std::snprintf(name, sizeof name, "XrResult %d", static_cast<int>(result));
  return {ErrorCode::internal, std::string(call) + " failed: " + name};
}

Result<std::unique_ptr<Session>> Session::make(const SessionParams& params) {
  std::unique_ptr<Session> session(new Session());
  session->state_ = std::make_unique<State>();
  State& st = *session->state_;
  if (Status s = create_instance(params, st); !s.ok()) return s;
  if (Status s = create_session(params, st); !s.ok()) return s;
  if (Status s = create_swapchains(st); !s.ok()) return s;
  return session;
}

Session::~Session() {
  State& st = *state_;
  if (st.context && st.context->device != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(st.context->device);
    if (st.fence != VK_NULL_HANDLE) vkDestroyFence(st.context->device, st.fence, nullptr);
    if (st.pool != VK_NULL_HANDLE) vkDestroyCommandPool(st.context->device, st.pool, nullptr);
  }
  for (Eye& eye : st.eyes)
    if (eye.swapchain != XR_NULL_HANDLE) xrDestroySwapchain(eye.swapchain);
  if (st.space != XR_NULL_HANDLE) xrDestroySpace(st.space);
  if (st.session != XR_NULL_HANDLE) {
    if (st.begun) xrEndSession(st.session);
    xrDestroySession(st.session);
  }
  if (st.instance != XR_NULL_HANDLE) xrDestroyInstance(st.instance);
  st.context.reset();  // after the session: the runtime's images live on its device
}

const std::shared_ptr<vk::Context>& Session::context() const { return state_->context; }
int Session::eye_width() const { return static_cast<int>(state_->width); }
int Session::eye_height() const { return static_cast<int>(state_->height); }
const std::string& Session::runtime_name() const { return state_->runtime_name; }
bool Session::running() const { return state_->begun; }
bool Session::exiting() const { return state_->exiting; }

Status Session::poll_events() {
  State& st = *state_;
  for (;;) {
    XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER};
    const XrResult r = xrPollEvent(st.instance, &event);
    if (r == XR_EVENT_UNAVAILABLE) return {};
    if (Status s = check(st.instance, r, "xrPollEvent"); !s.ok()) return s;
    if (event.type == XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING) {
      st.exiting = true;
      continue;
    }
    if (event.type != XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) continue;
    st.state = reinterpret_cast<const XrEventDataSessionStateChanged&>(event).state;
    if (st.state == XR_SESSION_STATE_READY) {
      XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO};
      begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
      if (Status s = check(st.instance, xrBeginSession(st.session, &begin), "xrBeginSession");
          !s.ok())
        return s;
      st.begun = true;
    } else if (st.state == XR_SESSION_STATE_STOPPING) {
      st.begun = false;
      if (Status s = check(st.instance, xrEndSession(st.session), "xrEndSession"); !s.ok())
        return s;
    } else if (st.state == XR_SESSION_STATE_EXITING || st.state == XR_SESSION_STATE_LOSS_PENDING) {
      st.exiting = true;
    }
  }
}

Status Session::request_exit() {
  return check(state_->instance, xrRequestExitSession(state_->session), "xrRequestExitSession");
}

}  // namespace ocean::xr
