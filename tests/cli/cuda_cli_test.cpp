// The CUDA backend from the command line: where it cannot run (built without CUDA, or no usable
// device: CI has neither a GPU nor a driver), every command that takes --backend cuda (render and
// view included, before any window or file) prints one line, "ocean: error: " and the backend
// table's reason, writes nothing on standard output and exits 1; `ocean info` says why there are no
// CUDA devices. Where a device exists these checks give way to the conformance tests
// (tests/backends/conformance_test.cpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/cli_run.hpp"
#include "ocean/backends.hpp"

namespace {

// The table's entry for cuda: available, and the detail (the reason when unavailable).
ocean::BackendInfo cuda_entry() {
  for (const ocean::BackendInfo& b : ocean::list_backends())
    if (b.name == "cuda") return b;
  return {"cuda", false, "missing from the backend table"};
}

TEST(CudaCli, WithoutADeviceEveryCommandSaysWhyOnOneLine) {
  const ocean::BackendInfo cuda = cuda_entry();
  if (cuda.available) GTEST_SKIP() << "a CUDA device is present: " << cuda.detail;
  const bool built = ocean::compiled_in("cuda").ok();
  const std::string expected =
      built ? "ocean: error: " + cuda.detail + "\n"
            : "ocean: error: unsupported: backend 'cuda' " + cuda.detail + "\n";
  if (built) {
    EXPECT_TRUE(cuda.detail.starts_with("no CUDA device: ")) << cuda.detail;
  }
  for (const std::string args :
       {"validate --backend cuda", "query --backend cuda --at 1,2",
        "bench --backend cuda --resolution 64 --cascades 1",
        "render --backend cuda --out cuda_cli_never_written.png", "view --backend cuda"}) {
    SCOPED_TRACE(args);
    const ocean_test::CliRun r = ocean_test::run_cli(args);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_TRUE(r.out.empty()) << r.out;
    if (args.starts_with("render")) {
      EXPECT_FALSE(std::filesystem::exists("cuda_cli_never_written.png"));
    }
    if (args.starts_with("bench") && !built) {
      EXPECT_EQ(r.err, "ocean: error: ocean bench --backend cuda: built without CUDA\n");
    } else {
      EXPECT_EQ(r.err, expected);
    }
  }
}

TEST(CudaCli, InfoSaysWhyThereAreNoDevices) {
  const ocean::BackendInfo cuda = cuda_entry();
  const ocean_test::CliRun r = ocean_test::run_cli("info --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("cuda"));
  if (cuda.available) {
    EXPECT_FALSE(j["cuda"]["devices"].empty());
    EXPECT_EQ(j["cuda"]["status"], "ok");
    return;
  }
  EXPECT_EQ(j["cuda"]["status"],
            ocean::compiled_in("cuda").ok() ? cuda.detail : "built without CUDA");
  EXPECT_TRUE(j["cuda"]["devices"].empty());
  // Whether --backend cuda would render with no host copy: not without a device, and why.
  EXPECT_EQ(j["cuda"]["render"], j["cuda"]["status"]);
  const ocean_test::CliRun text = ocean_test::run_cli("info");
  EXPECT_NE(text.out.find("cuda devices: none ("), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("cuda render: " + j["cuda"]["status"].get<std::string>() + "\n"),
            std::string::npos)
      << text.out;
}

}  // namespace
