// tests/support/npy_reader.cpp — a strict, fuzz-safe .npy 1.0 float32 reader.
#include "support/npy_reader.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <exception>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include "io/format_detail.hpp"
#include "ocean/io.hpp"

namespace ocean::io {
namespace {

using detail::byte_swap;
using detail::element_count;

using detail::kNpyMagic;
using detail::kNpyMagicLen;
using detail::kNpyPreludeLen;

// ---- header parsing: the subset of Python literal syntax that .npy headers use ------------------
class HeaderParser {
 public:
  explicit HeaderParser(std::string_view text) : s_(text) {}

  // Parses the whole dict into `out` or returns the problem.
  std::optional<std::string> parse(NpyArray& out) {
    bool have_descr = false, have_order = false, have_shape = false;
    skip_ws();
    if (!eat('{')) return error("expected '{'");
    skip_ws();
    while (!eat('}')) {
      std::string key;
      if (!parse_string(key)) return error("expected a quoted key");
      skip_ws();
      if (!eat(':')) return error("expected ':'");
      skip_ws();
      bool* seen = key == "descr"           ? &have_descr
                   : key == "fortran_order" ? &have_order
                   : key == "shape"         ? &have_shape
                                            : nullptr;
      if (seen == nullptr) return "unexpected header key '" + key + "'";
      if (*seen) return "duplicate header key '" + key + "'";
      *seen = true;
      if (key == "descr") {
        std::string descr;
        if (!parse_string(descr)) return std::string("'descr' is not a simple dtype string");
        if (descr != "<f4") {
          return "dtype '" + descr + "' is not supported: only '<f4' (little-endian float32)";
        }
      } else if (key == "fortran_order") {
        if (s_.substr(pos_, 4) == "True") return std::string("Fortran order is not supported");
        if (s_.substr(pos_, 5) != "False") return error("'fortran_order' must be True or False");
        pos_ += 5;
      } else if (auto problem = parse_shape(out.shape)) {
        return problem;
      }
      skip_ws();
      if (!eat(',') && (pos_ >= s_.size() || s_[pos_] != '}')) return error("expected ',' or '}'");
      skip_ws();
    }
    skip_ws();
    if (pos_ != s_.size()) return error("unexpected text after the header dict");
    if (!have_descr) return std::string("header lacks 'descr'");
    if (!have_order) return std::string("header lacks 'fortran_order'");
    if (!have_shape) return std::string("header lacks 'shape'");
    return std::nullopt;
  }

 private:
  std::string error(const char* what) const {
    std::string message = "malformed header: ";
    return message.append(what).append(" at header byte ").append(std::to_string(pos_));
  }
  void skip_ws() {
    while (pos_ < s_.size() && std::string_view(" \t\n\r").find(s_[pos_]) != s_.npos) ++pos_;
  }
  bool digit_at(std::size_t i) const { return i < s_.size() && s_[i] >= '0' && s_[i] <= '9'; }
  bool eat(char c) {
    if (pos_ < s_.size() && s_[pos_] == c) return ++pos_, true;
    return false;
  }
  bool parse_string(std::string& out) {
    if (pos_ >= s_.size() || (s_[pos_] != '\'' && s_[pos_] != '"')) return false;
    const char quote = s_[pos_];
    const std::size_t end = s_.find(quote, pos_ + 1);
    if (end == std::string_view::npos) return false;
    const std::string_view body = s_.substr(pos_ + 1, end - pos_ - 1);
    if (body.find_first_of("\\\n") != std::string_view::npos) return false;  // no escapes
    out.assign(body);
    pos_ = end + 1;
    return true;
  }
  std::optional<std::string> parse_shape(std::vector<std::size_t>& shape) {
    if (!eat('(')) return error("'shape' must be a tuple");
    bool last_had_comma = true;
    for (skip_ws(); !eat(')'); skip_ws()) {
      if (!last_had_comma) return error("expected ',' or ')' in 'shape'");
      if (!digit_at(pos_)) return error("expected a non-negative integer in 'shape'");
      if (s_[pos_] == '0' && digit_at(pos_ + 1)) return error("leading zero in 'shape'");
      std::size_t value = 0;
      for (; digit_at(pos_); ++pos_) {
        const auto digit = static_cast<std::size_t>(s_[pos_] - '0');
        if (value > (std::numeric_limits<std::size_t>::max() - digit) / 10) {
          return std::string("a 'shape' dimension is too large");
        }
        value = value * 10 + digit;
      }
      (void)eat('L');  // Python 2 era files wrote longs as "3L"
      if (shape.size() == kNpyMaxDims) return std::string("'shape' has too many dimensions");
      shape.push_back(value);
      skip_ws();
      last_had_comma = eat(',');
    }
    // "(3)" is the integer 3 in Python, not a tuple.
    if (shape.size() == 1 && !last_had_comma) return error("'shape' must be a tuple");
    return std::nullopt;
  }

