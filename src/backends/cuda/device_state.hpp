// Every CUDA object of a configured simulation and the one function that issues a frame's
// schedule (plan.hpp) on its streams, eagerly or into a captured graph.
#pragma once

#include <cufft.h>

#include <vector>

#include "cufft_library.hpp"
#include "far_noise_kernel.hpp"
#include "kernels.hpp"
#include "ocean/backends/cuda.hpp"
#include "ocean/interop.hpp"
#include "plan.hpp"

namespace ocean::cuda::detail {

struct DeviceState {
  DeviceState() = default;
  ~DeviceState();  // releases everything below, in reverse order; errors are ignored
  DeviceState(const DeviceState&) = delete;
  DeviceState& operator=(const DeviceState&) = delete;

  Layout layout;
  const CufftLibrary* cufft = nullptr;  // nullptr: the own FFT kernels
  char* device = nullptr;               // Layout::device_bytes(), every cascade's block
  FrameParams* params_device = nullptr;
  char* host = nullptr;                  // pinned: Layout::host_bytes(), every readback block
  FrameParams* params_host = nullptr;    // pinned, rewritten before each frame
  std::vector<cudaStream_t> streams;     // origin + one per cascade (+ the noise map's)
  std::vector<cudaEvent_t> events;       // fork + one join per cascade (+ the map's), no timing
  std::vector<cufftHandle> plans;        // cuFFT: per cascade, `planes` 2-D N×N C2C transforms
  std::vector<CascadeArgs> args;         // per cascade
  cudaGraphExec_t frame = nullptr;       // concurrent, with readback: what step() launches
  cudaGraphExec_t simulation = nullptr;  // concurrent, no readback (time_frames)
  cudaGraphExec_t serial = nullptr;      // one stream, no readback (time_frames)
  cudaEvent_t start = nullptr, stop = nullptr;  // timing events
  // The far field's noise map (far_noise_state.cpp), when Layout::noise_resolution > 0:
  FarNoiseArgs noise;                        // its kernel's arguments
  cudaGraphExec_t cascades_alone = nullptr;  // time_frames: the cascades without the map
  cudaGraphExec_t noise_alone = nullptr;     // time_frames: the map without the cascades
  // The renderer's shared inputs (CudaBackend::share_inputs): the imported Vulkan memory mapped as
  // a buffer, the two imported semaphores, and the frame's graph with the share copies.
  cudaExternalMemory_t shared_memory = nullptr;
  char* shared = nullptr;  // mapped: interop::inputs_layout, freed with cudaFree
  interop::InputsLayout shared_layout;
  cudaExternalSemaphore_t written = nullptr, read = nullptr;
  bool timeline = false;
  cudaGraphExec_t shared_frame = nullptr;  // concurrent, with share copies and readback
  std::uint64_t shared_frames = 0;         // frames written into `shared` (the semaphore value)
  void release_shared();                   // the five above; errors are ignored
};

/// Creates streams, events, buffers and plans (with `cufft`; nullptr for the own FFT kernels) for
/// `layout`, and fills `args` from `base` (the configuration's scalars) and the buffers. The
/// spectra and twiddles are the caller's to upload.
Status create_device_state(DeviceState& state, const Layout& layout, const CufftLibrary* cufft,
                           const CascadeArgs& base);

/// Issues `schedule` on the state's streams: eagerly (capture = false; the caller synchronises),
/// or captured into an instantiated graph stored in `*graph`.
Status issue(DeviceState& state, const Schedule& schedule, bool capture,
             cudaGraphExec_t* graph = nullptr);

}  // namespace ocean::cuda::detail
