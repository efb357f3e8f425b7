// A minimal OpenXR runtime for tests: the Khronos loader loads it through a manifest named by
// XR_RUNTIME_JSON. It exposes one stereo HMD (runtime.hpp), runs the session state machine,
// predicts display times 1/90 s apart (pacing xrWaitFrame as a compositor would), and checks
// what the application submits: xrLocateViews and xrEndFrame at the predicted time, one
// projection layer of two views whose poses and fields of view are the located ones, and in
// each view a swapchain image released during the frame that is not black. What it found goes
// to the JSON file $OCEAN_TEST_XR_REPORT when the instance is destroyed.
//
// The loader-negotiation structs are declared here: the OpenXR 1.0.20 headers of Debian 12 do
// not ship them (OpenXR loader specification, "Runtime Interface Negotiation").
#include "runtime.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <string_view>
#include <thread>
#include <vector>

extern "C" {
enum XrLoaderInterfaceStructs {
  XR_LOADER_INTERFACE_STRUCT_UNINTIALIZED = 0,
  XR_LOADER_INTERFACE_STRUCT_LOADER_INFO,
  XR_LOADER_INTERFACE_STRUCT_API_LAYER_REQUEST,
  XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST,
};
struct XrNegotiateLoaderInfo {
  XrLoaderInterfaceStructs structType;
  std::uint32_t structVersion;
  std::size_t structSize;
  std::uint32_t minInterfaceVersion, maxInterfaceVersion;
  XrVersion minApiVersion, maxApiVersion;
};
struct XrNegotiateRuntimeRequest {
  XrLoaderInterfaceStructs structType;
  std::uint32_t structVersion;
  std::size_t structSize;
  std::uint32_t runtimeInterfaceVersion;
  XrVersion runtimeApiVersion;
  PFN_xrGetInstanceProcAddr getInstanceProcAddr;
};
}

