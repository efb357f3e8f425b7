// Parameter validation helpers and number formatting shared by every module.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "ocean/core.hpp"

namespace ocean {

std::string format_number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[32];
#if defined(__cpp_lib_to_chars)
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
#else
  // C++ libraries without floating-point to_chars (emscripten 3.1.6's libc++, the WebAssembly
  // build): what to_chars writes. The fewest significant digits that read back as the same
  // double, then the shorter of the fixed and the scientific form, fixed on a tie.
  int digits = 1;
  for (; digits < 17; ++digits) {
    std::snprintf(buffer, sizeof(buffer), "%.*e", digits - 1, value);
    if (std::strtod(buffer, nullptr) == value) break;
  }
  std::snprintf(buffer, sizeof(buffer), "%.*e", digits - 1, value);
  const std::string e_form(buffer);
  const bool negative = e_form[0] == '-';
  const std::size_t e_at = e_form.find('e');
  std::string mantissa;
  for (std::size_t i = negative ? 1 : 0; i < e_at; ++i)
    if (e_form[i] != '.') mantissa += e_form[i];
  while (mantissa.size() > 1 && mantissa.back() == '0') mantissa.pop_back();
  const int exponent = std::atoi(e_form.c_str() + e_at + 1);
  const int n = static_cast<int>(mantissa.size());
  std::string scientific = mantissa.substr(0, 1);
  if (n > 1) scientific += "." + mantissa.substr(1);
  std::snprintf(buffer, sizeof(buffer), "e%c%02d", exponent < 0 ? '-' : '+', std::abs(exponent));
  scientific += buffer;
  std::string fixed;
  if (exponent >= n - 1) {
    // An integer: printf's %f writes its exact digits, which is what to_chars writes too.
    if (static_cast<std::size_t>(exponent) + 1 > scientific.size())
      return (negative ? "-" : "") + scientific;
    std::snprintf(buffer, sizeof(buffer), "%.0f", std::fabs(value));
    fixed = buffer;
  } else if (exponent < 0)
    fixed = "0." + std::string(static_cast<std::size_t>(-exponent - 1), '0') + mantissa;
  else
    fixed = mantissa.substr(0, static_cast<std::size_t>(exponent + 1)) + "." +
            mantissa.substr(static_cast<std::size_t>(exponent + 1));
  return (negative ? "-" : "") + (fixed.size() <= scientific.size() ? fixed : scientific);
#endif
}

namespace {
// Length of the well-formed UTF-8 sequence starting at s[i] (RFC 3629: no overlong forms, no
// surrogates, nothing above U+10FFFF), or 0 when it is not one.
std::size_t utf8_sequence_length(std::string_view s, std::size_t i) {
  const auto byte = [&](std::size_t j) { return static_cast<unsigned char>(s[j]); };
  const unsigned char b0 = byte(i);
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // allowed range of the second byte
  if (b0 >= 0xC2 && b0 <= 0xDF) {
    n = 2;
  } else if (b0 >= 0xE0 && b0 <= 0xEF) {
    n = 3;
    if (b0 == 0xE0) lo = 0xA0;
    if (b0 == 0xED) hi = 0x9F;
  } else if (b0 >= 0xF0 && b0 <= 0xF4) {
    n = 4;
    if (b0 == 0xF0) lo = 0x90;
    if (b0 == 0xF4) hi = 0x8F;
  } else {
    return 0;
  }
  if (i + n > s.size()) return 0;
  if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (std::size_t j = 2; j < n; ++j)
    if (byte(i + j) < 0x80 || byte(i + j) > 0xBF) return 0;
  return n;
}
}  // namespace

std::string excerpt(std::string_view text, std::size_t max_bytes) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    std::size_t length = 1;
    if (c >= 0x80) {
      length = utf8_sequence_length(text, i);
      if (length == 0) length = 1;  // escaped below
    }
    if (i + length > max_bytes) break;
    if (c == '\\') {
      out += "\\\\";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c < 0x20 || c == 0x7F || (c >= 0x80 && utf8_sequence_length(text, i) == 0)) {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 0xF];
    } else {
      out.append(text.substr(i, length));
    }
    i += length;
  }
  if (i < text.size()) out += "... (" + std::to_string(text.size()) + " bytes)";
  return out;
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
