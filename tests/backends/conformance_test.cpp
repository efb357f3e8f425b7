// Backend conformance: one test body, run against every backend of the table (cpu always, vulkan
// where a device exists), compares each output with the CPU backend's scalar reference pipeline
// for the same configuration: for "cpu" that is its fused SIMD pipeline against the scalar one,
// for "vulkan" the compute shaders. The Vulkan backend runs with the Khronos validation layer and
// must produce zero messages. Without a Vulkan device its tests skip, or fail when
// OCEAN_REQUIRE_DEVICES=1 (tests/support/require_devices.hpp). Without a CUDA device the cuda
// tests skip whatever OCEAN_REQUIRE_DEVICES says (CI, which sets it, has no GPU); they fail
// instead only with OCEAN_REQUIRE_CUDA=1, which tools/gpu-check.sh sets on an NVIDIA machine.
//
// The bounds, the comparison and the case list are the library's (ocean/conformance.hpp), the
// same that `ocean validate` runs.
#include "ocean/conformance.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ocean/backends.hpp"
#include "ocean/backends/cpu.hpp"
#include "ocean/half.hpp"
#include "ocean/waves.hpp"
#include "support/require_devices.hpp"
#ifdef OCEAN_HAS_VULKAN
#include "ocean/backends/vulkan.hpp"
#endif

namespace {

// Validation on for every Vulkan context these tests create (read by vk::create_context).
const int kValidationOn = setenv("OCEAN_VK_VALIDATION", "1", 0);

// Whether OCEAN_REQUIRE_CUDA is set to a value other than "" and "0".
bool cuda_required() {
  const char* v = std::getenv("OCEAN_REQUIRE_CUDA");
  return v != nullptr && std::string_view(v) != "" && std::string_view(v) != "0";
}

// The parameter's backend: a name of the table, or "cuda_kernels", the CUDA backend on its own
// FFT kernels instead of cuFFT (make_backend("cuda") takes cuFFT where it loads).
ocean::Result<std::unique_ptr<ocean::Backend>> make(const std::string& param) {
  if (param == "cuda_kernels")
    return ocean::make_backend("cuda", {.fft = ocean::cuda::FftEngine::kernels});
  return ocean::make_backend(param);
}

// After a case: a GPU backend's own status (its failures do not reach the Frame), and no message
// from the Vulkan validation layer.
void expect_backend_ok(const ocean::Backend& b) {
  if (const ocean::DeviceCapabilities* gpu = ocean::capabilities(b)) {
    EXPECT_TRUE(gpu->status().ok()) << gpu->status().message();
  }
#ifdef OCEAN_HAS_VULKAN
  if (const auto* vk = dynamic_cast<const ocean::vk::VulkanBackend*>(&b)) {
    EXPECT_EQ(vk->context().validation_messages.load(), 0u)
        << vk->context().last_validation_message;
  }
#endif
}

class Conformance : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    ASSERT_EQ(kValidationOn, 0);
    const bool cuda = GetParam().starts_with("cuda");
    for (const ocean::BackendInfo& info : ocean::list_backends()) {
      if (info.name != (cuda ? "cuda" : GetParam()) || info.available) continue;
      if (cuda) {
        if (cuda_required()) GTEST_FAIL() << "OCEAN_REQUIRE_CUDA is set: " << info.detail;
        GTEST_SKIP() << "backend 'cuda' unavailable (" << info.detail
                     << "); skipped even under OCEAN_REQUIRE_DEVICES, since CI has no GPU: "
                        "tools/gpu-check.sh runs it with OCEAN_REQUIRE_CUDA=1 on an NVIDIA "
                        "machine";
      }
      OCEAN_SKIP_OR_FAIL("backend '" + GetParam() + "' unavailable: " + info.detail);
    }
  }
};

