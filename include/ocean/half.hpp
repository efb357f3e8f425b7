// ocean/half.hpp — IEEE-754 binary16 ("half") conversion for texture data.
#pragma once

#include <cstdint>

namespace ocean {

/// float → half bits with round-to-nearest-even; overflow gives ±inf, NaN stays NaN,
/// subnormal halves are produced exactly.
std::uint16_t float_to_half(float value);
/// half bits → float (exact).
float half_to_float(std::uint16_t bits);

}  // namespace ocean
