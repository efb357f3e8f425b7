// Output names as data (see output_name.hpp): one pass over the bytes, `%` the only special one.
#include "output_name.hpp"

#include <algorithm>
#include <filesystem>

namespace ocean::cli {

namespace {

constexpr std::string_view kRule =
    "a name holds at most one frame-number field, %d or %0Nd with N from 1 to 18, and writes a "
    "percent sign as %%";
static_assert(kMaxFrameDigits == 18, "kRule states the bound");

std::string echoed(std::string_view flag, std::string_view name) {
  return std::string(flag) + " = '" + excerpt(name) + "'";
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The width of a field starting at name[at] == '%': 0 for "%d", N for "%0Nd" (N 1..18 without a
// leading zero); -1 when the bytes there are not a field. `length` is the field's bytes.
int field_width(std::string_view name, std::size_t at, std::size_t& length) {
  const std::string_view rest = name.substr(at + 1);
  if (!rest.empty() && rest[0] == 'd') {
    length = 2;
    return 0;
  }
  if (rest.size() < 3 || rest[0] != '0' || rest[1] < '1' || rest[1] > '9') return -1;
  int n = rest[1] - '0';
  std::size_t i = 2;
  if (is_digit(rest[i])) n = 10 * n + (rest[i++] - '0');
  if (i >= rest.size() || rest[i] != 'd' || n > kMaxFrameDigits) return -1;
  length = i + 2;
  return n;
}

// The bytes a refused `%` starts, to name in the message: it, up to three digits and the byte
// after them ("%s", "%019d", "%" at the end).
std::string_view bad_field(std::string_view name, std::size_t at) {
  std::size_t end = at + 1;
  while (end < name.size() && end < at + 4 && is_digit(name[end])) ++end;
  if (end < name.size()) ++end;
  return name.substr(at, end - at);
}

std::string padded(long long frame, int digits) {
  std::string number = std::to_string(frame);
  if (number.size() < static_cast<std::size_t>(digits))
    number.insert(0, static_cast<std::size_t>(digits) - number.size(), '0');
  return number;
}

}  // namespace

Status check_output_name(std::string_view flag, std::string_view name) {
  if (name.empty()) return invalid_argument(std::string(flag) + " is empty: give a file name");
  if (name.size() > kMaxOutputNameBytes)
    return invalid_argument(echoed(flag, name) + " is longer than " +
                            std::to_string(kMaxOutputNameBytes) + " bytes (PATH_MAX)");
  std::size_t start = 0;
  while (start < name.size()) {
    const std::size_t end = std::min(name.find('/', start), name.size());
    if (end - start > kMaxOutputComponentBytes)
      return invalid_argument(echoed(flag, name) + " has a part longer than " +
                              std::to_string(kMaxOutputComponentBytes) + " bytes (NAME_MAX)");
    start = end + 1;
  }
  return {};
}

Result<OutputPattern> parse_output_pattern(std::string_view name, std::string_view flag) {
  if (Status s = check_output_name(flag, name); !s.ok()) return s;
  OutputPattern p;
  std::string* text = &p.head;
  for (std::size_t i = 0; i < name.size(); ++i) {
    if (name[i] != '%') {
      *text += name[i];
      continue;
    }
    if (i + 1 < name.size() && name[i + 1] == '%') {
      *text += '%';
      ++i;
      continue;
    }
    std::size_t length = 0;
    const int width = field_width(name, i, length);
    if (width < 0)
      return invalid_argument(echoed(flag, name) + ": '" + excerpt(bad_field(name, i)) +
                              "' is not a frame-number field: " + std::string(kRule));
    if (p.numbered)
      return invalid_argument(echoed(flag, name) +
                              " has two frame-number fields: " + std::string(kRule));
    p.numbered = true;
    p.digits = width;
    text = &p.tail;
    i += length - 1;
  }
  return p;
}

std::string OutputPattern::name() const { return numbered ? name_for(0) : head; }

std::string OutputPattern::name_for(long long frame) const {
  if (numbered) return head + padded(frame, digits) + tail;
  const std::filesystem::path path(head);
  const std::string file =
      path.stem().string() + "_" + padded(frame, 5) + path.extension().string();
  return (path.parent_path() / file).string();
}

}  // namespace ocean::cli