TEST_P(Conformance, EveryOutputMatchesTheCpuReference) {
  std::unique_ptr<ocean::TaskRunner> runner = ocean::make_serial_runner();
  const ocean::conformance::Bounds& bounds = ocean::conformance::bounds_for(GetParam());
  ocean::conformance::Errors worst;
  for (const ocean::conformance::Case& c : ocean::conformance::cases()) {
    SCOPED_TRACE(c.name);
    auto reference =
        ocean::cpu::make_cpu_backend({.pipeline = ocean::cpu::CpuPipeline::scalar_reference});
    auto backend = make(GetParam());
    ASSERT_TRUE(backend.ok()) << backend.status().message();
    const auto frames =
        ocean::conformance::run_case(c, *reference, *backend.value(), *runner, bounds);
    ASSERT_TRUE(frames.ok()) << frames.status().message();
    ASSERT_EQ(frames.value().size(), c.times_s.size());
    for (const ocean::conformance::FrameResult& f : frames.value()) {
      const double t = f.time_s;
      const ocean::conformance::Errors& e = f.errors;
      std::printf(
          "[%s] %s t=%.3f: height %.3g Hs, displacement %.3g Hs, half %.3g of bound, "
          "normal %.3g, jacobian %.3g, foam %.3g, packed %d LSB on %.3g%% of texels\n",
          GetParam().c_str(), c.name.c_str(), t, e.height_rel_hs, e.displacement_rel_hs,
          e.displacement_half_rel_bound, e.normal, e.jacobian, e.foam, e.packed_lsb,
          100.0 * e.packed_fraction);
      EXPECT_LE(e.height_rel_hs, bounds.height_rel_hs) << "t = " << t;
      EXPECT_LE(e.displacement_rel_hs, bounds.displacement_rel_hs) << "t = " << t;
      EXPECT_LE(e.displacement_half_rel_bound, bounds.displacement_half_rel_bound) << "t = " << t;
      EXPECT_LE(e.normal, bounds.normal) << "t = " << t;
      EXPECT_LE(e.jacobian, bounds.jacobian) << "t = " << t;
      EXPECT_LE(e.foam, bounds.foam) << "t = " << t;
      EXPECT_LE(e.packed_lsb, bounds.packed_lsb) << "t = " << t;
      EXPECT_LE(e.packed_fraction, bounds.packed_fraction) << "t = " << t;
      EXPECT_TRUE(e.pass(bounds)) << "t = " << t;
      EXPECT_EQ(f.other_time_s, t);
      worst.merge(e);
    }
#ifdef OCEAN_HAS_VULKAN
    if (auto* vk = dynamic_cast<ocean::vk::VulkanBackend*>(backend.value().get())) {
      EXPECT_TRUE(vk->context().validation);
    }
#endif
    expect_backend_ok(*backend.value());
  }
  // The two sides are different computations (other FFT orders, other sin/cos): comparing a
  // pipeline with itself would give zero everywhere and prove nothing.
  EXPECT_GT(worst.height_rel_hs, 0.0);
  EXPECT_GT(worst.displacement_rel_hs, 0.0);
  EXPECT_GT(worst.normal, 0.0);
  EXPECT_GT(worst.jacobian, 0.0);
}

