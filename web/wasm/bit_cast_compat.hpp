// bit_cast_compat.hpp — std::bit_cast for C++ libraries that lack it (emscripten 3.1.6's libc++),
// force-included into the WebAssembly build only (web/wasm/CMakeLists.txt). Clang's builtin is
// what libc++ itself uses where it has std::bit_cast.
#pragma once
#include <version>

#if !defined(__cpp_lib_bit_cast)
#include <type_traits>
namespace std {
template <class To, class From>
  requires(sizeof(To) == sizeof(From) && is_trivially_copyable_v<To> &&
           is_trivially_copyable_v<From>)
constexpr To bit_cast(const From& from) noexcept {
  return __builtin_bit_cast(To, from);
}
}  // namespace std
#endif
