// `ocean validate`: runs the backend conformance cases (ocean/conformance.hpp) on this machine's
// device and prints each output's error against the CPU backend's scalar reference pipeline;
// exit 1 when a bound of the backend's kind (conformance::bounds_for) is exceeded.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"
#include "ocean/backends.hpp"
#include "ocean/backends/cpu.hpp"
#include "ocean/conformance.hpp"

namespace ocean::cli {

namespace {

struct ValidateOptions {
  std::string backend = "vulkan";
  bool json = false;
};

// The fields of conformance::Errors or conformance::Bounds (the same names).
template <typename Fields>
nlohmann::ordered_json errors_json(const Fields& e) {
  return {{"height_rel_hs", e.height_rel_hs},
          {"displacement_rel_hs", e.displacement_rel_hs},
          {"displacement_half_rel_bound", e.displacement_half_rel_bound},
          {"normal", e.normal},
          {"jacobian", e.jacobian},
          {"foam", e.foam},
          {"packed_lsb", static_cast<double>(e.packed_lsb)},
          {"packed_fraction", e.packed_fraction}};
}

int run_validate(const ValidateOptions& o) {
  std::unique_ptr<TaskRunner> runner = make_tbb_runner();
  std::string device = o.backend;
  const conformance::Bounds& bounds = conformance::bounds_for(o.backend);
  conformance::Errors all;
  nlohmann::ordered_json per_case = nlohmann::ordered_json::array();
  for (const conformance::Case& c : conformance::cases()) {
    const std::unique_ptr<Backend> reference =
        cpu::make_cpu_backend({.pipeline = cpu::CpuPipeline::scalar_reference});
    Result<std::unique_ptr<Backend>> backend = make_backend(o.backend);
    if (!backend.ok()) return report(backend.status());
    const DeviceCapabilities* caps = capabilities(*backend.value());
    if (caps != nullptr) device = caps->device_name();
    Result<std::vector<conformance::FrameResult>> frames =
        conformance::run_case(c, *reference, *backend.value(), *runner, bounds);
    if (!frames.ok()) return report(frames.status());
    conformance::Errors e;
    for (const conformance::FrameResult& f : frames.value()) e.merge(f.errors);
    if (caps != nullptr && !caps->status().ok()) return report(caps->status());
    all.merge(e);
    nlohmann::ordered_json j = {{"case", c.name}, {"pass", e.pass(bounds)}};
    j.update(errors_json(e));
    per_case.push_back(j);
  }
  if (o.json) {
    nlohmann::ordered_json out = {
        {"backend", o.backend},       {"device", device},
        {"pass", all.pass(bounds)},   {"max_error_rel_hs", all.displacement_rel_hs},
        {"errors", errors_json(all)}, {"bounds", errors_json(bounds)},
        {"cases", per_case}};
    print_json(out);
  } else {
    std::cout << "backend " << o.backend << " on " << device << ": "
              << (all.pass(bounds) ? "pass" : "FAIL") << "\n";
    for (const auto& j : per_case) {
      std::cout << "  " << j["case"].get<std::string>() << ": "
                << (j["pass"].get<bool>() ? "pass" : "FAIL") << "  height "
                << j["height_rel_hs"].get<double>() << "·Hs, displacement "
                << j["displacement_rel_hs"].get<double>() << "·Hs"
                << ", half " << j["displacement_half_rel_bound"].get<double>() << " of bound"
                << ", normal " << j["normal"].get<double>() << ", jacobian "
                << j["jacobian"].get<double>() << ", foam " << j["foam"].get<double>()
                << ", packed " << j["packed_lsb"].get<double>() << " LSB on "
                << 100.0 * j["packed_fraction"].get<double>() << "% of texels\n";
    }
    std::cout << "max_error_rel_hs " << all.displacement_rel_hs << " (bound "
              << bounds.displacement_rel_hs << ")\n";
  }
  return all.pass(bounds) ? kExitOk : kExitFailure;
}

}  // namespace

Command add_validate_command(CLI::App& app) {
  auto o = std::make_shared<ValidateOptions>();
  CLI::App* command = app.add_subcommand(
      "validate", "compare a backend with the CPU reference pipeline on this machine's device");
  command->add_option("--backend", o->backend, "backend to validate (see ocean info)");
  command->add_flag("--json", o->json, "print JSON: device, pass, max_error_rel_hs, errors");
  return {command, [o] { return run_validate(*o); }};
}

}  // namespace ocean::cli
