// The CUDA backend's host-side logic, which needs no device: the runtime's and cuFFT's errors as
// one-line Status values (every way of having no device says "no CUDA device: "), the frame's
// memory layout (against the Frame arrays allocate_frame sizes: an identity), the mip passes
// (every level once) and the frame's schedule (each cascade on its own stream, every event
// recorded before it is waited for). On this machine class (CI: no GPU, no driver) the backend's
// factory must answer the mapped runtime error; where a device exists it must succeed.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <set>
#include <string>
#include <vector>

#include "cuda/cufft_library.hpp"
#include "cuda/errors.hpp"
#include "cuda/plan.hpp"
#include "ocean/backends.hpp"
#include "ocean/cuda/simulation.hpp"

namespace {

namespace d = ocean::cuda::detail;

bool one_line(const std::string& s) { return s.find('\n') == std::string::npos && !s.empty(); }

TEST(CudaErrors, EveryWayOfHavingNoDeviceSaysSoOnOneLine) {
  for (const cudaError_t e :
       {cudaErrorInsufficientDriver, cudaErrorNoDevice, cudaErrorStubLibrary,
        cudaErrorCallRequiresNewerDriver, cudaErrorSystemDriverMismatch,
        cudaErrorCompatNotSupportedOnDevice, cudaErrorDevicesUnavailable, cudaErrorSystemNotReady,
        cudaErrorNoKernelImageForDevice, cudaErrorInitializationError, cudaErrorInvalidDevice}) {
    SCOPED_TRACE(cudaGetErrorName(e));
    const ocean::Status s = d::to_status(e, "cudaGetDeviceCount");
    EXPECT_TRUE(d::means_no_device(e));
    EXPECT_EQ(s.code(), ocean::ErrorCode::unsupported);
    EXPECT_TRUE(s.message().starts_with("no CUDA device: ")) << s.message();
    EXPECT_NE(s.message().find(cudaGetErrorName(e)), std::string::npos) << s.message();
    EXPECT_TRUE(one_line(s.message()));
  }
  const ocean::Status driver = d::to_status(cudaErrorInsufficientDriver, "x");
  EXPECT_NE(driver.message().find("driver"), std::string::npos) << driver.message();
}

TEST(CudaErrors, FailuresOnAWorkingDeviceNameTheCall) {
  EXPECT_TRUE(d::to_status(cudaSuccess, "anything").ok());
  const ocean::Status oom = d::to_status(cudaErrorMemoryAllocation, "the simulation's buffers");
  EXPECT_EQ(oom.code(), ocean::ErrorCode::unsupported);
  EXPECT_NE(oom.message().find("the simulation's buffers"), std::string::npos);
  EXPECT_FALSE(oom.message().starts_with("no CUDA device"));
  for (const cudaError_t e : {cudaErrorIllegalAddress, cudaErrorLaunchFailure,
                              cudaErrorInvalidValue, cudaErrorLaunchTimeout}) {
    SCOPED_TRACE(cudaGetErrorName(e));
    EXPECT_FALSE(d::means_no_device(e));
    const ocean::Status s = d::to_status(e, "the finalize kernel");
    EXPECT_EQ(s.code(), ocean::ErrorCode::internal);
    EXPECT_TRUE(s.message().starts_with("CUDA error in the finalize kernel: ")) << s.message();
    EXPECT_NE(s.message().find(cudaGetErrorName(e)), std::string::npos);
    EXPECT_TRUE(one_line(s.message()));
  }
}

TEST(CudaErrors, CufftResultsAreNamed) {
  EXPECT_TRUE(d::to_status(CUFFT_SUCCESS, "x").ok());
  const ocean::Status alloc = d::to_status(CUFFT_ALLOC_FAILED, "cufftPlanMany");
  EXPECT_EQ(alloc.code(), ocean::ErrorCode::unsupported);
  EXPECT_NE(alloc.message().find("CUFFT_ALLOC_FAILED"), std::string::npos);
  const ocean::Status exec = d::to_status(CUFFT_EXEC_FAILED, "cufftExecC2C");
  EXPECT_EQ(exec.code(), ocean::ErrorCode::internal);
  EXPECT_EQ(exec.message(), "cuFFT error in cufftExecC2C: CUFFT_EXEC_FAILED");
  EXPECT_EQ(d::cufft_result_name(static_cast<cufftResult>(0x10 + 0x0f)), "cufftResult (unknown)");
}

// Without a usable device the factory, the device list and the backend table give the runtime's
// own error, mapped; with one (a GPU machine) the factory succeeds.
TEST(CudaDevices, NoDeviceIsOneClearError) {
  int count = 0;
  const cudaError_t e = cudaGetDeviceCount(&count);
  auto backend = ocean::cuda::make_cuda_backend();
  if (e == cudaSuccess && count > 0) {
    EXPECT_TRUE(backend.ok()) << backend.status().message();
    return;
  }
  ASSERT_FALSE(backend.ok());
  const ocean::Status expected =
      e == cudaSuccess ? ocean::unsupported("no CUDA device: the CUDA runtime reports no device")
                       : d::to_status(e, "cudaGetDeviceCount");
  EXPECT_EQ(backend.status().message(), expected.message());
  EXPECT_EQ(backend.status().code(), ocean::ErrorCode::unsupported);
  auto made = ocean::make_backend("cuda");
  ASSERT_FALSE(made.ok());
  EXPECT_EQ(made.status().message(), expected.message());
  for (const ocean::BackendInfo& b : ocean::list_backends()) {
    if (b.name == "cuda") {
      EXPECT_FALSE(b.available);
      EXPECT_EQ(b.detail, expected.message());
    }
  }
  EXPECT_NE(ocean::cuda::runtime_versions().find("runtime "), std::string::npos);
}

// cuFFT loads from the soname of the headers this build used, or says it is missing.
TEST(CudaDevices, CufftLoadsOrSaysWhy) {
  EXPECT_EQ(std::string(d::cufft_soname()), "libcufft.so." + std::to_string(CUFFT_VER_MAJOR));
  auto cufft = d::load_cufft();
  if (!cufft.ok()) {
    EXPECT_TRUE(cufft.status().message().starts_with("cuFFT (libcufft.so."))
        << cufft.status().message();
    return;
  }
  int version = 0;
  ASSERT_EQ(cufft.value()->get_version(&version), CUFFT_SUCCESS);
  EXPECT_EQ(version / 1000, CUFFT_VER_MAJOR);
}

ocean::SimulationConfig config_of(int n, int cascades, ocean::NormalMethod normals,
                                  ocean::FrameOutputs outputs) {
  ocean::SimulationConfig c;
  c.resolution = n;
  const std::vector<double> sizes = {1000.0, 233.0, 57.0, 13.0};
  c.cascade_patch_sizes_m.assign(sizes.begin(), sizes.begin() + cascades);
  c.normals = normals;
  c.outputs = outputs;
  return c;
}

// Every region aligned, inside the cascade's block, disjoint; the readback block holds exactly
// the arrays of a Frame (allocate_frame's sizes, in bytes), in Frame's order; foam's state is in
// the readback block when foam is read back and outside it otherwise.
TEST(CudaLayout, RegionsMatchTheFrameArrays) {
  using ocean::FrameOutputs;
  for (const int n : {16, 64, 512}) {
    for (const auto normals :
         {ocean::NormalMethod::central_difference, ocean::NormalMethod::analytic}) {
      for (const FrameOutputs want :
           {FrameOutputs::all(), FrameOutputs::textures(), FrameOutputs{.jacobian = false}}) {
        SCOPED_TRACE("N = " + std::to_string(n));
        const ocean::SimulationConfig config = config_of(n, 3, normals, want);
        auto made = d::make_layout(config);
        ASSERT_TRUE(made.ok()) << made.status().message();
        const d::Layout& l = made.value();
        EXPECT_EQ(l.planes, normals == ocean::NormalMethod::analytic ? 4 : 2);
        ocean::Frame frame;
        ocean::allocate_frame(config, frame);
        const ocean::CascadeFrame& f = frame.cascades[0];
        const std::size_t frame_bytes[d::kOutputs] = {
            4 * f.displacement.size(), 2 * f.displacement_half.size(),
            4 * f.normal.size(),       4 * f.jacobian.size(),
            4 * f.foam.size(),         4 * f.packed_mips.size()};
        std::size_t end = 0;
        for (int o = 0; o < d::kOutputs; ++o) {
          EXPECT_EQ(l.outputs[o].bytes, frame_bytes[o]) << "output " << o;
          EXPECT_EQ(l.outputs[o].offset % d::kAlignment, 0u);
          if (l.outputs[o].bytes == 0) continue;
          EXPECT_GE(l.outputs[o].offset, end) << "output " << o;  // in order, disjoint
          end = l.outputs[o].offset + l.outputs[o].bytes;
        }
        EXPECT_EQ(l.readback.bytes, end);
        std::vector<d::Region> regions = {l.spectrum,   l.phase_rate, l.twiddle,
                                          l.fft_planes, l.mip_work,   l.readback};
        if (!want.foam) regions.push_back(l.foam_state);
        std::sort(regions.begin(), regions.end(),
                  [](const d::Region& a, const d::Region& b) { return a.offset < b.offset; });
        for (std::size_t i = 0; i < regions.size(); ++i) {
          EXPECT_EQ(regions[i].offset % d::kAlignment, 0u);
          EXPECT_LE(regions[i].offset + regions[i].bytes,
                    i + 1 < regions.size() ? regions[i + 1].offset : l.cascade_bytes);
        }
        const std::size_t texels = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
        EXPECT_EQ(l.fft_planes.bytes, 8 * texels * static_cast<std::size_t>(l.planes));
        EXPECT_EQ(l.foam_state.bytes, 4 * texels);
        const std::size_t foam_in_readback = l.readback.offset + l.outputs[d::foam].offset;
        EXPECT_EQ(l.foam_state.offset == foam_in_readback, want.foam);
        EXPECT_EQ(l.device_bytes(), 3 * l.cascade_bytes);
        EXPECT_EQ(l.host_bytes(), 3 * l.readback.bytes);
      }
    }
  }
  EXPECT_EQ(d::make_layout(config_of(100, 1, ocean::NormalMethod::sobel, {})).status().code(),
            ocean::ErrorCode::invalid_argument);
}

// Levels 1 … log2 N, each written by exactly one pass; each pass's tile divides its source level.
TEST(CudaLayout, MipPassesWriteEveryLevelOnce) {
  for (int n = 16; n <= 2048; n *= 2) {
    SCOPED_TRACE("N = " + std::to_string(n));
    auto l = d::make_layout(config_of(n, 1, ocean::NormalMethod::central_difference, {}));
    ASSERT_TRUE(l.ok());
    int next = 1;
    ASSERT_FALSE(l.value().mip_passes.empty());
    EXPECT_EQ(l.value().mip_passes.front().source, 0);
    for (const d::MipPass& p : l.value().mip_passes) {
      EXPECT_EQ(p.source + 1, next);
      const int size = n >> p.source;
      EXPECT_EQ(size % p.tile, 0);
      EXPECT_LE(p.tile, 16);
      EXPECT_EQ(1 << p.levels, p.tile);
      next += p.levels;
    }
    EXPECT_EQ(next - 1, std::countr_zero(static_cast<unsigned>(n)));
  }
}

// A concurrent frame: upload on the origin, each cascade's chain on its own stream after the
// fork event, the origin's join after every cascade's event; every waited event was recorded by
// an earlier operation. A serial frame: one stream, no event. Readback only where asked.
TEST(CudaSchedule, CascadesRunOnTheirOwnStreamsBetweenForkAndJoin) {
  auto made = d::make_layout(config_of(512, 4, ocean::NormalMethod::central_difference, {}));
  ASSERT_TRUE(made.ok());
  const d::Layout& l = made.value();
  for (const bool readback : {true, false}) {
    const d::Schedule s = d::make_schedule(l, true, readback);
    EXPECT_EQ(s.streams, 5);
    std::set<int> recorded;
    std::vector<std::vector<d::Op::Kind>> chains(4);
    for (const d::Op& op : s.ops) {
      for (const int w : op.waits) EXPECT_TRUE(recorded.contains(w)) << "event " << w;
      if (op.records >= 0) {
        EXPECT_TRUE(recorded.insert(op.records).second);
      }
      EXPECT_LT(op.stream, s.streams);
      if (op.cascade >= 0) {
        EXPECT_EQ(op.stream, op.cascade + 1);
        chains[static_cast<std::size_t>(op.cascade)].push_back(op.kind);
      } else {
        EXPECT_EQ(op.stream, 0);
      }
    }
    EXPECT_EQ(static_cast<int>(recorded.size()), s.events);
    EXPECT_EQ(s.ops.front().kind, d::Op::upload_params);
    EXPECT_EQ(s.ops.back().kind, d::Op::join);
    EXPECT_EQ(s.ops.back().waits, (std::vector<int>{1, 2, 3, 4}));
    std::vector<d::Op::Kind> expected = {d::Op::evolve, d::Op::fft, d::Op::finalize};
    for (std::size_t p = 1; p < l.mip_passes.size(); ++p) expected.push_back(d::Op::mips);
    if (readback) expected.push_back(d::Op::readback);
    for (const auto& chain : chains) EXPECT_EQ(chain, expected);
  }
  // The shared frame (CudaBackend::share_inputs): each cascade's share copies after its last mip
  // pass (the RGBA8 chain is complete) and before its join event, on its own stream.
  const d::Schedule shared = d::make_schedule(l, true, true, true);
  std::vector<std::vector<d::Op::Kind>> chains(4);
  for (const d::Op& op : shared.ops) {
    if (op.cascade >= 0) chains[static_cast<std::size_t>(op.cascade)].push_back(op.kind);
    if (op.kind == d::Op::share) {
      EXPECT_EQ(op.stream, op.cascade + 1);
    }
  }
  std::vector<d::Op::Kind> expected = {d::Op::evolve, d::Op::fft, d::Op::finalize};
  for (std::size_t p = 1; p < l.mip_passes.size(); ++p) expected.push_back(d::Op::mips);
  expected.push_back(d::Op::share);
  expected.push_back(d::Op::readback);
  for (const auto& chain : chains) EXPECT_EQ(chain, expected);
  for (int c = 0; c < 4; ++c) {
    auto last = std::find_if(shared.ops.rbegin(), shared.ops.rend(),
                             [c](const d::Op& op) { return op.cascade == c; });
    EXPECT_EQ(last->records, 1 + c);  // the join event follows the share copies
  }
  const d::Schedule serial = d::make_schedule(l, false, true);
  EXPECT_EQ(serial.streams, 1);
  EXPECT_EQ(serial.events, 0);
  for (const d::Op& op : serial.ops) {
    EXPECT_EQ(op.stream, 0);
    EXPECT_TRUE(op.waits.empty());
    EXPECT_EQ(op.records, -1);
  }
}

}  // namespace