namespace ocean::test_xr {

Runtime& runtime() {
  static Runtime rt;
  return rt;
}

void problem(const std::string& text) {
  Runtime& rt = runtime();
  if (rt.problems.size() < 50) rt.problems.push_back(text);
}

namespace {

const auto kInstance = reinterpret_cast<XrInstance>(std::uintptr_t{0x1001});
const auto kSession = reinterpret_cast<XrSession>(std::uintptr_t{0x2001});
constexpr XrSystemId kSystem = 7;

std::int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

std::string frame_label() { return "frame " + std::to_string(runtime().frames); }

// Copies `text` (with its terminating zero) under the two-call idiom.
XrResult fill_string(const std::string& text, std::uint32_t capacity, std::uint32_t* count,
                     char* buffer) {
  *count = static_cast<std::uint32_t>(text.size() + 1);
  if (capacity == 0) return XR_SUCCESS;
  if (capacity < *count) return XR_ERROR_SIZE_INSUFFICIENT;
  std::memcpy(buffer, text.c_str(), text.size() + 1);
  return XR_SUCCESS;
}

void write_report() {
  const Runtime& rt = runtime();
  const char* path = std::getenv("OCEAN_TEST_XR_REPORT");
  if (path == nullptr) return;
  std::ofstream out(path);
  out << "{\"frames\": " << rt.frames << ", \"views\": " << rt.views
      << ", \"images_checked\": " << rt.images_checked << ", \"images_lit\": " << rt.images_lit
      << ", \"min_lit_fraction\": " << rt.min_lit_fraction;
  if (rt.images_saved) {
    // The views the saved images were drawn for (pose, then XrFovf's four angles).
    out << ", \"saved_views\": [";
    for (std::size_t i = 0; i < 2; ++i) {
      const XrView& v = rt.saved[i];
      out << (i ? ", " : "") << "{\"orientation\": [" << v.pose.orientation.x << ", "
          << v.pose.orientation.y << ", " << v.pose.orientation.z << ", " << v.pose.orientation.w
          << "], \"position\": [" << v.pose.position.x << ", " << v.pose.position.y << ", "
          << v.pose.position.z << "], \"fov\": [" << v.fov.angleLeft << ", " << v.fov.angleRight
          << ", " << v.fov.angleUp << ", " << v.fov.angleDown << "]}";
    }
    out << "]";
  }
  out << ", \"problems\": [";
  for (std::size_t i = 0; i < rt.problems.size(); ++i) {
    std::string p;
    for (char c : rt.problems[i]) p += (c == '"' || c == '\\') ? '\'' : c;
    out << (i ? ", " : "") << '"' << p << '"';
  }
  out << "]}\n";
}

// The head's pose at a display time: rolled by kRoll_rad about its forward axis (+Z), then
// turned by the yaw about +Y (q = q_yaw·q_roll); eyes ∓IPD/2 along the head's rolled x axis.
XrView eye_view(int eye, std::int64_t time_ns) {
  const Runtime& rt = runtime();
  const double yaw = kYawRate_rad_per_s * double(time_ns - rt.first_predicted_ns) * 1e-9;
  const double sy = std::sin(0.5 * yaw), cy = std::cos(0.5 * yaw);
  const double sr = std::sin(0.5 * kRoll_rad), cr = std::cos(0.5 * kRoll_rad);
  XrView v{XR_TYPE_VIEW};
  v.pose.orientation = {float(sy * sr), float(sy * cr), float(cy * sr), float(cy * cr)};
  // R(q)·(side, 0, 0) = R_yaw·(side·cos r, side·sin r, 0).
  const double side = (eye == 0 ? -0.5 : 0.5) * kIpd_m;
  const double x = side * std::cos(kRoll_rad);
  v.pose.position = {float(x * std::cos(yaw)), float(side * std::sin(kRoll_rad)),
                     float(-x * std::sin(yaw))};
  v.fov = eye == 0 ? XrFovf{-kOuterFov_rad, kInnerFov_rad, kUpFov_rad, -kDownFov_rad}
                   : XrFovf{-kInnerFov_rad, kOuterFov_rad, kUpFov_rad, -kDownFov_rad};
  return v;
}

bool same_view(const XrCompositionLayerProjectionView& a, const XrView& b) {
  const auto near = [](float x, float y) { return std::fabs(x - y) <= 1e-6f; };
  return near(a.pose.orientation.x, b.pose.orientation.x) &&
         near(a.pose.orientation.y, b.pose.orientation.y) &&
         near(a.pose.orientation.z, b.pose.orientation.z) &&
         near(a.pose.orientation.w, b.pose.orientation.w) &&
         near(a.pose.position.x, b.pose.position.x) && near(a.pose.position.y, b.pose.position.y) &&
         near(a.pose.position.z, b.pose.position.z) && near(a.fov.angleLeft, b.fov.angleLeft) &&
         near(a.fov.angleRight, b.fov.angleRight) && near(a.fov.angleUp, b.fov.angleUp) &&
         near(a.fov.angleDown, b.fov.angleDown);
}

// ---- instance and system ------------------------------------------------------------------

XRAPI_ATTR XrResult XRAPI_CALL enumerate_extensions(const char* layer, std::uint32_t capacity,
                                                    std::uint32_t* count,
                                                    XrExtensionProperties* props) {
  if (layer != nullptr) return XR_ERROR_API_LAYER_NOT_PRESENT;
  *count = 1;
  if (capacity == 0) return XR_SUCCESS;
  std::strcpy(props[0].extensionName, XR_KHR_VULKAN_ENABLE_EXTENSION_NAME);
  props[0].extensionVersion = XR_KHR_vulkan_enable_SPEC_VERSION;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL create_instance(const XrInstanceCreateInfo* info,
                                               XrInstance* instance) {
  Runtime& rt = runtime();
  if (rt.instance) return XR_ERROR_LIMIT_REACHED;
  bool vulkan = false;
  for (std::uint32_t i = 0; i < info->enabledExtensionCount; ++i) {
    const std::string_view name = info->enabledExtensionNames[i];
    if (name != XR_KHR_VULKAN_ENABLE_EXTENSION_NAME) return XR_ERROR_EXTENSION_NOT_PRESENT;
    vulkan = true;
  }
  if (!vulkan) problem("xrCreateInstance without XR_KHR_vulkan_enable");
  rt = Runtime{};
  rt.instance = true;
  if (const char* dir = std::getenv("OCEAN_TEST_XR_IMAGES"); dir != nullptr) rt.image_dir = dir;
  if (const char* hz = std::getenv("OCEAN_TEST_XR_HZ"); hz != nullptr && std::atof(hz) > 0.0)
    rt.period_ns = static_cast<std::int64_t>(1e9 / std::atof(hz));
  *instance = kInstance;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL destroy_instance(XrInstance) {
  Runtime& rt = runtime();
  write_report();
  rt.instance = false;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL get_instance_properties(XrInstance, XrInstanceProperties* props) {
  props->runtimeVersion = XR_MAKE_VERSION(0, 1, 0);
  std::strcpy(props->runtimeName, "ocean test runtime");
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL get_system(XrInstance, const XrSystemGetInfo* info,
                                          XrSystemId* system) {
  if (info->formFactor != XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY)
    return XR_ERROR_FORM_FACTOR_UNSUPPORTED;
  *system = kSystem;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL enumerate_view_configurations(XrInstance, XrSystemId,
                                                             std::uint32_t capacity,
                                                             std::uint32_t* count,
                                                             XrViewConfigurationType* types) {
  *count = 1;
  if (capacity > 0) types[0] = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL enumerate_view_configuration_views(XrInstance, XrSystemId,
                                                                  XrViewConfigurationType type,
                                                                  std::uint32_t capacity,
                                                                  std::uint32_t* count,
                                                                  XrViewConfigurationView* views) {
  if (type != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO)
    return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
  *count = 2;
  if (capacity == 0) return XR_SUCCESS;
  if (capacity < 2) return XR_ERROR_SIZE_INSUFFICIENT;
  for (int i = 0; i < 2; ++i) {
    views[i].recommendedImageRectWidth = views[i].recommendedImageRectHeight = kEyeSize;
    views[i].maxImageRectWidth = views[i].maxImageRectHeight = 4096;
    views[i].recommendedSwapchainSampleCount = views[i].maxSwapchainSampleCount = 1;
  }
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL enumerate_blend_modes(XrInstance, XrSystemId,
                                                     XrViewConfigurationType,
                                                     std::uint32_t capacity, std::uint32_t* count,
                                                     XrEnvironmentBlendMode* modes) {
  *count = 1;
  if (capacity > 0) modes[0] = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
  return XR_SUCCESS;
}

// ---- XR_KHR_vulkan_enable -----------------------------------------------------------------

XRAPI_ATTR XrResult XRAPI_CALL vulkan_extensions(XrInstance, XrSystemId, std::uint32_t capacity,
                                                 std::uint32_t* count, char* buffer) {
  return fill_string("", capacity, count, buffer);  // this runtime needs none
}

XRAPI_ATTR XrResult XRAPI_CALL vulkan_device(XrInstance, XrSystemId, VkInstance instance,
                                             VkPhysicalDevice* device) {
  std::uint32_t n = 1;
  const VkResult r = vkEnumeratePhysicalDevices(instance, &n, device);
  return (r == VK_SUCCESS || r == VK_INCOMPLETE) && n == 1 ? XR_SUCCESS : XR_ERROR_RUNTIME_FAILURE;
}

XRAPI_ATTR XrResult XRAPI_CALL vulkan_requirements(XrInstance, XrSystemId,
                                                   XrGraphicsRequirementsVulkanKHR* req) {
  req->minApiVersionSupported = XR_MAKE_VERSION(1, 0, 0);
  req->maxApiVersionSupported = XR_MAKE_VERSION(1, 3, 0);
  runtime().requirements_queried = true;
  return XR_SUCCESS;
}

// ---- session and events -------------------------------------------------------------------

XRAPI_ATTR XrResult XRAPI_CALL create_session(XrInstance, const XrSessionCreateInfo* info,
                                              XrSession* session) {
  Runtime& rt = runtime();
  if (!rt.requirements_queried) return XR_ERROR_GRAPHICS_REQUIREMENTS_CALL_MISSING;
  const auto* binding = static_cast<const XrGraphicsBindingVulkanKHR*>(info->next);
  if (binding == nullptr || binding->type != XR_TYPE_GRAPHICS_BINDING_VULKAN_KHR)
    return XR_ERROR_GRAPHICS_DEVICE_INVALID;
  if (rt.session) return XR_ERROR_LIMIT_REACHED;
  rt.binding = *binding;
  if (!open_device_queue()) return XR_ERROR_RUNTIME_FAILURE;
  rt.session = true;
  rt.events = {XR_SESSION_STATE_IDLE, XR_SESSION_STATE_READY};
  *session = kSession;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL destroy_session(XrSession) {
  Runtime& rt = runtime();
  for (auto& s : rt.swapchains) destroy_swapchain(*s);
  rt.swapchains.clear();
  close_device_queue();
  rt.session = false;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL poll_event(XrInstance, XrEventDataBuffer* buffer) {
  Runtime& rt = runtime();
  if (rt.events.empty()) return XR_EVENT_UNAVAILABLE;
  auto* e = reinterpret_cast<XrEventDataSessionStateChanged*>(buffer);
  *e = {XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED, nullptr, kSession, rt.events.front(), now_ns()};
  rt.events.pop_front();
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL begin_session(XrSession, const XrSessionBeginInfo* info) {
  Runtime& rt = runtime();
  if (info->primaryViewConfigurationType != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO)
    return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
  if (rt.running) return XR_ERROR_SESSION_RUNNING;
  rt.running = true;
  rt.next_display_ns = now_ns() + 2 * rt.period_ns;
  rt.first_predicted_ns = rt.next_display_ns;
  rt.events.insert(rt.events.end(), {XR_SESSION_STATE_SYNCHRONIZED, XR_SESSION_STATE_VISIBLE,
                                     XR_SESSION_STATE_FOCUSED});
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL request_exit(XrSession) {
  Runtime& rt = runtime();
  if (!rt.running) return XR_ERROR_SESSION_NOT_RUNNING;
  rt.events.insert(rt.events.end(), {XR_SESSION_STATE_VISIBLE, XR_SESSION_STATE_SYNCHRONIZED,
                                     XR_SESSION_STATE_STOPPING});
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL end_session(XrSession) {
  Runtime& rt = runtime();
  if (!rt.running) return XR_ERROR_SESSION_NOT_RUNNING;
  rt.running = false;
  rt.events.insert(rt.events.end(), {XR_SESSION_STATE_IDLE, XR_SESSION_STATE_EXITING});
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL create_space(XrSession, const XrReferenceSpaceCreateInfo*,
                                            XrSpace* space) {
  static std::uintptr_t next = 0x3001;
  *space = reinterpret_cast<XrSpace>(next++);
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL destroy_space(XrSpace) { return XR_SUCCESS; }

// ---- swapchains -----------------------------------------------------------------------------

XRAPI_ATTR XrResult XRAPI_CALL enumerate_formats(XrSession, std::uint32_t capacity,
                                                 std::uint32_t* count, std::int64_t* formats) {
  *count = 2;
  if (capacity == 0) return XR_SUCCESS;
  if (capacity < 2) return XR_ERROR_SIZE_INSUFFICIENT;
  formats[0] = VK_FORMAT_R8G8B8A8_SRGB;
  formats[1] = VK_FORMAT_B8G8R8A8_SRGB;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL create_swapchain_call(XrSession, const XrSwapchainCreateInfo* info,
                                                     XrSwapchain* swapchain) {
  return create_swapchain(*info, swapchain);
}

XRAPI_ATTR XrResult XRAPI_CALL destroy_swapchain_call(XrSwapchain handle) {
  auto& list = runtime().swapchains;
  for (auto it = list.begin(); it != list.end(); ++it) {
    if (reinterpret_cast<XrSwapchain>(it->get()) == handle) {
      destroy_swapchain(**it);
      list.erase(it);
      return XR_SUCCESS;
    }
  }
  return XR_ERROR_HANDLE_INVALID;
}

Swapchain& chain(XrSwapchain handle) { return *reinterpret_cast<Swapchain*>(handle); }

XRAPI_ATTR XrResult XRAPI_CALL enumerate_images(XrSwapchain handle, std::uint32_t capacity,
                                                std::uint32_t* count,
                                                XrSwapchainImageBaseHeader* images) {
  Swapchain& s = chain(handle);
  *count = static_cast<std::uint32_t>(s.images.size());
  if (capacity == 0) return XR_SUCCESS;
  if (capacity < *count) return XR_ERROR_SIZE_INSUFFICIENT;
  auto* vk_images = reinterpret_cast<XrSwapchainImageVulkanKHR*>(images);
  for (std::uint32_t i = 0; i < *count; ++i) vk_images[i].image = s.images[i];
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL acquire_image(XrSwapchain handle, const XrSwapchainImageAcquireInfo*,
                                             std::uint32_t* index) {
  Swapchain& s = chain(handle);
  if (s.acquired.size() == s.images.size()) return XR_ERROR_CALL_ORDER_INVALID;
  *index = s.next;
  s.acquired.push_back(s.next);
  s.next = (s.next + 1) % static_cast<std::uint32_t>(s.images.size());
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL wait_image(XrSwapchain handle, const XrSwapchainImageWaitInfo*) {
  return chain(handle).acquired.empty() ? XR_ERROR_CALL_ORDER_INVALID : XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL release_image(XrSwapchain handle,
                                             const XrSwapchainImageReleaseInfo*) {
  Swapchain& s = chain(handle);
  if (s.acquired.empty()) return XR_ERROR_CALL_ORDER_INVALID;
  s.released = s.acquired.front();
  s.acquired.pop_front();
  s.released_since_end_frame = true;
  return XR_SUCCESS;
}

// ---- frames ---------------------------------------------------------------------------------

XRAPI_ATTR XrResult XRAPI_CALL wait_frame(XrSession, const XrFrameWaitInfo*, XrFrameState* state) {
  Runtime& rt = runtime();
  if (!rt.running) return XR_ERROR_SESSION_NOT_RUNNING;
  // A compositor releases the application one period before the frame is displayed; an
  // application that fell behind gets the next display time still ahead of it.
  const std::int64_t now = now_ns();
  while (rt.next_display_ns < now) rt.next_display_ns += rt.period_ns;
  std::this_thread::sleep_for(std::chrono::nanoseconds(rt.next_display_ns - rt.period_ns - now));
  rt.predicted_ns = rt.next_display_ns;
  rt.next_display_ns += rt.period_ns;
  rt.waited = true;
  rt.located_valid = false;
  state->predictedDisplayTime = rt.predicted_ns;
  state->predictedDisplayPeriod = rt.period_ns;
  state->shouldRender = XR_TRUE;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL begin_frame(XrSession, const XrFrameBeginInfo*) {
  Runtime& rt = runtime();
  if (!rt.waited) return XR_ERROR_CALL_ORDER_INVALID;
  rt.waited = false;
  rt.begun = true;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL locate_views(XrSession, const XrViewLocateInfo* info,
                                            XrViewState* state, std::uint32_t capacity,
                                            std::uint32_t* count, XrView* views) {
  Runtime& rt = runtime();
  *count = 2;
  if (capacity == 0) return XR_SUCCESS;
  if (capacity < 2) return XR_ERROR_SIZE_INSUFFICIENT;
  if (info->displayTime != rt.predicted_ns)
    problem(frame_label() + ": xrLocateViews at " + std::to_string(info->displayTime) +
            ", predicted " + std::to_string(rt.predicted_ns));
  state->viewStateFlags = XR_VIEW_STATE_ORIENTATION_VALID_BIT | XR_VIEW_STATE_POSITION_VALID_BIT |
                          XR_VIEW_STATE_ORIENTATION_TRACKED_BIT |
                          XR_VIEW_STATE_POSITION_TRACKED_BIT;
  for (int i = 0; i < 2; ++i) {
    rt.located[i] = eye_view(i, info->displayTime);
    views[i].pose = rt.located[i].pose;
    views[i].fov = rt.located[i].fov;
  }
  rt.located_valid = info->displayTime == rt.predicted_ns;
  return XR_SUCCESS;
}

void check_projection(const XrCompositionLayerProjection& layer) {
  Runtime& rt = runtime();
  rt.views += layer.viewCount;
  if (layer.viewCount != 2) {
    problem(frame_label() + ": " + std::to_string(layer.viewCount) + " views, expected 2");
    return;
  }
  for (std::uint32_t i = 0; i < 2; ++i) {
    const XrCompositionLayerProjectionView& v = layer.views[i];
    Swapchain& s = chain(v.subImage.swapchain);
    const std::string view = frame_label() + " view " + std::to_string(i);
    if (!rt.located_valid || !same_view(v, rt.located[i]))
      problem(view + ": pose or field of view differs from xrLocateViews at the predicted time");
    if (v.subImage.imageRect.extent.width != std::int32_t(s.width) ||
        v.subImage.imageRect.extent.height != std::int32_t(s.height))
      problem(view + ": the image rectangle is not the whole swapchain image");
    if (!s.released_since_end_frame || s.released < 0) {
      problem(view + ": no swapchain image released during the frame");
      continue;
    }
    std::vector<std::uint8_t> rgba;
    ++rt.images_checked;
    if (!read_back(s, static_cast<std::uint32_t>(s.released), rgba)) {
      problem(view + ": could not read the image back");
      rt.min_lit_fraction = std::min(rt.min_lit_fraction, -1.0);
      continue;
    }
    // Lit: more than half the pixels have a channel above 8 of 255.
    std::size_t lit_pixels = 0;
    for (std::size_t p = 0; p < rgba.size(); p += 4)
      if (std::max({rgba[p], rgba[p + 1], rgba[p + 2]}) > 8) ++lit_pixels;
    const double lit = double(lit_pixels) / double(rgba.size() / 4);
    if (lit > 0.5) ++rt.images_lit;
    rt.min_lit_fraction = std::min(rt.min_lit_fraction, lit);
    if (!rt.image_dir.empty()) {
      const std::string path = rt.image_dir + "/view" + std::to_string(i) + ".png";
      if (!write_png(path, s.width, s.height, rgba)) problem(view + ": cannot write " + path);
      rt.saved[i] = rt.located[i];
      rt.images_saved = true;
    }
  }
}

XRAPI_ATTR XrResult XRAPI_CALL end_frame(XrSession, const XrFrameEndInfo* info) {
  Runtime& rt = runtime();
  if (!rt.begun) return XR_ERROR_CALL_ORDER_INVALID;
  rt.begun = false;
  if (info->displayTime != rt.predicted_ns)
    problem(frame_label() + ": xrEndFrame at " + std::to_string(info->displayTime) +
            ", predicted " + std::to_string(rt.predicted_ns));
  if (info->layerCount != 1 || info->layers[0]->type != XR_TYPE_COMPOSITION_LAYER_PROJECTION) {
    problem(frame_label() + ": expected one projection layer");
  } else {
    check_projection(*reinterpret_cast<const XrCompositionLayerProjection*>(info->layers[0]));
  }
  for (auto& s : rt.swapchains) s->released_since_end_frame = false;
  ++rt.frames;
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL result_to_string(XrInstance, XrResult value, char* buffer) {
  std::snprintf(buffer, XR_MAX_RESULT_STRING_SIZE, "XR_RESULT_%d", int(value));
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL structure_to_string(XrInstance, XrStructureType value,
                                                   char* buffer) {
  std::snprintf(buffer, XR_MAX_STRUCTURE_NAME_SIZE, "XR_STRUCTURE_%d", int(value));
  return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL get_proc_addr(XrInstance, const char* name,
                                             PFN_xrVoidFunction* function) {
  struct Entry {
    const char* name;
    PFN_xrVoidFunction fn;
  };
#define OCEAN_XR_ENTRY(xr_name, fn) \
  { #xr_name, reinterpret_cast < PFN_xrVoidFunction>(fn) }
  static const Entry entries[] = {
      OCEAN_XR_ENTRY(xrGetInstanceProcAddr, get_proc_addr),
      OCEAN_XR_ENTRY(xrEnumerateInstanceExtensionProperties, enumerate_extensions),
      OCEAN_XR_ENTRY(xrCreateInstance, create_instance),
      OCEAN_XR_ENTRY(xrDestroyInstance, destroy_instance),
      OCEAN_XR_ENTRY(xrGetInstanceProperties, get_instance_properties),
      OCEAN_XR_ENTRY(xrGetSystem, get_system),
      OCEAN_XR_ENTRY(xrEnumerateViewConfigurations, enumerate_view_configurations),
      OCEAN_XR_ENTRY(xrEnumerateViewConfigurationViews, enumerate_view_configuration_views),
      OCEAN_XR_ENTRY(xrEnumerateEnvironmentBlendModes, enumerate_blend_modes),
      OCEAN_XR_ENTRY(xrGetVulkanInstanceExtensionsKHR, vulkan_extensions),
      OCEAN_XR_ENTRY(xrGetVulkanDeviceExtensionsKHR, vulkan_extensions),
      OCEAN_XR_ENTRY(xrGetVulkanGraphicsDeviceKHR, vulkan_device),
      OCEAN_XR_ENTRY(xrGetVulkanGraphicsRequirementsKHR, vulkan_requirements),
      OCEAN_XR_ENTRY(xrCreateSession, create_session),
      OCEAN_XR_ENTRY(xrDestroySession, destroy_session),
      OCEAN_XR_ENTRY(xrPollEvent, poll_event),
      OCEAN_XR_ENTRY(xrBeginSession, begin_session),
      OCEAN_XR_ENTRY(xrEndSession, end_session),
      OCEAN_XR_ENTRY(xrRequestExitSession, request_exit),
      OCEAN_XR_ENTRY(xrCreateReferenceSpace, create_space),
      OCEAN_XR_ENTRY(xrDestroySpace, destroy_space),
      OCEAN_XR_ENTRY(xrEnumerateSwapchainFormats, enumerate_formats),
      OCEAN_XR_ENTRY(xrCreateSwapchain, create_swapchain_call),
      OCEAN_XR_ENTRY(xrDestroySwapchain, destroy_swapchain_call),
      OCEAN_XR_ENTRY(xrEnumerateSwapchainImages, enumerate_images),
      OCEAN_XR_ENTRY(xrAcquireSwapchainImage, acquire_image),
      OCEAN_XR_ENTRY(xrWaitSwapchainImage, wait_image),
      OCEAN_XR_ENTRY(xrReleaseSwapchainImage, release_image),
      OCEAN_XR_ENTRY(xrWaitFrame, wait_frame),
      OCEAN_XR_ENTRY(xrBeginFrame, begin_frame),
      OCEAN_XR_ENTRY(xrEndFrame, end_frame),
      OCEAN_XR_ENTRY(xrLocateViews, locate_views),
      OCEAN_XR_ENTRY(xrResultToString, result_to_string),
      OCEAN_XR_ENTRY(xrStructureTypeToString, structure_to_string),
  };
#undef OCEAN_XR_ENTRY
  for (const Entry& e : entries) {
    if (std::strcmp(e.name, name) == 0) {
      *function = e.fn;
      return XR_SUCCESS;
    }
  }
  *function = nullptr;
  return XR_ERROR_FUNCTION_UNSUPPORTED;
}

}  // namespace

}  // namespace ocean::test_xr

extern "C" __attribute__((visibility("default"))) XrResult xrNegotiateLoaderRuntimeInterface(
    const XrNegotiateLoaderInfo* info, XrNegotiateRuntimeRequest* request) {
  if (info == nullptr || request == nullptr ||
      info->structType != XR_LOADER_INTERFACE_STRUCT_LOADER_INFO ||
      request->structType != XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST ||
      info->minInterfaceVersion > 1 || info->maxInterfaceVersion < 1)
    return XR_ERROR_INITIALIZATION_FAILED;
  request->runtimeInterfaceVersion = 1;
  request->runtimeApiVersion = XR_CURRENT_API_VERSION;
  request->getInstanceProcAddr = ocean::test_xr::get_proc_addr;
  return XR_SUCCESS;
}
