// cuFFT, loaded at run time (dlopen) the first time a CUDA backend is made: the library is large
// (≈ 290 MB), and linking it would cost every process of the tool and the tests ≈ 30 ms at start
// and a missing libcufft would stop the tool from starting at all; loaded, a missing one leaves
// the backend on its own FFT kernels (FftEngine::automatic) or is one error line.
#pragma once

#include <cufft.h>

#include "ocean/core.hpp"

namespace ocean::cuda::detail {

/// The entry points the backend uses, with cuFFT's own signatures.
struct CufftLibrary {
  decltype(&cufftPlanMany) plan_many = nullptr;
  decltype(&cufftSetStream) set_stream = nullptr;
  decltype(&cufftExecC2C) exec_c2c = nullptr;
  decltype(&cufftDestroy) destroy = nullptr;
  decltype(&cufftGetVersion) get_version = nullptr;
};

/// The file name dlopen looks for: libcufft.so.<CUFFT_VER_MAJOR> of the headers this build used.
const char* cufft_soname();

/// Loads cuFFT once per process (thread-safe) and returns its entry points; `unsupported`
/// "cuFFT (libcufft.so.N) not found: ..." when it or a symbol is missing.
Result<const CufftLibrary*> load_cufft();

}  // namespace ocean::cuda::detail
