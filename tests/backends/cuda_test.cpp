// The CUDA backend's host-side logic, which needs no device: the runtime's and cuFFT's errors as
// one-line Status values (every way of having no device says "no CUDA device: "), the frame's
// memory layout (against the Frame arrays allocate_frame sizes: an identity), the mip passes
// (every level once) and the frame's schedule (each cascade on its own stream, every event
// recorded before it is waited for; the far field's noise map on a stream of its own, ordered
// after the fork and before the join and with no cascade operation), the map's place in both
// allocations, and its timings' overlap. On this machine class (CI: no GPU, no driver) the
// backend's factory must answer the mapped runtime error; where a device exists it must succeed.
#include "ocean/backends/cuda.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "cuda/cufft_library.hpp"
#include "cuda/errors.hpp"
#include "cuda/plan.hpp"
#include "ocean/backends.hpp"
#include "sim/far_noise.h"

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

// The far field's noise map's regions follow every cascade's block in the device allocation and
// every cascade's readback block in the pinned buffer, aligned and disjoint; the map's readback
// holds exactly Frame::far_noise's array; without a map both allocations are the cascades' alone.
TEST(CudaLayout, NoiseMapFollowsTheCascadesInBothAllocations) {
  for (const int m : {16, 100, 256}) {
    SCOPED_TRACE("M = " + std::to_string(m));
    ocean::SimulationConfig config =
        config_of(64, 3, ocean::NormalMethod::central_difference, ocean::FrameOutputs::all());
    const auto plain = d::make_layout(config);
    config.far_noise.resolution = m;
    const auto made = d::make_layout(config);
    ASSERT_TRUE(plain.ok() && made.ok()) << made.status().message();
    const d::Layout& l = made.value();
    EXPECT_EQ(plain.value().noise_resolution, 0);
    EXPECT_EQ(plain.value().device_bytes(), 3 * plain.value().cascade_bytes);
    EXPECT_EQ(plain.value().host_bytes(), 3 * plain.value().readback.bytes);
    EXPECT_EQ(l.noise_resolution, m);
    ocean::Frame frame;
    ocean::allocate_frame(config, frame);
    const std::size_t map_bytes = sizeof(float) * frame.far_noise.height_slope.size();
    EXPECT_EQ(map_bytes, std::size_t{12} * static_cast<std::size_t>(m * m));
    EXPECT_EQ(l.noise_map.bytes, map_bytes);
    EXPECT_EQ(l.noise_readback.bytes, map_bytes);
    EXPECT_EQ(l.noise_params_device.bytes, sizeof(ocean::noise::FarNoiseMapParams));
    EXPECT_EQ(l.noise_params_host.bytes, sizeof(ocean::noise::FarNoiseMapParams));
    // Device: [cascades' blocks][params][map]; host: [readback blocks][params][map readback].
    const std::pair<std::size_t, std::vector<d::Region>> allocations[] = {
        {l.device_bytes(), {{0, 3 * l.cascade_bytes}, l.noise_params_device, l.noise_map}},
        {l.host_bytes(), {{0, 3 * l.readback.bytes}, l.noise_params_host, l.noise_readback}}};
    for (const auto& [total, regions] : allocations) {
      for (std::size_t i = 0; i < regions.size(); ++i) {
        EXPECT_EQ(regions[i].offset % d::kAlignment, 0u) << "region " << i;
        EXPECT_GT(regions[i].bytes, 0u);
        EXPECT_LE(regions[i].offset + regions[i].bytes,
                  i + 1 < regions.size() ? regions[i + 1].offset : total)
            << "region " << i;
      }
      EXPECT_EQ(regions.back().offset + regions.back().bytes, total);
    }
    // The cascades' own layout does not move.
    EXPECT_EQ(l.cascade_bytes, plain.value().cascade_bytes);
    EXPECT_EQ(l.readback.bytes, plain.value().readback.bytes);
  }
}

