// conformance_errors: the largest error of every output over the conformance cases
// (ocean/conformance.hpp), each case run at every size of 64…1024 texels, against the CPU
// backend's scalar reference pipeline, for
//   cpu      the CPU backend's fused SIMD pipeline;
//   vulkan   the Vulkan backend, where a device exists (lavapipe on a machine without a GPU);
//   gpu-trig the scalar pipeline with every evolved spectral coefficient z moved by 2ε·|z| in a
//            random direction, ε = 2^-21.19: the error a GPU's sin/cos of NVIDIA's documented
//            accuracy (CUDA C++ Programming Guide, __sinf on [−π, π]) can add to the evolution
//            h̃ = S'xy·cos φ + S'zw·sin φ (M.6.5). |δh̃| ≤ ε·(|S'xy| + |S'zw|), whose mean square
//            over the phases is at most 4ε² times that of h̃: the same as 2ε·|z|'s.
// The figures are those of docs/vulkan.md ("Conformance bounds"), from which the bounds of
// ocean/conformance.hpp are set. A program, not a test: it prints figures, it asserts nothing.
//   conformance_errors [--sizes 64,128,256,512,1024]
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "ocean/backends.hpp"
#include "ocean/backends/cpu.hpp"
#include "ocean/conformance.hpp"
#include "ocean/fft.hpp"

namespace {

namespace conformance = ocean::conformance;

// CUDA's __sinf bound on [−π, π] (2^-21.19; __cosf: 2^-21.41).
const double kTrigError = std::exp2(-21.19);

// SplitMix64's finaliser (Steele et al. 2014): a well-mixed 64-bit value of a counter.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// The radix-2 FFT of the scalar pipeline after the perturbation described at the top.
class PerturbedFft final : public ocean::cpu::ExternalFft {
 public:
  explicit PerturbedFft(ocean::fft::Plan2D plan)
      : plan_(std::move(plan)), runner_(ocean::make_serial_runner()) {}
  void inverse(std::span<const ocean::fft::SplitComplex> planes) override {
    const auto texels = static_cast<std::size_t>(plan_.size()) * plan_.size();
    for (const ocean::fft::SplitComplex& p : planes) {
      for (std::size_t i = 0; i < texels; ++i) {
        const double turn = static_cast<double>(mix(++counter_) >> 11) * 0x1p-53;
        const double r = 2.0 * kTrigError * std::hypot(p.re[i], p.im[i]);
        p.re[i] += static_cast<float>(r * std::cos(2.0 * std::numbers::pi * turn));
        p.im[i] += static_cast<float>(r * std::sin(2.0 * std::numbers::pi * turn));
      }
    }
    plan_.inverse(planes, *runner_, false);
  }

 private:
  ocean::fft::Plan2D plan_;
  std::unique_ptr<ocean::TaskRunner> runner_;
  std::uint64_t counter_ = 0;
};

struct Row {
  int size = 0;
  conformance::Errors errors;
};

void print_table(const char* title, const std::vector<Row>& rows) {
  std::printf("\n%s\n\n", title);
  std::printf(
      "| N | height/Hs | displacement/Hs | half (of bound) | normal | Jacobian | foam | "
      "packed LSB | packed share |\n|---|---|---|---|---|---|---|---|---|\n");
  conformance::Errors all;
  for (const Row& r : rows) all.merge(r.errors);
  std::vector<Row> with_all = rows;
  with_all.push_back({0, all});
  for (const Row& r : with_all) {
    const conformance::Errors& e = r.errors;
    const std::string n = r.size == 0 ? "all" : std::to_string(r.size);
    std::printf("| %s | %.3g | %.3g | %.3g | %.3g | %.3g | %.3g | %d | %.3g |\n", n.c_str(),
                e.height_rel_hs, e.displacement_rel_hs, e.displacement_half_rel_bound, e.normal,
                e.jacobian, e.foam, e.packed_lsb, e.packed_fraction);
  }
}

std::vector<int> parse_sizes(int argc, char** argv) {
  std::vector<int> sizes = {64, 128, 256, 512, 1024};
  if (argc == 3 && std::strcmp(argv[1], "--sizes") == 0) {
    sizes.clear();
    std::stringstream list(argv[2]);
    for (std::string item; std::getline(list, item, ',');) sizes.push_back(std::stoi(item));
  }
  return sizes;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<int> sizes = parse_sizes(argc, argv);
  std::unique_ptr<ocean::TaskRunner> runner = ocean::make_tbb_runner();
  bool vulkan = false;
  for (const ocean::BackendInfo& b : ocean::list_backends()) {
    if (b.name != "vulkan") continue;
    vulkan = b.available;
    std::printf("vulkan: %s\n", b.detail.c_str());
  }
  std::vector<Row> cpu_rows, vulkan_rows, trig_rows;
  for (const int n : sizes) {
    Row cpu{n, {}}, gpu{n, {}}, trig{n, {}};
    for (conformance::Case c : conformance::cases()) {
      c.resolution = n;
      std::fprintf(stderr, "%s at %d\n", c.name.c_str(), n);
      const auto run = [&](ocean::Backend& other, const conformance::Bounds& bounds, Row& row) {
        auto reference =
            ocean::cpu::make_cpu_backend({.pipeline = ocean::cpu::CpuPipeline::scalar_reference});
        auto frames = conformance::run_case(c, *reference, other, *runner, bounds);
        if (!frames.ok()) {
          std::fprintf(stderr, "conformance_errors: %s\n", frames.status().message().c_str());
          std::exit(1);
        }
        for (const conformance::FrameResult& f : frames.value()) row.errors.merge(f.errors);
      };
      run(*ocean::cpu::make_cpu_backend(), conformance::kCpuBounds, cpu);
      PerturbedFft fft(ocean::fft::Plan2D::make(n).value());
      run(*ocean::cpu::make_cpu_backend(
              {.pipeline = ocean::cpu::CpuPipeline::external_fft, .fft = &fft}),
          conformance::kDeviceBounds, trig);
      if (vulkan) run(*ocean::make_backend("vulkan").value(), conformance::kDeviceBounds, gpu);
    }
    cpu_rows.push_back(cpu);
    trig_rows.push_back(trig);
    if (vulkan) vulkan_rows.push_back(gpu);
  }
  print_table("cpu: fused SIMD pipeline vs scalar reference", cpu_rows);
  if (vulkan) print_table("vulkan vs scalar reference", vulkan_rows);
  print_table("gpu-trig: scalar pipeline with sin/cos error 2^-21.19 vs scalar reference",
              trig_rows);
  return 0;
}
