// src/capi/hooks.cpp — where the C ABI's messages and the simulation's large arrays go
// (ocean_set_log_callback, ocean_set_allocator).
#include <mutex>
#include <string>

#include "capi_internal.hpp"
#include "ocean/memory.hpp"

namespace ocean::capi {
namespace {

struct LogSink {
  ocean_log_fn log = nullptr;
  void* user_data = nullptr;
};
std::mutex g_log_mutex;
LogSink g_log;

}  // namespace

void log_message(ocean_log_level level, const char* message) noexcept {
  LogSink sink;
  {
    const std::lock_guard lock(g_log_mutex);
    sink = g_log;
  }
  if (sink.log != nullptr) sink.log(sink.user_data, level, message);
}

void log_created(const Simulator& simulator, int threads) noexcept {
  try {
    const SimulationConfig& c = simulator.config();
    std::string text = "simulator: " + std::string(simulator.backend().name()) + " backend, " +
                       std::to_string(c.cascade_patch_sizes_m.size()) + " cascade" +
                       (c.cascade_patch_sizes_m.size() == 1 ? "" : "s") + " of " +
                       std::to_string(c.resolution) + " x " + std::to_string(c.resolution) +
                       " (patches";
    for (std::size_t i = 0; i < c.cascade_patch_sizes_m.size(); ++i)
      text += (i == 0 ? " " : ", ") + format_number(c.cascade_patch_sizes_m[i]);
    text += " m), on " + std::to_string(threads) + " thread" + (threads == 1 ? "" : "s");
    log_message(OCEAN_LOG_INFO, text.c_str());
  } catch (...) {  // no memory for the message: nothing to say
  }
}

}  // namespace ocean::capi

extern "C" {

using namespace ocean::capi;

OCEAN_API void ocean_set_log_callback(ocean_log_fn log, void* user_data) {
  const std::lock_guard lock(g_log_mutex);
  g_log = {log, user_data};
}

OCEAN_API ocean_status ocean_set_allocator(const ocean_allocator* allocator) {
  return guarded([&]() -> ocean::Status {
    constexpr std::string_view f = "ocean_set_allocator: ";
    ocean::LargeAllocatorHooks hooks;
    if (allocator != nullptr) {
      if (allocator->struct_size < sizeof(ocean_allocator))
        return ocean::invalid_argument(
            std::string(f) + "allocator->struct_size = " + std::to_string(allocator->struct_size) +
            " is too small: must be sizeof(ocean_allocator)");
      if (allocator->allocate == nullptr || allocator->deallocate == nullptr)
        return ocean::invalid_argument(
            std::string(f) + "allocator->" +
            (allocator->allocate == nullptr ? "allocate" : "deallocate") + " is NULL");
      hooks = {allocator->user_data, allocator->allocate, allocator->deallocate};
    }
    if (!ocean::set_large_allocator(allocator != nullptr ? &hooks : nullptr)) {
      return ocean::invalid_argument(
          std::string(f) + std::to_string(ocean::live_large_arrays()) +
          " large arrays are live (a simulator exists): destroy every simulator first, each array "
          "goes back to the allocator that made it");
    }
    return {};
  });
}

}  // extern "C"