// A bad FarNoiseConfig is refused with one line naming the field, as validate() refuses it for
// every backend, before anything touches a device.
TEST(CudaLayout, BadNoiseMapSettingsAreRefused) {
  const ocean::SimulationConfig base =
      config_of(64, 1, ocean::NormalMethod::central_difference, ocean::FrameOutputs::all());
  const auto with = [&](ocean::FarNoiseConfig f) {
    ocean::SimulationConfig c = base;
    c.far_noise = f;
    return d::make_layout(c).status();
  };
  for (const ocean::FarNoiseConfig& f :
       {ocean::FarNoiseConfig{.resolution = 8}, ocean::FarNoiseConfig{.resolution = 4097},
        ocean::FarNoiseConfig{.resolution = -16},
        ocean::FarNoiseConfig{.resolution = 64, .size_m = 0.5},
        ocean::FarNoiseConfig{.resolution = 64, .size_m = std::nan("")},
        ocean::FarNoiseConfig{.resolution = 64, .origin_m = {2e9, 0.0}},
        ocean::FarNoiseConfig{.resolution = 64, .origin_m = {0.0, -INFINITY}}}) {
    const ocean::Status s = with(f);
    EXPECT_EQ(s.code(), ocean::ErrorCode::invalid_argument) << s.message();
    EXPECT_TRUE(one_line(s.message()));
    EXPECT_NE(s.message().find("far_noise."), std::string::npos) << s.message();
  }
  EXPECT_TRUE(with({.resolution = 16}).ok());
  EXPECT_TRUE(with({.resolution = 4096, .origin_m = {-1e9, 1e9}, .size_m = 1e6}).ok());
}

// Which operations a schedule orders before which: a before b when b follows a on its stream, or
// b waits for an event recorded at or after a on a's stream (transitively). What a CUDA graph
// captured from the schedule keeps as edges; everything else may run concurrently.
std::vector<std::vector<bool>> happens_before(const d::Schedule& s) {
  const std::size_t n = s.ops.size();
  std::vector<std::vector<bool>> before(n, std::vector<bool>(n, false));
  std::vector<int> last_on_stream(static_cast<std::size_t>(s.streams), -1);
  std::vector<int> recorder(static_cast<std::size_t>(s.events), -1);
  for (std::size_t b = 0; b < n; ++b) {
    const d::Op& op = s.ops[b];
    std::vector<int> direct;
    if (const int prev = last_on_stream[static_cast<std::size_t>(op.stream)]; prev >= 0)
      direct.push_back(prev);
    for (const int w : op.waits) direct.push_back(recorder[static_cast<std::size_t>(w)]);
    for (const int a : direct) {
      if (a < 0) continue;
      before[static_cast<std::size_t>(a)][b] = true;
      for (std::size_t x = 0; x < n; ++x)
        if (before[x][static_cast<std::size_t>(a)]) before[x][b] = true;
    }
    last_on_stream[static_cast<std::size_t>(op.stream)] = static_cast<int>(b);
    if (op.records >= 0) recorder[static_cast<std::size_t>(op.records)] = static_cast<int>(b);
  }
  return before;
}

bool is_noise_op(const d::Op& op) {
  return op.kind == d::Op::noise_params || op.kind == d::Op::noise ||
         op.kind == d::Op::noise_readback;
}

