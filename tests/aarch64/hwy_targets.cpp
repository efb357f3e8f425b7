// The three symbols of Highway 1.0.3's targets.cc the SIMD kernels use, for AArch64, so that
// the cross-build needs Highway's headers only (they are architecture-independent) and no
// libhwy1:arm64. NEON is part of the AArch64 baseline; SVE is not built (see CMakeLists.txt).
#include <hwy/targets.h>

namespace hwy {

namespace {
std::int64_t g_for_test = 0;  // SetSupportedTargetsForTest's mask, 0: none
}  // namespace

HWY_DLLEXPORT std::int64_t SupportedTargets() {
  const std::int64_t targets = g_for_test != 0 ? g_for_test : (HWY_NEON | HWY_EMU128 | HWY_SCALAR);
  return targets != 0 ? targets : HWY_STATIC_TARGET;
}

HWY_DLLEXPORT void SetSupportedTargetsForTest(std::int64_t targets) {
  g_for_test = targets;
  GetChosenTarget().Update(SupportedTargets());
}

HWY_DLLEXPORT ChosenTarget& GetChosenTarget() {
  static ChosenTarget chosen;
  return chosen;
}

}  // namespace hwy