// Optional arrays a configuration does not request (FrameOutputs) stay empty, and leaving them
// out changes nothing else: every other array has the bits of the run with every output, over
// consecutive frames (foam accumulates in the backend's state either way), for each normal
// method. The Vulkan backend neither copies nor maps them (no validation message).
TEST_P(Conformance, OptionalOutputsAreLeftOutAndTheRestUnchanged) {
  std::unique_ptr<ocean::TaskRunner> runner = ocean::make_serial_runner();
  const auto same = [](const auto& a, const auto& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](auto x, auto y) {
             return std::memcmp(&x, &y, sizeof(x)) == 0;
           });
  };
  for (const ocean::NormalMethod normals :
       {ocean::NormalMethod::central_difference, ocean::NormalMethod::sobel,
        ocean::NormalMethod::analytic}) {
    SCOPED_TRACE(std::string(ocean::to_string(normals)));
    ocean::SimulationConfig config;
    config.resolution = 32;
    config.cascade_patch_sizes_m = {300.0, 71.0, 17.0};
    config.normals = normals;
    config.foam.source = ocean::FoamSource::ramp;
    config.foam.jacobian_start = 1.0;  // foam on part of the patch: accumulation is exercised
    for (const ocean::FrameOutputs want :
         {ocean::FrameOutputs::textures(), ocean::FrameOutputs{.normal = false, .foam = false},
          ocean::FrameOutputs{.jacobian = false}}) {
      ocean::SimulationConfig lean = config;
      lean.outputs = want;
      auto full = make(GetParam());
      auto part = make(GetParam());
      ASSERT_TRUE(full.ok() && part.ok());
      ASSERT_TRUE(full.value()->configure(config, *runner).ok());
      ASSERT_TRUE(part.value()->configure(lean, *runner).ok());
      ocean::Frame a, b;
      full.value()->allocate(a);
      part.value()->allocate(b);
      const std::size_t texels = 32 * 32;
      for (const ocean::CascadeFrame& c : b.cascades) {
        EXPECT_EQ(c.normal.size(), want.normal ? 3 * texels : 0);
        EXPECT_EQ(c.jacobian.size(), want.jacobian ? texels : 0);
        EXPECT_EQ(c.foam.size(), want.foam ? texels : 0);
      }
      double foamy = 0.0;
      for (const double t : {10.0, 10.1, 10.2, 10.3}) {
        full.value()->step(t, a);
        part.value()->step(t, b);
        for (std::size_t c = 0; c < a.cascades.size(); ++c) {
          const ocean::CascadeFrame& x = a.cascades[c];
          const ocean::CascadeFrame& y = b.cascades[c];
          EXPECT_TRUE(same(x.displacement, y.displacement)) << "cascade " << c << ", t = " << t;
          EXPECT_TRUE(same(x.displacement_half, y.displacement_half)) << "cascade " << c;
          EXPECT_TRUE(same(x.packed_mips, y.packed_mips)) << "cascade " << c << ", t = " << t;
          EXPECT_TRUE(!want.normal || same(x.normal, y.normal)) << "cascade " << c;
          EXPECT_TRUE(!want.jacobian || same(x.jacobian, y.jacobian)) << "cascade " << c;
          EXPECT_TRUE(!want.foam || same(x.foam, y.foam)) << "cascade " << c;
          for (const float f : x.foam) foamy += f;
        }
      }
      EXPECT_GT(foamy, 0.0) << "no foam: the packed maps' blue channel was not exercised";
      expect_backend_ok(*part.value());
    }
  }
}

// The far field's noise map (docs/rendering.md R.13a) against the CPU backend's, texel by texel,
// at the start, after a second and three days in (the octaves thousands of cells away), within
// kFarNoiseDeviceBounds; and the map changes nothing else: the cascades' arrays keep the bits of
// the same backend without it (on CUDA: the map on its own stream in the frame's graph).
TEST_P(Conformance, FarNoiseMapMatchesTheCpuMapAndChangesNothingElse) {
  std::unique_ptr<ocean::TaskRunner> runner = ocean::make_serial_runner();
  ocean::SimulationConfig config;
  config.resolution = 32;
  config.cascade_patch_sizes_m = {300.0, 71.0};
  ocean::SimulationConfig plain = config;
  config.far_noise = {.resolution = 96, .origin_m = {-2000.0, 1000.0}, .size_m = 4000.0};
  auto reference = ocean::cpu::make_cpu_backend();
  auto backend = make(GetParam());
  auto without = make(GetParam());
  ASSERT_TRUE(backend.ok() && without.ok());
  ASSERT_TRUE(reference->configure(config, *runner).ok());
  ASSERT_TRUE(backend.value()->configure(config, *runner).ok());
  ASSERT_TRUE(without.value()->configure(plain, *runner).ok());
  ocean::Frame r, b, w;
  reference->allocate(r);
  backend.value()->allocate(b);
  without.value()->allocate(w);
  double worst_h = 0.0, worst_s = 0.0;
  for (const double t : {0.0, 1.0, 259200.0}) {
    reference->step(t, r);
    backend.value()->step(t, b);
    without.value()->step(t, w);
    const auto& x = r.far_noise.height_slope;
    const auto& y = b.far_noise.height_slope;
    ASSERT_EQ(x.size(), y.size());
    double h2 = 0.0, s2 = 0.0, dh = 0.0, ds = 0.0;
    for (std::size_t i = 0; i < x.size(); i += 3) {
      h2 += double(x[i]) * x[i];
      s2 += 0.5 * (double(x[i + 1]) * x[i + 1] + double(x[i + 2]) * x[i + 2]);
      dh = std::max(dh, double(std::abs(x[i] - y[i])));
      ds = std::max(
          {ds, double(std::abs(x[i + 1] - y[i + 1])), double(std::abs(x[i + 2] - y[i + 2]))});
    }
    const double texels = static_cast<double>(x.size() / 3);
    ASSERT_GT(h2, 0.0);
    worst_h = std::max(worst_h, dh / std::sqrt(h2 / texels));
    worst_s = std::max(worst_s, ds / std::sqrt(s2 / texels));
    for (std::size_t c = 0; c < b.cascades.size(); ++c) {
      const ocean::CascadeFrame &p = b.cascades[c], &q = w.cascades[c];
      EXPECT_EQ(std::memcmp(p.displacement.data(), q.displacement.data(),
                            p.displacement.size() * sizeof(float)),
                0)
          << "cascade " << c << ", t = " << t;
      EXPECT_EQ(std::memcmp(p.packed_mips.data(), q.packed_mips.data(),
                            p.packed_mips.size() * sizeof(std::uint32_t)),
                0)
          << "cascade " << c << ", t = " << t;
    }
  }
  std::printf("[%s] far-field noise map: height %.3g of its rms, slope %.3g of its rms\n",
              GetParam().c_str(), worst_h, worst_s);
  EXPECT_LE(worst_h, ocean::conformance::kFarNoiseDeviceBounds.height_rel);
  EXPECT_LE(worst_s, ocean::conformance::kFarNoiseDeviceBounds.slope_rel);
  expect_backend_ok(*backend.value());
}

