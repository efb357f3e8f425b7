// IEEE-754 binary16 conversion (IEEE Std 754-2008 §3.6; round-to-nearest-even).
#include "ocean/half.hpp"

#include <bit>
#include <cstring>

namespace ocean {

std::uint16_t float_to_half(float value) {
  const std::uint32_t f = std::bit_cast<std::uint32_t>(value);
  const std::uint32_t sign = (f >> 16) & 0x8000u;
  const std::uint32_t abs = f & 0x7fffffffu;
  if (abs >= 0x7f800000u) {  // inf or NaN
    const std::uint32_t mantissa = abs > 0x7f800000u ? 0x0200u | ((abs >> 13) & 0x03ffu) : 0u;
    return static_cast<std::uint16_t>(sign | 0x7c00u | mantissa);
  }
  if (abs >= 0x477ff000u) return static_cast<std::uint16_t>(sign | 0x7c00u);  // rounds to inf
  if (abs < 0x38800000u) {
    // Subnormal half (or zero): shift the implicit-1 mantissa into place, rounding to even.
    if (abs < 0x33000000u) return static_cast<std::uint16_t>(sign);  // below half the min subnormal
    const std::uint32_t exponent = abs >> 23;
    const std::uint32_t mantissa = (abs & 0x007fffffu) | 0x00800000u;
    const std::uint32_t shift = 126u - exponent;  // 14..24
    std::uint32_t half_mantissa = mantissa >> shift;
    const std::uint32_t remainder = mantissa & ((1u << shift) - 1u);
    const std::uint32_t halfway = 1u << (shift - 1u);
    if (remainder > halfway || (remainder == halfway && (half_mantissa & 1u))) ++half_mantissa;
    return static_cast<std::uint16_t>(sign | half_mantissa);
  }
  // Normal: rebias the exponent and round the mantissa to 10 bits (nearest, ties to even).
  std::uint32_t bits = abs - 0x38000000u;  // exponent bias 127 → 15, still in float layout
  const std::uint32_t round = 0x0fffu + ((bits >> 13) & 1u);
  bits += round;
  return static_cast<std::uint16_t>(sign | (bits >> 13));
}

float half_to_float(std::uint16_t bits) {
  const std::uint32_t sign = static_cast<std::uint32_t>(bits & 0x8000u) << 16;
  const std::uint32_t exponent = (bits >> 10) & 0x1fu;
  const std::uint32_t mantissa = bits & 0x03ffu;
  std::uint32_t f = 0;
  if (exponent == 0) {
    if (mantissa == 0) {
      f = sign;
    } else {  // subnormal: value = mantissa · 2^-24
      const float v = static_cast<float>(mantissa) * 5.9604644775390625e-8f;
      return sign ? -v : v;
    }
  } else if (exponent == 31) {
    f = sign | 0x7f800000u | (mantissa << 13);
  } else {
    f = sign | ((exponent + 112u) << 23) | (mantissa << 13);
  }
  return std::bit_cast<float>(f);
}

}  // namespace ocean
