// src/capi/status.cpp — the C ABI's version queries, status names and the per-thread last error.
#include <cstring>

#include "capi_internal.hpp"

namespace ocean::capi {
namespace {

// The last error of this thread. `fallback` stands in when the message could not be stored.
thread_local std::string t_message;
thread_local const char* t_fallback = nullptr;

static_assert(static_cast<int>(ErrorCode::invalid_argument) == OCEAN_INVALID_ARGUMENT &&
                  static_cast<int>(ErrorCode::io_error) == OCEAN_IO_ERROR &&
                  static_cast<int>(ErrorCode::unsupported) == OCEAN_UNSUPPORTED &&
                  static_cast<int>(ErrorCode::internal) == OCEAN_INTERNAL &&
                  static_cast<int>(ErrorCode::cancelled) == OCEAN_CANCELLED,
              "ocean_status mirrors ocean::ErrorCode");
// ocean.h's version and ABI agree with the project's (CMakeLists.txt) and the soname.
static_assert(OCEAN_VERSION == (OCEAN_PROJECT_VERSION), "ocean.h's version is the project's");
static_assert(OCEAN_ABI_VERSION == OCEAN_C_ABI_VERSION, "ocean.h's ABI version is the soname");

}  // namespace

ocean_status fail(ocean_status status, std::string_view message, std::string_view detail) noexcept {
  try {
    t_message.assign(message);
    t_message.append(detail);
    // One line, as the CLI prints it: a message never carries a newline of its own.
    for (char& c : t_message) {
      if (c == '\n' || c == '\r') c = ' ';
    }
    t_fallback = nullptr;
  } catch (...) {
    t_fallback = "out of memory";
  }
  log_message(OCEAN_LOG_ERROR, t_fallback != nullptr ? t_fallback : t_message.c_str());
  return status;
}

ocean_status succeed() noexcept {
  t_message.clear();
  t_fallback = nullptr;
  return OCEAN_OK;
}

ocean_status from_status(const Status& status) noexcept {
  if (status.ok()) return succeed();
  return fail(static_cast<ocean_status>(status.code()), status.message());
}

Status require_not_null(const void* pointer, std::string_view function, std::string_view what) {
  if (pointer != nullptr) return {};
  return invalid_argument(std::string(function) + ": " + std::string(what) + " is NULL");
}

std::string indexed(std::string_view name, std::size_t index) {
  // Built with append rather than operator+ to dodge a g++ 12 -O3 -Wrestrict false positive.
  std::string text(name);
  text.append(1, '[').append(std::to_string(index)).append(1, ']');
  return text;
}

}  // namespace ocean::capi

extern "C" {

OCEAN_API uint32_t ocean_version(void) { return OCEAN_VERSION; }

OCEAN_API const char* ocean_version_string(void) {
#define OCEAN_STRINGIFY2(x) #x
#define OCEAN_STRINGIFY(x) OCEAN_STRINGIFY2(x)
  return OCEAN_STRINGIFY(OCEAN_VERSION_MAJOR) "." OCEAN_STRINGIFY(
      OCEAN_VERSION_MINOR) "." OCEAN_STRINGIFY(OCEAN_VERSION_PATCH);
#undef OCEAN_STRINGIFY
#undef OCEAN_STRINGIFY2
}

OCEAN_API uint32_t ocean_abi_version(void) { return OCEAN_ABI_VERSION; }

OCEAN_API const char* ocean_last_error(void) {
  using namespace ocean::capi;
  return t_fallback != nullptr ? t_fallback : t_message.c_str();
}

OCEAN_API const char* ocean_status_name(ocean_status status) {
  switch (status) {
    case OCEAN_OK: return "ok";
    case OCEAN_INVALID_ARGUMENT: return "invalid_argument";
    case OCEAN_IO_ERROR: return "io_error";
    case OCEAN_UNSUPPORTED: return "unsupported";
    case OCEAN_INTERNAL: return "internal";
    case OCEAN_CANCELLED: return "cancelled";
    case OCEAN_OUT_OF_MEMORY: return "out_of_memory";
    case OCEAN_STATUS_MAX_ENUM: break;
  }
  return "unknown";
}

}  // extern "C"