// The local surface (docs/math.md M.7.9) is the cascades sampled and summed with the layer, so
// the backend's errors reach it through the sum: |ΔD| ≤ C·ε_D·Hs (plus the float rounding of the
// stored sum), gradients within e_g = 2·|ΔD|max/Δ, |ΔJ| ≤ e_g·(2 + 2·Σ|∂D|) + 2·e_g², and the
// first frame's foam, a ramp of J, within |ΔJ|/(J_start − J_full).
TEST_P(Conformance, LocalSurfaceConformsAsItsCascadesDo) {
  const ocean::conformance::Bounds& bounds = ocean::conformance::bounds_for(GetParam());
  ocean::SimulationConfig config;
  config.resolution = 64;
  config.cascade_patch_sizes_m = {300.0, 71.0};
  config.sea.wind_sea.spectrum.wind_speed_mps = 14.0;
  config.choppiness = 1.5;
  config.foam.source = ocean::FoamSource::ramp;  // the foam bound below is the ramp's
  ocean::waves::LayerParams params;
  params.area = {.origin_m = {-40.0, -40.0}, .size_m = 80.0, .resolution = 64};
  params.wakes.push_back({.x_m = 20.0,
                          .heading_deg = 200.0,
                          .speed_mps = 4.0,
                          .hull_length_m = 10.0,
                          .peak_height_m = 0.8});
  auto layer = ocean::waves::LocalLayer::make(params);
  ASSERT_TRUE(layer.ok()) << layer.status().message();
  const std::shared_ptr<const ocean::waves::LocalLayer> shared = std::move(layer).value();
  std::shared_ptr<ocean::TaskRunner> runner = ocean::make_serial_runner();
  auto backend = make(GetParam());
  ASSERT_TRUE(backend.ok()) << backend.status().message();
  auto reference = ocean::Simulator::make(
      config, ocean::cpu::make_cpu_backend({.pipeline = ocean::cpu::CpuPipeline::scalar_reference}),
      runner);
  auto tested = ocean::Simulator::make(config, std::move(backend).value(), runner);
  ASSERT_TRUE(reference.ok() && tested.ok());
  for (auto* sim : {reference.value().get(), tested.value().get()}) {
    sim->set_local_layer(shared);
    sim->step(2.0);
  }
  const ocean::LocalSurfaceFrame& a = reference.value()->frame().local;
  const ocean::LocalSurfaceFrame& b = tested.value()->frame().local;
  ASSERT_EQ(a.displacement.size(), b.displacement.size());
  double variance = 0.0, largest = 0.0;
  for (const ocean::CascadeFrame& c : reference.value()->frame().cascades) {
    double sum = 0.0;
    for (std::size_t i = 1; i < c.displacement.size(); i += 3)
      sum += c.displacement[i] * c.displacement[i];
    variance += sum / static_cast<double>(c.displacement.size() / 3);
  }
  for (const float d : a.displacement)
    largest = std::max(largest, std::abs(static_cast<double>(d)));
  const double hs = 4.0 * std::sqrt(variance);
  const double e_d = 2.0 * bounds.displacement_rel_hs * hs + 0x1p-23 * largest;
  double worst_d = 0.0;
  for (std::size_t i = 0; i < a.displacement.size(); ++i)
    worst_d =
        std::max(worst_d, std::abs(static_cast<double>(a.displacement[i]) - b.displacement[i]));
  EXPECT_LE(worst_d, e_d);
  EXPECT_GT(worst_d, 0.0);  // two different computations: equal bits would prove nothing
  const int n = a.resolution;
  const double e_g = 2.0 * e_d / (a.size_m / n);
  const ocean::FoamParams& foam = config.foam;
  double worst_j = 0.0, worst_j_share = 0.0;
  for (int row = 0; row < n; ++row) {
    for (int col = 0; col < n; ++col) {
      const auto at = [&](int c, int r, int k) {
        c = std::clamp(c, 0, n - 1), r = std::clamp(r, 0, n - 1);
        return static_cast<double>(
            a.displacement[3 * static_cast<std::size_t>(r * n + c) + static_cast<std::size_t>(k)]);
      };
      const double spacing = a.size_m / n;
      double gradients = 0.0;
      for (const int k : {0, 2}) {
        gradients += std::abs(at(col + 1, row, k) - at(col - 1, row, k)) / spacing;
        gradients += std::abs(at(col, row + 1, k) - at(col, row - 1, k)) / spacing;
      }
      const auto i = static_cast<std::size_t>(row * n + col);
      const double e_j =
          e_g * (2.0 + 2.0 * gradients) + 2.0 * e_g * e_g + 1e-6 * (1.0 + std::abs(a.jacobian[i]));
      const double dj = std::abs(a.jacobian[i] - b.jacobian[i]);
      worst_j = std::max(worst_j, dj);
      worst_j_share = std::max(worst_j_share, dj / e_j);
      ASSERT_LE(dj, e_j) << col << ", " << row;
      ASSERT_LE(std::abs(a.foam[i] - b.foam[i]),
                e_j / (foam.jacobian_start - foam.jacobian_full) + 1e-6)
          << col << ", " << row;
    }
  }
  std::printf(
      "[%s] local surface: |dD| %.3g m (%.3g of its bound), |dJ| %.3g (%.3g of its bound)\n",
      GetParam().c_str(), worst_d, worst_d / e_d, worst_j, worst_j_share);
  expect_backend_ok(tested.value()->backend());
}

