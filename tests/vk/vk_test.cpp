// The shared Vulkan layer: device enumeration, context creation with validation, device
// selection errors, buffer round trip through a copy, timestamps, the side of the CUDA pairing
// (external_interop). Skips where no device exists (fails with OCEAN_REQUIRE_DEVICES=1).
#include "ocean/vk.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <numeric>
#include <vector>

#include "ocean/interop.hpp"
#include "ocean/vk/external.hpp"
#include "support/require_devices.hpp"

namespace {

bool have_device() {
  auto devices = ocean::vk::list_devices();
  if (!devices.ok()) return false;
  for (const auto& d : devices.value())
    if (d.usable) return true;
  return false;
}

TEST(Vk, ListDevicesNamesEveryDeviceOrSaysWhatToInstall) {
  auto devices = ocean::vk::list_devices();
  if (!devices.ok()) {
    EXPECT_EQ(devices.status().code(), ocean::ErrorCode::unsupported);
    EXPECT_NE(devices.status().message().find("install"), std::string::npos);
    return;
  }
  for (const auto& d : devices.value()) {
    EXPECT_FALSE(d.name.empty());
    EXPECT_FALSE(d.type.empty());
    EXPECT_EQ(d.usable, d.reason.empty());
  }
}

TEST(Vk, BadDeviceIndexIsAClearError) {
  if (!have_device()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  auto ctx = ocean::vk::create_context({.device_index = 99});
  ASSERT_FALSE(ctx.ok());
  EXPECT_EQ(ctx.status().code(), ocean::ErrorCode::invalid_argument);
  EXPECT_NE(ctx.status().message().find("ocean info"), std::string::npos);
}

// An allocation above the device's maxMemoryAllocationSize is refused with one line before
// vkAllocateMemory (drivers may crash or fail late on one). The limit is lowered to 1 MiB here
// so that the refusal can be seen without allocating gigabytes.
TEST(Vk, AllocationAboveTheDeviceLimitIsRefusedBeforeAllocating) {
  if (!have_device()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  auto created = ocean::vk::create_context({.validation = true});
  ASSERT_TRUE(created.ok()) << created.status().message();
  ocean::vk::Context& ctx = *created.value();
  EXPECT_GE(ctx.max_allocation_bytes, VkDeviceSize{1} << 30);  // Vulkan's required minimum
  ctx.max_allocation_bytes = VkDeviceSize{1} << 20;
  auto fits = ocean::vk::create_buffer(ctx, VkDeviceSize{1} << 19, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                       ocean::vk::MemoryUse::upload);
  ASSERT_TRUE(fits.ok()) << fits.status().message();
  ocean::vk::destroy_buffer(ctx, fits.value());
  auto too_big = ocean::vk::create_buffer(
      ctx, VkDeviceSize{2} << 20, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, ocean::vk::MemoryUse::upload);
  ASSERT_FALSE(too_big.ok());
  EXPECT_EQ(too_big.status().code(), ocean::ErrorCode::invalid_argument);
  EXPECT_NE(too_big.status().message().find("maxMemoryAllocationSize 1.0 MiB"), std::string::npos)
      << too_big.status().message();
  EXPECT_EQ(ctx.validation_messages.load(), 0u) << ctx.last_validation_message;
}

TEST(Vk, BufferCopyRoundTripsWithZeroValidationMessages) {
  if (!have_device()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  auto created = ocean::vk::create_context({.validation = true});
  ASSERT_TRUE(created.ok()) << created.status().message();
  ocean::vk::Context& ctx = *created.value();
  EXPECT_TRUE(ctx.validation);
  {
    std::vector<float> data(1000);
    std::iota(data.begin(), data.end(), 0.5f);
    const VkDeviceSize bytes = data.size() * sizeof(float);
    auto up = ocean::vk::create_buffer(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                       ocean::vk::MemoryUse::upload);
    auto dev = ocean::vk::create_buffer(
        ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
        ocean::vk::MemoryUse::device);
    auto down = ocean::vk::create_buffer(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                         ocean::vk::MemoryUse::readback);
    auto cmds = ocean::vk::create_commands(ctx);
    auto stamps = ocean::vk::create_timestamps(ctx, 2);
    ASSERT_TRUE(up.ok() && dev.ok() && down.ok() && cmds.ok());
    std::memcpy(up.value().mapped, data.data(), bytes);
    const ocean::Status s = ocean::vk::run_once(ctx, cmds.value(), [&](VkCommandBuffer cmd) {
      if (stamps.ok()) {
        vkCmdResetQueryPool(cmd, stamps.value().pool, 0, 2);
        vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, stamps.value().pool, 0);
      }
      const VkBufferCopy region{0, 0, bytes};
      vkCmdCopyBuffer(cmd, up.value().buffer, dev.value().buffer, 1, &region);
      ocean::vk::barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
      vkCmdCopyBuffer(cmd, dev.value().buffer, down.value().buffer, 1, &region);
      if (stamps.ok())
        vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, stamps.value().pool, 1);
    });
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(std::memcmp(down.value().mapped, data.data(), bytes), 0);
    if (stamps.ok()) {
      double ms[2];
      ASSERT_TRUE(ocean::vk::read_timestamps_ms(ctx, stamps.value(), ms).ok());
      EXPECT_EQ(ms[0], 0.0);
      EXPECT_GE(ms[1], 0.0);
      ocean::vk::destroy_timestamps(ctx, stamps.value());
    }
    ocean::vk::destroy_commands(ctx, cmds.value());
    ocean::vk::destroy_buffer(ctx, up.value());
    ocean::vk::destroy_buffer(ctx, dev.value());
    ocean::vk::destroy_buffer(ctx, down.value());
  }
  EXPECT_EQ(ctx.validation_messages.load(), 0u) << ctx.last_validation_message;
}

TEST(Vk, CheckTurnsDeviceLossAndOutOfMemoryIntoClearMessages) {
  const ocean::Status lost = ocean::vk::check(VK_ERROR_DEVICE_LOST, "vkQueueSubmit");
  EXPECT_NE(lost.message().find("device lost"), std::string::npos);
  EXPECT_NE(lost.message().find("--backend cpu"), std::string::npos);
  const ocean::Status oom = ocean::vk::check(VK_ERROR_OUT_OF_DEVICE_MEMORY, "vkAllocateMemory");
  EXPECT_NE(oom.message().find("lower the resolution"), std::string::npos);
  EXPECT_TRUE(ocean::vk::check(VK_SUCCESS, "x").ok());
}

// The context's side of the CUDA pairing on a real device: the UUID read from the device is the
// one the device list reports, not all zeros, and stays the same for a second device; the
// extensions the context enabled are those the device advertises; and interop::choose with a
// CUDA device of that UUID shares memory only where both fd extensions are on (lavapipe, Mesa
// 22: memory yes, semaphores no), naming the missing one otherwise.
TEST(Vk, ExternalInteropSideMatchesTheDeviceAndDecides) {
  if (!have_device()) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  auto made = ocean::vk::create_context({.validation = true, .external_interop = true});
  ASSERT_TRUE(made.ok()) << made.status().message();
  const ocean::vk::Context& ctx = *made.value();
  const ocean::interop::VulkanSide side = ocean::vk::interop_side(ctx);
  EXPECT_NE(side.uuid, ocean::interop::Uuid{});
  auto sides = ocean::vk::list_interop_sides();
  ASSERT_TRUE(sides.ok()) << sides.status().message();
  const auto same = std::find_if(sides.value().begin(), sides.value().end(),
                                 [&](const auto& s) { return s.name == side.name; });
  ASSERT_NE(same, sides.value().end());
  EXPECT_EQ(same->uuid, side.uuid);
  EXPECT_EQ(same->memory_fd, side.memory_fd);
  EXPECT_EQ(same->semaphore_fd, side.semaphore_fd);
  auto again = ocean::vk::create_context({.external_interop = true});
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(again.value()->device_uuid, ctx.device_uuid);
  // Without external_interop nothing is enabled.
  auto plain = ocean::vk::create_context({});
  ASSERT_TRUE(plain.ok());
  EXPECT_FALSE(plain.value()->external_memory_fd || plain.value()->external_semaphore_fd ||
               plain.value()->timeline_semaphore);

  const std::vector<ocean::interop::CudaSide> cuda = {
      {.index = 0, .name = "same GPU", .uuid = side.uuid, .usable = true}};
  const ocean::interop::Choice c = ocean::interop::choose(side, cuda);
  EXPECT_EQ(c.cuda_device, 0);
  EXPECT_EQ(c.zero_copy, side.memory_fd && side.semaphore_fd) << c.reason;
  if (!side.semaphore_fd) {
    EXPECT_NE(c.reason.find("VK_KHR_external_semaphore_fd"), std::string::npos) << c.reason;
  }
  EXPECT_EQ(ctx.validation_messages.load(), 0u) << ctx.last_validation_message;
}

}  // namespace
