// CUDA runtime and cuFFT results as the library's Status: one line that says what failed and
// what to do. Host code only (no kernel), tested without a device (tests/backends/cuda_test.cpp).
#pragma once

#include <cuda_runtime_api.h>
#include <cufft.h>

#include <string_view>

#include "ocean/core.hpp"

namespace ocean::cuda::detail {

/// The prefix of every error that means "this machine cannot run the CUDA backend".
inline constexpr std::string_view kNoDevice = "no CUDA device: ";

/// Whether `error` means that no device can be used at all (no driver, a driver older than the
/// runtime, no GPU, a GPU without code in this build, devices busy or not ready), as opposed to
/// a failure of one call on a working device.
bool means_no_device(cudaError_t error);

/// ok for cudaSuccess. Errors of means_no_device() become `unsupported` "no CUDA device: <why,
/// what to do> (<name>)"; out of memory becomes `unsupported` naming `what`; every other error
/// `internal` "CUDA error in <what>: <runtime's text> (<name>)".
Status to_status(cudaError_t error, std::string_view what);

/// ok for CUFFT_SUCCESS; otherwise `unsupported` for allocation failures and `internal` for the
/// rest, "cuFFT error in <what>: <result name>".
Status to_status(cufftResult result, std::string_view what);

/// The name of a cuFFT result ("CUFFT_ALLOC_FAILED"), "cufftResult <n>" for unknown values.
std::string_view cufft_result_name(cufftResult result);

}  // namespace ocean::cuda::detail
