// cuFFT loaded with dlopen (cufft_library.hpp). The handle stays open for the process's life:
// plans of any backend may outlive each other, and unloading buys nothing.
#include "cufft_library.hpp"

#include <dlfcn.h>

#include <string>

namespace ocean::cuda::detail {
namespace {

#define OCEAN_CUFFT_STRINGIFY2(x) #x
#define OCEAN_CUFFT_STRINGIFY(x) OCEAN_CUFFT_STRINGIFY2(x)
constexpr const char* kSoname = "libcufft.so." OCEAN_CUFFT_STRINGIFY(CUFFT_VER_MAJOR);

template <typename F>
bool bind(void* handle, const char* symbol, F& f) {
  f = reinterpret_cast<F>(dlsym(handle, symbol));
  return f != nullptr;
}

Result<const CufftLibrary*> load_once() {
  static CufftLibrary library;
  void* handle = dlopen(kSoname, RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    return unsupported(std::string("cuFFT (") + kSoname +
                       ") not found: install the CUDA toolkit's cuFFT or add its lib64 folder "
                       "to LD_LIBRARY_PATH (" +
                       excerpt(why != nullptr ? why : "dlopen failed") + ")");
  }
  if (!bind(handle, "cufftPlanMany", library.plan_many) ||
      !bind(handle, "cufftSetStream", library.set_stream) ||
      !bind(handle, "cufftExecC2C", library.exec_c2c) ||
      !bind(handle, "cufftDestroy", library.destroy) ||
      !bind(handle, "cufftGetVersion", library.get_version)) {
    return unsupported(std::string("cuFFT: ") + kSoname +
                       " lacks a function this build calls: install the cuFFT of the CUDA "
                       "toolkit it was built with");
  }
  return &library;
}

}  // namespace

const char* cufft_soname() { return kSoname; }

Result<const CufftLibrary*> load_cufft() {
  static const Result<const CufftLibrary*> loaded = load_once();
  return loaded;
}

}  // namespace ocean::cuda::detail
