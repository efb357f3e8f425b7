// src/capi/capi_internal.hpp — what the C ABI's translation units share (private to src/capi):
// the handle types behind the opaque C pointers, the per-thread last error, and the guard that
// turns every Status and every exception into an ocean_status.
#pragma once

#include <functional>
#include <memory>
#include <new>
#include <string>
#include <string_view>

#include "ocean/core.hpp"
#include "ocean/ocean.h"
#include "ocean/preset.hpp"
#include "ocean/sim.hpp"

// The handles are global-namespace structs because ocean.h declares them there.
struct ocean_config {
  ocean::preset::Document document;  // the layers as merged, always valid
  ocean::SimulationConfig config;    // document.config(), kept in step with it
};

struct ocean_simulator {
  std::unique_ptr<ocean::Simulator> simulator;
};

namespace ocean::capi {

/// Records `message` + `detail` as this thread's last error (ocean_last_error) and returns
/// `status`. If even the copy fails for lack of memory, the message becomes "out of memory".
/// Never throws.
ocean_status fail(ocean_status status, std::string_view message,
                  std::string_view detail = {}) noexcept;
/// Hands `message` to the log callback (ocean_set_log_callback), if one is set. Never throws.
void log_message(ocean_log_level level, const char* message) noexcept;
/// INFO: what `simulator` was made with, on `threads` threads.
void log_created(const Simulator& simulator, int threads) noexcept;

/// Clears this thread's last error and returns OCEAN_OK. Never throws.
ocean_status succeed() noexcept;
/// The ocean_status of a library Status, its message recorded as the last error.
ocean_status from_status(const Status& status) noexcept;

/// invalid_argument "<function>: <what> is NULL" when `pointer` is null, else ok.
Status require_not_null(const void* pointer, std::string_view function, std::string_view what);

/// "<name>[<index>]", how messages name an element of a caller's array.
std::string indexed(std::string_view name, std::size_t index);

/// Makes the backend of a simulator (by name, or on an engine's Vulkan device).
using BackendFactory = std::function<Result<std::unique_ptr<Backend>>()>;

/// ocean_simulator_create_with_options' checks of `o` (named in messages as `function`'s
/// options), then a simulator of `config` with o's outputs and runner on the backend `make`
/// makes (o.backend by name when `make` is empty).
Status simulator_with_options(const ocean_config& config, const ocean_simulator_options& o,
                              std::string_view function, const BackendFactory& make,
                              ocean_simulator*& out);

/// Fills `view` (but its struct_size and patch size) for one field of a cascade's host arrays.
Status field_view(const CascadeFrame& cascade, ocean_field field, int32_t level,
                  ocean_field_view& view);

/// The first failure of a frame on the simulator's device backend (device lost, timeout); ok on
/// the CPU backend and while everything works. Not while a kicked frame runs.
Status device_status(const Simulator& simulator);

/// Runs `body` (returning a Status) so that nothing escapes into C: its Status becomes the
/// result, std::bad_alloc OCEAN_OUT_OF_MEMORY, any other exception OCEAN_INTERNAL.
template <typename Body>
ocean_status guarded(Body&& body) noexcept {
  try {
    return from_status(body());
  } catch (const std::bad_alloc&) {
    return fail(OCEAN_OUT_OF_MEMORY, "out of memory");
  } catch (const std::exception& e) {
    return fail(OCEAN_INTERNAL, "internal error: ", e.what());
  } catch (...) {
    return fail(OCEAN_INTERNAL, "internal error: an unknown exception");
  }
}

}  // namespace ocean::capi