// The map on a stream of its own (neither the origin's nor a cascade's), forked from the origin
// after the frame's first operation and joined by the final join; no cascade operation ordered
// before or after any of the map's (so they may overlap), its upload before its kernel before its
// readback; the parts alone keep the frame's stream and event numbers; a serial frame runs the map
// on the origin stream; a layout without a map gets no map operation.
TEST(CudaSchedule, NoiseMapRunsOnItsOwnStreamBetweenForkAndJoin) {
  ocean::SimulationConfig config =
      config_of(256, 4, ocean::NormalMethod::central_difference, ocean::FrameOutputs::all());
  const auto plain = d::make_layout(config);
  config.far_noise.resolution = 128;
  const auto made = d::make_layout(config);
  ASSERT_TRUE(plain.ok() && made.ok());
  const d::Layout& l = made.value();
  ASSERT_EQ(d::noise_stream(l), 5);
  ASSERT_EQ(d::noise_event(l), 5);
  for (const bool readback : {true, false}) {
    SCOPED_TRACE(readback ? "with readback" : "without readback");
    const d::Schedule s = d::make_schedule(l, true, readback);
    EXPECT_EQ(s.streams, 6);
    EXPECT_EQ(s.events, 6);
    const auto before = happens_before(s);
    std::vector<d::Op::Kind> noise_kinds;
    std::vector<std::size_t> noise_ops, cascade_ops;
    for (std::size_t i = 0; i < s.ops.size(); ++i) {
      const d::Op& op = s.ops[i];
      if (is_noise_op(op)) {
        EXPECT_EQ(op.stream, d::noise_stream(l));
        EXPECT_EQ(op.cascade, -1);
        noise_kinds.push_back(op.kind);
        noise_ops.push_back(i);
      } else if (op.cascade >= 0) {
        EXPECT_NE(op.stream, d::noise_stream(l));
        cascade_ops.push_back(i);
      }
    }
    std::vector<d::Op::Kind> expected = {d::Op::noise_params, d::Op::noise};
    if (readback) expected.push_back(d::Op::noise_readback);
    EXPECT_EQ(noise_kinds, expected);
    // Forked from the origin: the frame's first operation (the upload, which records the fork)
    // comes before the map's first; the join after its last; the map's own order.
    EXPECT_EQ(s.ops.front().kind, d::Op::upload_params);
    EXPECT_EQ(s.ops.front().records, 0);
    EXPECT_EQ(s.ops[noise_ops.front()].waits, (std::vector<int>{0}));
    EXPECT_EQ(s.ops[noise_ops.back()].records, d::noise_event(l));
    EXPECT_EQ(s.ops.back().kind, d::Op::join);
    for (std::size_t k = 0; k < noise_ops.size(); ++k) {
      EXPECT_TRUE(before[0][noise_ops[k]]);
      EXPECT_TRUE(before[noise_ops[k]][s.ops.size() - 1]) << "the join waits for the map";
      if (k > 0) {
        EXPECT_TRUE(before[noise_ops[k - 1]][noise_ops[k]]);
      }
      for (const std::size_t c : cascade_ops) {
        EXPECT_FALSE(before[noise_ops[k]][c]) << "op " << noise_ops[k] << " before " << c;
        EXPECT_FALSE(before[c][noise_ops[k]]) << "op " << c << " before " << noise_ops[k];
      }
    }
    for (const std::size_t c : cascade_ops) EXPECT_TRUE(before[c][s.ops.size() - 1]);
  }

  // The parts alone: the cascades without any map operation (the join waits for them only), the
  // map alone forked by a bare `fork` (no frame-parameter upload to time) and joined.
  const d::Schedule cascades = d::make_schedule(l, {.readback = false, .noise = false});
  EXPECT_EQ(cascades.streams, 6);
  EXPECT_TRUE(std::none_of(cascades.ops.begin(), cascades.ops.end(), is_noise_op));
  EXPECT_EQ(cascades.ops.back().waits, (std::vector<int>{1, 2, 3, 4}));
  const d::Schedule alone = d::make_schedule(l, {.readback = false, .cascades = false});
  ASSERT_EQ(alone.ops.size(), 4u);
  EXPECT_EQ(alone.ops[0].kind, d::Op::fork);
  EXPECT_EQ(alone.ops[0].records, 0);
  EXPECT_EQ(alone.ops[0].stream, 0);
  EXPECT_EQ(alone.ops[1].kind, d::Op::noise_params);
  EXPECT_EQ(alone.ops[1].waits, (std::vector<int>{0}));
  EXPECT_EQ(alone.ops[2].kind, d::Op::noise);
  EXPECT_EQ(alone.ops[3].kind, d::Op::join);
  EXPECT_EQ(alone.ops[3].waits, (std::vector<int>{d::noise_event(l)}));
  const auto alone_before = happens_before(alone);
  EXPECT_TRUE(alone_before[0][2] && alone_before[2][3]);

  // Serial: the map on the origin stream with everything else, no event.
  const d::Schedule serial = d::make_schedule(l, false, true);
  EXPECT_EQ(serial.streams, 1);
  EXPECT_EQ(serial.events, 0);
  EXPECT_EQ(std::count_if(serial.ops.begin(), serial.ops.end(), is_noise_op), 3);
  for (const d::Op& op : serial.ops) EXPECT_EQ(op.stream, 0);

  // No map in the layout: no map operation whatever the parts ask, the frame's streams as before.
  const d::Schedule without = d::make_schedule(plain.value(), true, true);
  EXPECT_EQ(without.streams, 5);
  EXPECT_TRUE(std::none_of(without.ops.begin(), without.ops.end(), is_noise_op));
}

// FrameTimings::noise_overlap is ocean bench --overlap's (t_c + t_n − t_both)/min(t_c, t_n): 1
// when the shorter part is hidden entirely, 0 when the parts run in turn, 0 without a map.
TEST(CudaTimings, NoiseOverlapIsTheBenchDefinition) {
  const auto overlap = [](double c, double n, double both) {
    return ocean::cuda::FrameTimings{.simulation_ms = both, .cascades_ms = c, .noise_ms = n}
        .noise_overlap();
  };
  EXPECT_DOUBLE_EQ(overlap(0.4, 0.1, 0.4), 1.0);
  EXPECT_DOUBLE_EQ(overlap(0.4, 0.1, 0.5), 0.0);
  EXPECT_DOUBLE_EQ(overlap(0.1, 0.4, 0.45), 0.5);
  EXPECT_DOUBLE_EQ(overlap(0.4, 0.1, 0.6), -1.0);
  EXPECT_DOUBLE_EQ(overlap(0.4, 0.0, 0.4), 0.0);
}

}  // namespace
