// CUDA runtime and cuFFT results as Status (errors.hpp). The runtime links statically and loads
// the driver (libcuda) itself, so a machine without one reaches here with
// cudaErrorInsufficientDriver from the first call instead of failing to start.
#include "errors.hpp"

#include <string>

namespace ocean::cuda::detail {
namespace {

// What to do about each way of having no usable device.
std::string_view advice(cudaError_t error) {
  switch (error) {
    case cudaErrorInsufficientDriver:
      return "the NVIDIA driver is missing or older than this build's CUDA runtime: install or "
             "update the driver";
    case cudaErrorNoDevice:
      return "no CUDA-capable GPU is visible (check the driver and CUDA_VISIBLE_DEVICES)";
    case cudaErrorStubLibrary:
      return "the CUDA driver found is the toolkit's stub library: install the NVIDIA driver";
    case cudaErrorCallRequiresNewerDriver:
      return "the NVIDIA driver is too old for this build's CUDA runtime: update the driver";
    case cudaErrorSystemDriverMismatch:
      return "the NVIDIA kernel module and user-space driver versions differ: reinstall the "
             "driver or reboot";
    case cudaErrorCompatNotSupportedOnDevice:
      return "the CUDA forward-compatibility driver does not support this GPU: use the system "
             "driver";
    case cudaErrorDevicesUnavailable:
      return "every CUDA device is busy or in exclusive-process mode (see nvidia-smi)";
    case cudaErrorSystemNotReady:
      return "the CUDA system is not ready (fabric manager not running?)";
    case cudaErrorNoKernelImageForDevice:
    case cudaErrorUnsupportedPtxVersion:
    case cudaErrorJitCompilerNotFound:
      return "this build has no code for the GPU: rebuild with its architecture in "
             "CMAKE_CUDA_ARCHITECTURES";
    case cudaErrorInitializationError:
      return "the CUDA driver failed to initialise (check dmesg and nvidia-smi)";
    case cudaErrorInvalidDevice: return "the selected CUDA device does not exist";
    default: return {};
  }
}

}  // namespace

bool means_no_device(cudaError_t error) { return !advice(error).empty(); }

Status to_status(cudaError_t error, std::string_view what) {
  if (error == cudaSuccess) return {};
  const std::string name = cudaGetErrorName(error);
  if (means_no_device(error))
    return unsupported(std::string(kNoDevice) + std::string(advice(error)) + " (" + name + ")");
  if (error == cudaErrorMemoryAllocation)
    return unsupported("out of CUDA device memory in " + std::string(what) +
                       ": lower the resolution or the cascades (" + name + ")");
  return {ErrorCode::internal, "CUDA error in " + std::string(what) + ": " +
                                   cudaGetErrorString(error) + " (" + name + ")"};
}

std::string_view cufft_result_name(cufftResult result) {
  switch (result) {
    case CUFFT_SUCCESS: return "CUFFT_SUCCESS";
    case CUFFT_INVALID_PLAN: return "CUFFT_INVALID_PLAN";
    case CUFFT_ALLOC_FAILED: return "CUFFT_ALLOC_FAILED";
    case CUFFT_INVALID_TYPE: return "CUFFT_INVALID_TYPE";
    case CUFFT_INVALID_VALUE: return "CUFFT_INVALID_VALUE";
    case CUFFT_INTERNAL_ERROR: return "CUFFT_INTERNAL_ERROR";
    case CUFFT_EXEC_FAILED: return "CUFFT_EXEC_FAILED";
    case CUFFT_SETUP_FAILED: return "CUFFT_SETUP_FAILED";
    case CUFFT_INVALID_SIZE: return "CUFFT_INVALID_SIZE";
    case CUFFT_UNALIGNED_DATA: return "CUFFT_UNALIGNED_DATA";
    case CUFFT_INVALID_DEVICE: return "CUFFT_INVALID_DEVICE";
    case CUFFT_NO_WORKSPACE: return "CUFFT_NO_WORKSPACE";
    case CUFFT_NOT_IMPLEMENTED: return "CUFFT_NOT_IMPLEMENTED";
    case CUFFT_NOT_SUPPORTED: return "CUFFT_NOT_SUPPORTED";
    default: return "cufftResult (unknown)";
  }
}

Status to_status(cufftResult result, std::string_view what) {
  if (result == CUFFT_SUCCESS) return {};
  const std::string message =
      "cuFFT error in " + std::string(what) + ": " + std::string(cufft_result_name(result));
  if (result == CUFFT_ALLOC_FAILED)
    return unsupported(message + " (out of device memory: lower the resolution or the cascades)");
  return {ErrorCode::internal, message};
}

}  // namespace ocean::cuda::detail