  std::string_view s_;
  std::size_t pos_ = 0;
};

// Reads exactly n bytes; returns 0, an errno value, or -1 at a premature end of file.
int read_exact(int fd, void* buffer, std::size_t n) {
  auto* p = static_cast<unsigned char*>(buffer);
  while (n > 0) {
    const ssize_t r = ::read(fd, p, std::min(n, std::size_t{1} << 30));
    if (r < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    if (r == 0) return -1;
    p += r;
    n -= static_cast<std::size_t>(r);
  }
  return 0;
}

// "cannot read '<path>': <why>" with the given code.
Status read_failure(ErrorCode code, const std::filesystem::path& path, const std::string& why) {
  return {code, std::string("cannot read '").append(path.string()).append("': ").append(why)};
}

Result<NpyArray> read_fd(int fd, const std::filesystem::path& path) {
  const auto bad = [&](const std::string& problem) {
    return read_failure(ErrorCode::invalid_argument, path, problem);
  };
  const auto os_error = [&](int err) {
    return read_failure(ErrorCode::io_error, path, errno_message(err));
  };
  struct stat st {};
  if (::fstat(fd, &st) != 0) return os_error(errno);
  if (S_ISDIR(st.st_mode)) return os_error(EISDIR);
  if (!S_ISREG(st.st_mode)) return bad("not a regular file");
  const auto file_size = static_cast<std::uint64_t>(st.st_size);

  unsigned char prelude[kNpyPreludeLen] = {};
  const std::size_t got =
      static_cast<std::size_t>(std::min<std::uint64_t>(file_size, kNpyPreludeLen));
  if (const int err = read_exact(fd, prelude, got); err != 0) {
    return err > 0 ? os_error(err) : bad("file shrank while reading");
  }
  if (got < kNpyMagicLen || std::memcmp(prelude, kNpyMagic, kNpyMagicLen) != 0) {
    return bad("not a .npy file (wrong magic)");
  }
  if (got < kNpyPreludeLen) return bad("truncated header");
  if (prelude[6] != 1 || prelude[7] != 0) {
    return bad("npy format version " + std::to_string(prelude[6]) + "." +
               std::to_string(prelude[7]) + " is not supported (only 1.0)");
  }
  const std::size_t header_len = std::size_t{prelude[8]} | (std::size_t{prelude[9]} << 8U);
  if (file_size < kNpyPreludeLen + header_len) return bad("truncated header");
  std::string header(header_len, '\0');
  if (const int err = read_exact(fd, header.data(), header_len); err != 0) {
    return err > 0 ? os_error(err) : bad("truncated header");
  }

  NpyArray array;
  if (auto problem = HeaderParser(header).parse(array)) return bad(*problem);
  const std::optional<std::size_t> count = element_count(array.shape);
  if (!count) return bad("the size of 'shape' overflows");
  const std::uint64_t available = file_size - kNpyPreludeLen - header_len;
  const std::uint64_t expected = static_cast<std::uint64_t>(*count) * sizeof(float);
  if (available < expected) {
    return bad("truncated data: the shape needs " + std::to_string(expected) +
               " bytes after the header, the file has " + std::to_string(available));
  }
  if (available > expected) {
    return bad(std::to_string(available - expected) + " unexpected bytes after the data");
  }
  array.data.resize(*count);
  if (const int err = read_exact(fd, array.data.data(), expected); err != 0) {
    return err > 0 ? os_error(err) : bad("truncated data (the file shrank while reading)");
  }
  if constexpr (std::endian::native == std::endian::big) byte_swap(array.data);
  return array;
}

}  // namespace

Result<NpyArray> read_npy(const std::filesystem::path& path) {
  try {
    int fd = -1;
    do {
      fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    } while (fd < 0 && errno == EINTR);
    if (fd < 0) return read_failure(ErrorCode::io_error, path, errno_message(errno));
    struct Closer {
      int fd;
      ~Closer() { ::close(fd); }
    } closer{fd};
    return read_fd(closer.fd, path);
  } catch (const std::exception& e) {  // out of memory
    return read_failure(ErrorCode::io_error, path, e.what());
  }
}

}  // namespace ocean::io