#ifdef OCEAN_HAS_VULKAN
// The GPU images the renderer samples hold the same values as the read-back arrays: displacement
// RGBA16F within one half ulp, every mip of the RGBA8 map within 1 LSB (the unorm conversion of
// imageStore may round differently from pack_rgba8). Stage timings come from timestamps.
TEST(VulkanImages, HoldTheReadBackOutputs) {
  auto made = ocean::vk::make_vulkan_backend({.validation = true});
  if (!made.ok()) OCEAN_SKIP_OR_FAIL(made.status().message());
  ocean::vk::VulkanBackend& backend = *made.value();
  const ocean::vk::Context& ctx = backend.context();
  std::unique_ptr<ocean::TaskRunner> runner = ocean::make_serial_runner();
  ocean::SimulationConfig config;
  config.resolution = 64;
  config.cascade_patch_sizes_m = {300.0, 70.0};
  ASSERT_TRUE(backend.configure(config, *runner).ok());
  ocean::Frame frame;
  backend.allocate(frame);
  backend.step(1.0, frame);
  ASSERT_TRUE(backend.status().ok()) << backend.status().message();
  if (ctx.timestamps) {
    EXPECT_GT(backend.timings().total_ms, 0.0);
  }

  const ocean::vk::SimulationImages images = backend.images();
  ASSERT_EQ(images.layers, 2u);
  ASSERT_EQ(images.mips, 7u);
  const std::size_t n = 64, chain = ocean::mip_chain_texels(64);
  const VkDeviceSize disp_bytes = 2 * n * n * 8, nfs_bytes = 2 * chain * 4;
  auto buffer =
      ocean::vk::create_buffer(ctx, disp_bytes + nfs_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                               ocean::vk::MemoryUse::readback);
  auto cmds = ocean::vk::create_commands(ctx);
  ASSERT_TRUE(buffer.ok() && cmds.ok());
  const ocean::Status copied = ocean::vk::run_once(ctx, cmds.value(), [&](VkCommandBuffer cmd) {
    const VkBufferImageCopy disp{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 2},
                                 .imageExtent = {64, 64, 1}};
    vkCmdCopyImageToBuffer(cmd, images.displacement, VK_IMAGE_LAYOUT_GENERAL, buffer.value().buffer,
                           1, &disp);
    VkDeviceSize offset = disp_bytes;
    for (std::uint32_t layer = 0; layer < 2; ++layer) {
      for (std::uint32_t m = 0; m < images.mips; ++m) {
        const std::uint32_t size = 64u >> m;
        const VkBufferImageCopy nfs{.bufferOffset = offset,
                                    .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, m, layer, 1},
                                    .imageExtent = {size, size, 1}};
        vkCmdCopyImageToBuffer(cmd, images.normal_foam, VK_IMAGE_LAYOUT_GENERAL,
                               buffer.value().buffer, 1, &nfs);
        offset += VkDeviceSize{size} * size * 4;
      }
    }
    ocean::vk::barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT);
  });
  ASSERT_TRUE(copied.ok()) << copied.message();
  const auto* halves = static_cast<const std::uint16_t*>(buffer.value().mapped);
  const auto* texels = reinterpret_cast<const std::uint32_t*>(
      static_cast<const char*>(buffer.value().mapped) + disp_bytes);
  int disp_ulps = 0, lsb = 0;
  for (std::size_t c = 0; c < 2; ++c) {
    const ocean::CascadeFrame& f = frame.cascades[c];
    for (std::size_t i = 0; i < 4 * n * n; ++i) {
      // Half bits as signed magnitudes: neighbours differ by one.
      const auto ordinal = [](std::uint16_t h) {
        return (h & 0x8000u) != 0 ? -static_cast<int>(h & 0x7fffu) : static_cast<int>(h);
      };
      disp_ulps = std::max(disp_ulps, std::abs(ordinal(f.displacement_half[i]) -
                                               ordinal(halves[c * 4 * n * n + i])));
    }
    for (std::size_t i = 0; i < chain; ++i) {
      for (int shift = 0; shift < 32; shift += 8) {
        const int a = static_cast<int>((f.packed_mips[i] >> shift) & 0xffu);
        const int b = static_cast<int>((texels[c * chain + i] >> shift) & 0xffu);
        lsb = std::max(lsb, std::abs(a - b));
      }
    }
  }
  EXPECT_LE(disp_ulps, 1);
  EXPECT_LE(lsb, 1);
  ocean::vk::destroy_buffer(ctx, buffer.value());
  ocean::vk::destroy_commands(ctx, cmds.value());
  EXPECT_EQ(ctx.validation_messages.load(), 0u) << ctx.last_validation_message;
}

