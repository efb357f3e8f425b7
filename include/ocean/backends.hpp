// ocean/backends.hpp — the table of simulation backends, chosen at run time by name.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "ocean/sim.hpp"

namespace ocean {

struct BackendInfo {
  std::string name;    ///< "cpu", "vulkan", ...
  bool available;      ///< compiled in and usable on this machine
  std::string detail;  ///< what it runs on, or why it is unavailable
};

/// Every backend the library knows, available or not.
std::vector<BackendInfo> list_backends();
/// Creates a backend; unknown names are invalid_argument, known but unavailable ones answer
/// unsupported ("unsupported: built without ...").
Result<std::unique_ptr<Backend>> make_backend(std::string_view name);
/// make_backend + Simulator::make.
Result<std::unique_ptr<Simulator>> make_simulator(const SimulationConfig& config,
                                                  std::string_view backend = "cpu",
                                                  std::shared_ptr<TaskRunner> runner = nullptr);

}  // namespace ocean
