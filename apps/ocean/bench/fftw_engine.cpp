// FFTW loaded with dlopen: the handful of entry points the baseline needs.
#include "bench/fftw_engine.hpp"

#include <dlfcn.h>
#include <fftw3.h>

#include <mutex>
#include <string>

namespace ocean::cli {

struct FftwApi {
  decltype(&fftwf_plan_guru_split_dft) plan_guru_split_dft = nullptr;
  decltype(&fftwf_execute_split_dft) execute_split_dft = nullptr;
  decltype(&fftwf_destroy_plan) destroy_plan = nullptr;
  decltype(&fftwf_init_threads) init_threads = nullptr;  // null without libfftw3f_threads
  decltype(&fftwf_plan_with_nthreads) plan_with_nthreads = nullptr;
};

namespace {

template <typename F>
bool bind(void* library, const char* name, F& f) {
  f = reinterpret_cast<F>(dlsym(library, name));
  return f != nullptr;
}

Result<const FftwApi*> load_api() {
  static FftwApi api;
  static std::string error;
  static std::once_flag once;
  std::call_once(once, [] {
    void* core = dlopen("libfftw3f.so.3", RTLD_NOW | RTLD_GLOBAL);
    if (core == nullptr) {
      error = "FFTW not found (libfftw3f.so.3): install Debian's libfftw3-single3 for the baseline";
      return;
    }
    if (!bind(core, "fftwf_plan_guru_split_dft", api.plan_guru_split_dft) ||
        !bind(core, "fftwf_execute_split_dft", api.execute_split_dft) ||
        !bind(core, "fftwf_destroy_plan", api.destroy_plan)) {
      error = "libfftw3f.so.3 lacks the split-complex guru interface";
      return;
    }
    if (void* threads = dlopen("libfftw3f_threads.so.3", RTLD_NOW | RTLD_GLOBAL)) {
      if (bind(threads, "fftwf_init_threads", api.init_threads) &&
          bind(threads, "fftwf_plan_with_nthreads", api.plan_with_nthreads)) {
        api.init_threads();
      } else {
        api.init_threads = nullptr;
      }
    }
  });
  if (!error.empty()) return unsupported(error);
  return &api;
}

}  // namespace

struct FftwEngine::Plan {
  const float* re;
  const float* im;
  fftwf_plan plan;
};

Result<std::unique_ptr<FftwEngine>> FftwEngine::make(int n, int threads) {
  Result<const FftwApi*> api = load_api();
  if (!api.ok()) return api.status();
  if (threads > 1 && api.value()->init_threads == nullptr)
    return unsupported("FFTW threads not found (libfftw3f_threads.so.3)");
  std::unique_ptr<FftwEngine> engine(new FftwEngine());
  engine->api_ = api.value();
  engine->n_ = n;
  engine->threads_ = threads;
  return engine;
}

FftwEngine::~FftwEngine() {
  for (const Plan& p : plans_) api_->destroy_plan(p.plan);
}

void FftwEngine::inverse(std::span<const fft::SplitComplex> planes) {
  for (const fft::SplitComplex& s : planes) {
    // FFTW's split transforms are forward; exchanging re and im gives the backward transform
    // e^{+2πi·jk/N}, our convention.
    // One plan per plane: FFTW_MEASURE wisdom makes the repeats cheap, and executing each plan
    // on the arrays it was made for avoids the new-array rules.
    fftwf_plan plan = nullptr;
    for (const Plan& p : plans_) {
      if (p.re == s.re && p.im == s.im) plan = p.plan;
    }
    if (plan == nullptr) {
      if (api_->plan_with_nthreads != nullptr) api_->plan_with_nthreads(threads_);
      fftwf_iodim dims[2] = {{n_, n_, n_}, {n_, 1, 1}};
      plan = api_->plan_guru_split_dft(2, dims, 0, nullptr, s.im, s.re, s.im, s.re, FFTW_MEASURE);
      plans_.push_back({s.re, s.im, plan});
    }
    api_->execute_split_dft(plan, s.im, s.re, s.im, s.re);
  }
}

}  // namespace ocean::cli