TEST(VulkanBenchmark, ReportsEveryStage) {
  ocean::SimulationConfig config;
  config.resolution = 64;
  auto t = ocean::vk::benchmark(config, 3, {.validation = true});
  if (!t.ok()) OCEAN_SKIP_OR_FAIL(t.status().message());
  const ocean::vk::StageTimings& s = t.value();
  EXPECT_GT(s.total_ms, 0.0);
  for (const double ms :
       {s.evolve_fft_rows_ms, s.fft_columns_ms, s.finalize_ms, s.mips_ms, s.readback_ms}) {
    EXPECT_TRUE(std::isfinite(ms));
    EXPECT_GE(ms, 0.0);
  }
  // The stages are differences of consecutive timestamps and the total the first to the last:
  // their sum is the total but for rounding (an identity, not a timing).
  const double sum =
      s.evolve_fft_rows_ms + s.fft_columns_ms + s.finalize_ms + s.mips_ms + s.readback_ms;
  EXPECT_NEAR(sum, s.total_ms, 1e-9 * s.total_ms);
}
#endif

// The bounds catch a small real error: one texel off by ten times the largest difference
// measured between any two pipelines at 64…1024 texels (docs/vulkan.md, "Conformance bounds":
// 1.3e-6·Hs of height, 2.1e-6 of a normal component, 1.7e-6 of J, 3.8e-6 of foam) fails both
// kinds of bounds, and so does a packed channel off by 2 LSB; the frame itself passes.
// The velocity output (M.7.11) is computed on the CPU only: a GPU backend that exists here
// refuses it at configure, naming it, rather than publishing zeros; one that does not exist says
// so as always. (Here, not in the simulator tests: making a Vulkan device is this binary's.)
TEST(VelocityOutput, IsRefusedByTheBackendsThatDoNotComputeIt) {
  ocean::SimulationConfig config;
  config.resolution = 32;
  config.outputs.velocity = true;
  for (const char* name : {"vulkan", "cuda"}) {
    const bool exists = ocean::make_backend(name).ok();
    const auto sim = ocean::make_simulator(config, name);
    ASSERT_FALSE(sim.ok()) << name;
    EXPECT_EQ(sim.status().code(), ocean::ErrorCode::unsupported) << name;
    if (exists) {
      EXPECT_NE(sim.status().message().find("does not compute the velocity"), std::string::npos)
          << sim.status().message();
    }
  }
  EXPECT_TRUE(ocean::make_simulator(config, "cpu").ok());
}

