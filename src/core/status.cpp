// Parameter validation helpers and number formatting shared by every module.
#include <charconv>
#include <cmath>
#include <string>

#include "ocean/core.hpp"

namespace ocean {

std::string format_number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

namespace {
Status out_of_range(std::string_view name, double value, std::string_view rule) {
  return invalid_argument(std::string(name) + " = " + format_number(value) +
                          " is out of range: must be " + std::string(rule));
}
}  // namespace

Status require_finite(std::string_view name, double value) {
  if (!std::isfinite(value)) return out_of_range(name, value, "a finite number");
  return {};
}

Status require_positive(std::string_view name, double value) {
  if (!(value > 0.0) || std::isinf(value)) return out_of_range(name, value, "> 0 and finite");
  return {};
}

Status require_non_negative(std::string_view name, double value) {
  if (!(value >= 0.0) || std::isinf(value)) return out_of_range(name, value, ">= 0 and finite");
  return {};
}

Status require_in_range(std::string_view name, double value, double lo, double hi) {
  if (!(value >= lo && value <= hi)) {
    return out_of_range(name, value, "in [" + format_number(lo) + ", " + format_number(hi) + "]");
  }
  return {};
}

}  // namespace ocean
