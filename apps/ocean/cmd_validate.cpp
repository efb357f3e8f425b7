// `ocean validate`: runs the backend conformance cases on this machine's device and prints each
// output's error against the CPU reference backend; exit 1 when a bound is exceeded.
//
// Bounds as tests/backends/conformance_test.cpp and src/backends/vulkan/README.md: displacement
// ≤ 1e-4·Hs (FP32), half4 ≤ one half ulp + 1e-4·Hs, normal/Jacobian/foam ≤ 1e-4, packed RGBA8
// within 1 LSB.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"
#include "ocean/backends.hpp"
#include "ocean/half.hpp"
#ifdef OCEAN_HAS_VULKAN
#include "ocean/vk/simulation.hpp"
#endif

namespace ocean::cli {

namespace {

struct ValidateOptions {
  std::string backend = "vulkan";
  bool json = false;
};

struct Case {
  const char* name;
  int resolution;
  std::vector<double> patches_m;
  SpectrumModel model;
  NormalMethod normals;
  std::vector<double> times_s;
};

struct Errors {
  double displacement_rel_hs = 0, half_rel_bound = 0, normal = 0, jacobian = 0, foam = 0;
  double packed_lsb = 0;
  void merge(const Errors& e) {
    displacement_rel_hs = std::max(displacement_rel_hs, e.displacement_rel_hs);
    half_rel_bound = std::max(half_rel_bound, e.half_rel_bound);
    normal = std::max(normal, e.normal);
    jacobian = std::max(jacobian, e.jacobian);
    foam = std::max(foam, e.foam);
    packed_lsb = std::max(packed_lsb, e.packed_lsb);
  }
  [[nodiscard]] bool pass() const {
    return displacement_rel_hs <= 1e-4 && half_rel_bound <= 1.0 && normal <= 1e-4 &&
           jacobian <= 1e-4 && foam <= 1e-4 && packed_lsb <= 1.0;
  }
  [[nodiscard]] nlohmann::ordered_json json() const {
    return {{"displacement_rel_hs", displacement_rel_hs},
            {"displacement_half_rel_bound", half_rel_bound},
            {"normal", normal},
            {"jacobian", jacobian},
            {"foam", foam},
            {"packed_lsb", packed_lsb}};
  }
};

SimulationConfig make_config(const Case& c) {
  SimulationConfig config;
  config.resolution = c.resolution;
  config.cascade_patch_sizes_m = c.patches_m;
  config.normals = c.normals;
  config.choppiness = 1.2;
  FrequencySpectrumParams& s = config.sea.wind_sea.spectrum;
  s.model = c.model;
  s.wind_speed_mps = 14.0;
  s.fetch_m = c.model == SpectrumModel::phillips ? kUnset : 80e3;
  if (c.model == SpectrumModel::tma) s.depth_m = config.sea.dispersion.depth_m = 20.0;
  return config;
}

double max_diff(std::span<const float> a, std::span<const float> b) {
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    m = std::max(m, std::abs(static_cast<double>(a[i]) - static_cast<double>(b[i])));
  return m;
}

Errors compare(const Frame& ref, const Frame& got) {
  double var = 0.0;
  for (const CascadeFrame& c : ref.cascades) {
    double sum = 0.0, sum2 = 0.0;
    for (std::size_t i = 0; i < c.jacobian.size(); ++i) {
      sum += c.displacement[3 * i + 1];
      sum2 += static_cast<double>(c.displacement[3 * i + 1]) * c.displacement[3 * i + 1];
    }
    const double n = static_cast<double>(c.jacobian.size());
    var += sum2 / n - (sum / n) * (sum / n);
  }
  const double hs = 4.0 * std::sqrt(var);
  Errors e;
  for (std::size_t c = 0; c < ref.cascades.size(); ++c) {
    const CascadeFrame& r = ref.cascades[c];
    const CascadeFrame& g = got.cascades[c];
    e.displacement_rel_hs =
        std::max(e.displacement_rel_hs, max_diff(r.displacement, g.displacement) / hs);
    e.normal = std::max(e.normal, max_diff(r.normal, g.normal));
    e.jacobian = std::max(e.jacobian, max_diff(r.jacobian, g.jacobian));
    e.foam = std::max(e.foam, max_diff(r.foam, g.foam));
    for (std::size_t i = 0; i < r.displacement_half.size(); ++i) {
      const double a = half_to_float(r.displacement_half[i]);
      const double b = half_to_float(g.displacement_half[i]);
      e.half_rel_bound =
          std::max(e.half_rel_bound, std::abs(a - b) / (std::ldexp(std::abs(a), -10) + 1e-4 * hs));
    }
    for (std::size_t i = 0; i < r.packed_mips.size(); ++i) {
      for (int shift = 0; shift < 32; shift += 8) {
        const int a = static_cast<int>((r.packed_mips[i] >> shift) & 0xffu);
        const int b = static_cast<int>((g.packed_mips[i] >> shift) & 0xffu);
        e.packed_lsb = std::max(e.packed_lsb, static_cast<double>(std::abs(a - b)));
      }
    }
  }
  return e;
}

int run_validate(const ValidateOptions& o) {
  using M = SpectrumModel;
  using N = NormalMethod;
  const std::vector<Case> cases = {
      {"64_phillips_3cascades_central",
       64,
       {800.0, 190.0, 47.0},
       M::phillips,
       N::central_difference,
       {0.0, 0.5}},
      {"256_jonswap_2cascades_analytic",
       256,
       {1000.0, 233.0},
       M::jonswap,
       N::analytic,
       {3 * 86400.0, 3 * 86400.0 + 1.0 / 30}},
      {"256_tma_3cascades_sobel", 256, {600.0, 140.0, 33.0}, M::tma, N::sobel, {2.0, 2.1}},
      {"1024_jonswap_1cascade_central", 1024, {1000.0}, M::jonswap, N::central_difference, {7.5}},
  };
  std::unique_ptr<TaskRunner> runner = make_tbb_runner();
  std::string device = o.backend;
  Errors all;
  nlohmann::ordered_json per_case = nlohmann::ordered_json::array();
  for (const Case& c : cases) {
    const SimulationConfig config = make_config(c);
    Result<std::unique_ptr<Backend>> reference = make_backend("cpu");
    Result<std::unique_ptr<Backend>> backend = make_backend(o.backend);
    if (!backend.ok()) return report(backend.status());
    if (!reference.ok()) return report(reference.status());
#ifdef OCEAN_HAS_VULKAN
    if (auto* v = dynamic_cast<vk::VulkanBackend*>(backend.value().get()))
      device = v->context().info.name;
#endif
    if (Status s = reference.value()->configure(config, *runner); !s.ok()) return report(s);
    if (Status s = backend.value()->configure(config, *runner); !s.ok()) return report(s);
    Frame ref, got;
    reference.value()->allocate(ref);
    backend.value()->allocate(got);
    Errors e;
    for (double t : c.times_s) {
      reference.value()->step(t, ref);
      backend.value()->step(t, got);
      e.merge(compare(ref, got));
    }
#ifdef OCEAN_HAS_VULKAN
    if (auto* v = dynamic_cast<vk::VulkanBackend*>(backend.value().get()); v && !v->status().ok())
      return report(v->status());
#endif
    all.merge(e);
    nlohmann::ordered_json j = {{"case", c.name}, {"pass", e.pass()}};
    j.update(e.json());
    per_case.push_back(j);
  }
  if (o.json) {
    nlohmann::ordered_json out = {
        {"backend", o.backend}, {"device", device},
        {"pass", all.pass()},   {"max_error_rel_hs", all.displacement_rel_hs},
        {"errors", all.json()}, {"cases", per_case}};
    print_json(out);
  } else {
    std::cout << "backend " << o.backend << " on " << device << ": "
              << (all.pass() ? "pass" : "FAIL") << "\n";
    for (const auto& j : per_case) {
      std::cout << "  " << j["case"].get<std::string>() << ": "
                << (j["pass"].get<bool>() ? "pass" : "FAIL") << "  displacement "
                << j["displacement_rel_hs"].get<double>() << "·Hs"
                << ", half " << j["displacement_half_rel_bound"].get<double>() << " of bound"
                << ", normal " << j["normal"].get<double>() << ", jacobian "
                << j["jacobian"].get<double>() << ", foam " << j["foam"].get<double>()
                << ", packed " << j["packed_lsb"].get<double>() << " LSB\n";
    }
    std::cout << "max_error_rel_hs " << all.displacement_rel_hs << " (bound 1e-4)\n";
  }
  return all.pass() ? kExitOk : kExitFailure;
}

}  // namespace

Command add_validate_command(CLI::App& app) {
  auto o = std::make_shared<ValidateOptions>();
  CLI::App* command = app.add_subcommand(
      "validate", "compare a backend with the CPU reference on this machine's device");
  command->add_option("--backend", o->backend, "backend to validate (see ocean info)");
  command->add_flag("--json", o->json, "print JSON: device, pass, max_error_rel_hs, errors");
  return {command, [o] { return run_validate(*o); }};
}

}  // namespace ocean::cli
