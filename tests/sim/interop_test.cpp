// The CUDA–Vulkan pairing decision and the shared-input layout (ocean/interop.hpp) on fabricated
// device descriptions: zero-copy only for the same GPU (equal UUIDs) with both fd extensions,
// else the first usable CUDA device with a one-line reason; the layout against the Frame arrays
// it carries (allocate_frame) and the renderer's mip offsets.
#include "ocean/interop.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ocean/sim.hpp"

namespace {

using namespace ocean;

interop::Uuid fake_uuid(std::uint8_t first) {
  interop::Uuid u{};
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = static_cast<std::uint8_t>(first + i);
  return u;
}

interop::VulkanSide fake_vulkan(interop::Uuid u) {
  return {.name = "GPU A", .uuid = u, .memory_fd = true, .semaphore_fd = true, .timeline = true};
}

TEST(Interop, SameUuidSharesMemory) {
  const std::vector<interop::CudaSide> cuda = {
      {.index = 0, .name = "other", .uuid = fake_uuid(9), .usable = true},
      {.index = 1, .name = "A", .uuid = fake_uuid(1), .usable = true}};
  const interop::Choice c = interop::choose(fake_vulkan(fake_uuid(1)), cuda);
  EXPECT_TRUE(c.zero_copy);
  EXPECT_EQ(c.cuda_device, 1);  // the matching one, not the first
  EXPECT_TRUE(c.timeline);
  EXPECT_NE(c.reason.find("timeline"), std::string::npos) << c.reason;
}

TEST(Interop, BinarySemaphoresWithoutTimeline) {
  interop::VulkanSide v = fake_vulkan(fake_uuid(1));
  v.timeline = false;
  const std::vector<interop::CudaSide> cuda = {
      {.index = 0, .name = "A", .uuid = fake_uuid(1), .usable = true}};
  const interop::Choice c = interop::choose(v, cuda);
  EXPECT_TRUE(c.zero_copy);
  EXPECT_FALSE(c.timeline);
  EXPECT_NE(c.reason.find("binary"), std::string::npos) << c.reason;
}

TEST(Interop, NoMatchingUuidFallsBackToUploadsOnTheFirstUsableDevice) {
  const std::vector<interop::CudaSide> cuda = {
      {.index = 0, .name = "B", .uuid = fake_uuid(1), .usable = false},
      {.index = 1, .name = "C", .uuid = fake_uuid(5), .usable = true}};
  // Device 0 has the UUID but is not usable: no zero copy, device 1 simulates.
  const interop::Choice c = interop::choose(fake_vulkan(fake_uuid(1)), cuda);
  EXPECT_FALSE(c.zero_copy);
  EXPECT_EQ(c.cuda_device, 1);
  EXPECT_NE(c.reason.find("no CUDA device is the Vulkan device 'GPU A'"), std::string::npos)
      << c.reason;
  EXPECT_NE(c.reason.find("read back and uploaded"), std::string::npos) << c.reason;
  EXPECT_EQ(c.reason.find('\n'), std::string::npos);
}

TEST(Interop, MissingExtensionsAreNamed) {
  const std::vector<interop::CudaSide> cuda = {
      {.index = 0, .name = "A", .uuid = fake_uuid(1), .usable = true}};
  interop::VulkanSide v = fake_vulkan(fake_uuid(1));
  v.memory_fd = false;
  interop::Choice c = interop::choose(v, cuda);
  EXPECT_FALSE(c.zero_copy);
  EXPECT_EQ(c.cuda_device, 0);
  EXPECT_NE(c.reason.find("lacks VK_KHR_external_memory_fd"), std::string::npos) << c.reason;
  v = fake_vulkan(fake_uuid(1));
  v.semaphore_fd = false;
  c = interop::choose(v, cuda);
  EXPECT_FALSE(c.zero_copy);
  EXPECT_NE(c.reason.find("lacks VK_KHR_external_semaphore_fd"), std::string::npos) << c.reason;
}

TEST(Interop, NoUsableCudaDevice) {
  const interop::Choice none = interop::choose(fake_vulkan(fake_uuid(1)), {});
  EXPECT_EQ(none.cuda_device, -1);
  EXPECT_FALSE(none.zero_copy);
  const std::vector<interop::CudaSide> cuda = {
      {.index = 0, .name = "A", .uuid = fake_uuid(1), .usable = false}};
  EXPECT_EQ(interop::choose(fake_vulkan(fake_uuid(1)), cuda).cuda_device, -1);
}

TEST(Interop, UuidPrintsAsNvidiaSmiDoes) {
  EXPECT_EQ(interop::to_string(fake_uuid(0)), "GPU-00010203-0405-0607-0809-0a0b0c0d0e0f");
}

TEST(Interop, LayoutHoldsTheFramesRendererArrays) {
  SimulationConfig config;
  config.resolution = 64;
  config.cascade_patch_sizes_m = {200.0, 47.0, 11.0};
  Frame frame;
  allocate_frame(config, frame);
  const interop::InputsLayout l = interop::inputs_layout(64, 3);
  std::size_t total = 0;
  for (int c = 0; c < 3; ++c) {
    const CascadeFrame& f = frame.cascades[static_cast<std::size_t>(c)];
    EXPECT_EQ(l.displacement_bytes, f.displacement_half.size() * sizeof(f.displacement_half[0]));
    EXPECT_EQ(l.mips_bytes, f.packed_mips.size() * sizeof(f.packed_mips[0]));
    total += l.displacement_bytes + l.mips_bytes;
    // Displacements first, then the mip chains, each cascade after the one before.
    EXPECT_EQ(l.displacement_offset(c), static_cast<std::size_t>(c) * 64 * 64 * 8);
    EXPECT_EQ(l.mips_offset(c),
              3 * l.displacement_bytes + static_cast<std::size_t>(c) * l.mips_bytes);
  }
  EXPECT_EQ(l.bytes(), total);
  // The chain is levels 64², 32², …, 1²: (4·64² − 1)/3 texels.
  EXPECT_EQ(l.mips_bytes, 4u * (4u * 64 * 64 - 1) / 3);
  EXPECT_EQ(l.mips_bytes, 4 * mip_chain_texels(64));
}

}  // namespace
