// `ocean info`: the simulation backends of this build (available or why not) and the Vulkan
// and CUDA devices of this machine, as a table or JSON.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"
#include "ocean/backends.hpp"

namespace ocean::cli {

namespace {

int run_info(bool json) {
  nlohmann::ordered_json backends = nlohmann::ordered_json::array();
  for (const BackendInfo& b : list_backends())
    backends.push_back({{"name", b.name}, {"available", b.available}, {"detail", b.detail}});
  nlohmann::ordered_json devices = nlohmann::ordered_json::array();
  std::string vulkan_status = "ok";
  Result<std::vector<VulkanDeviceInfo>> found = list_vulkan_devices();
  if (found.ok()) {
    for (std::size_t i = 0; i < found.value().size(); ++i) {
      const VulkanDeviceInfo& d = found.value()[i];
      devices.push_back({{"index", i},
                         {"name", d.name},
                         {"type", d.type},
                         {"api_version", d.api_version},
                         {"driver", d.driver},
                         {"usable", d.usable},
                         {"reason", d.reason}});
    }
  } else {
    vulkan_status = found.status().message();
  }
  nlohmann::ordered_json cuda_devices = nlohmann::ordered_json::array();
  const std::string cuda_versions = ocean::cuda_versions();
  Result<std::vector<cuda::DeviceInfo>> cuda_found = list_cuda_devices();
  const std::string cuda_status = cuda_found.ok() ? "ok" : cuda_found.status().message();
  for (const cuda::DeviceInfo& d :
       cuda_found.ok() ? cuda_found.value() : std::vector<cuda::DeviceInfo>{}) {
    cuda_devices.push_back({{"index", d.index},
                            {"name", d.name},
                            {"compute_capability", std::to_string(d.compute_major) + "." +
                                                       std::to_string(d.compute_minor)},
                            {"memory_bytes", d.memory_bytes},
                            {"multiprocessors", d.multiprocessors},
                            {"usable", d.usable},
                            {"reason", d.reason}});
  }
  // Whether `--backend cuda` renders with no host copy (or why there is no CUDA device).
  const std::string cuda_render = cuda_render_path(cuda_found);
  if (json) {
    print_json({{"backends", backends},
                {"vulkan", {{"status", vulkan_status}, {"devices", devices}}},
                {"cuda",
                 {{"status", cuda_status},
                  {"versions", cuda_versions},
                  {"devices", cuda_devices},
                  {"render", cuda_render}}}});
    return kExitOk;
  }
  std::cout << "backends:\n";
  for (const auto& b : backends) {
    std::cout << "  " << b["name"].get<std::string>() << "  "
              << (b["available"].get<bool>() ? "available" : "unavailable") << "  "
              << b["detail"].get<std::string>() << "\n";
  }
  std::cout << "vulkan devices:" << (devices.empty() ? " none (" + vulkan_status + ")" : "")
            << "\n";
  for (const auto& d : devices) {
    std::cout << "  [" << d["index"].get<std::size_t>() << "] " << d["name"].get<std::string>()
              << " (" << d["type"].get<std::string>() << ", Vulkan "
              << d["api_version"].get<std::string>() << ", " << d["driver"].get<std::string>()
              << ")"
              << (d["usable"].get<bool>() ? "" : " unusable: " + d["reason"].get<std::string>())
              << "\n";
  }
  std::cout << "cuda devices:" << (cuda_devices.empty() ? " none (" + cuda_status + ")" : "")
            << (cuda_versions.empty() ? "" : " [" + cuda_versions + "]") << "\n";
  for (const auto& d : cuda_devices) {
    std::cout << "  [" << d["index"].get<int>() << "] " << d["name"].get<std::string>()
              << " (compute " << d["compute_capability"].get<std::string>() << ", "
              << d["memory_bytes"].get<std::uint64_t>() / (std::uint64_t{1} << 20) << " MiB, "
              << d["multiprocessors"].get<int>() << " SMs)"
              << (d["usable"].get<bool>() ? "" : " unusable: " + d["reason"].get<std::string>())
              << "\n";
  }
  std::cout << "cuda render: " << cuda_render << "\n";
  return kExitOk;
}

}  // namespace

Command add_info_command(CLI::App& app) {
  auto json = std::make_shared<bool>(false);
  CLI::App* command =
      app.add_subcommand("info", "list the simulation backends and the Vulkan and CUDA devices");
  command->add_flag("--json", *json, "print JSON");
  return {command, [json] { return run_info(*json); }};
}

}  // namespace ocean::cli