TEST(ConformanceBounds, CatchAnErrorTenTimesTheLargestMeasured) {
  namespace conformance = ocean::conformance;
  const conformance::Case& c = conformance::cases().front();
  auto backend =
      ocean::cpu::make_cpu_backend({.pipeline = ocean::cpu::CpuPipeline::scalar_reference});
  std::unique_ptr<ocean::TaskRunner> runner = ocean::make_serial_runner();
  ASSERT_TRUE(backend->configure(conformance::make_config(c), *runner).ok());
  ocean::Frame ref;
  backend->allocate(ref);
  backend->step(c.times_s.front(), ref);
  const double hs = conformance::significant_height(ref);
  ASSERT_GT(hs, 0.0);
  const std::size_t texel = 1000;  // in the middle cascade
  const auto nudge = [](float& v, double by) { v += static_cast<float>(v > 0.5f ? -by : by); };
  const std::vector<std::pair<std::string, std::function<void(ocean::CascadeFrame&)>>> errors = {
      {"height",
       [&](ocean::CascadeFrame& f) { nudge(f.displacement[3 * texel + 1], 1.3e-5 * hs); }},
      {"normal", [&](ocean::CascadeFrame& f) { nudge(f.normal[3 * texel], 2.1e-5); }},
      {"jacobian", [&](ocean::CascadeFrame& f) { nudge(f.jacobian[texel], 1.7e-5); }},
      {"foam", [&](ocean::CascadeFrame& f) { nudge(f.foam[texel], 3.8e-5); }},
      {"packed", [&](ocean::CascadeFrame& f) { f.packed_mips[texel] ^= 2u; }},
  };
  for (const conformance::Bounds* bounds :
       {&conformance::kCpuBounds, &conformance::kDeviceBounds}) {
    EXPECT_TRUE(conformance::compare(ref, ref, *bounds).pass(*bounds));
    for (const auto& [what, apply] : errors) {
      ocean::Frame got = ref;
      apply(got.cascades[1]);
      EXPECT_FALSE(conformance::compare(ref, got, *bounds).pass(*bounds)) << what;
    }
  }
  EXPECT_EQ(&conformance::bounds_for("cpu"), &conformance::kCpuBounds);
  EXPECT_EQ(&conformance::bounds_for("vulkan"), &conformance::kDeviceBounds);
  EXPECT_EQ(&conformance::bounds_for("cuda"), &conformance::kDeviceBounds);
}

INSTANTIATE_TEST_SUITE_P(Backends, Conformance,
                         ::testing::Values("cpu", "vulkan", "cuda", "cuda_kernels"),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           return param.param;
                         });

}  // namespace
