// Inverse FFT: radix-2 decimation-in-time Cooley–Tukey, 1D and separable 2D.
//
// This work is based on:
//   - Cooley, J. W. & Tukey, J. W. (1965) An algorithm for the machine calculation of complex
//     Fourier series. Math. Comp. 19(90).
//   - Aebi, VR Ocean, §3.6: bit-reversed load (eq. 36), butterflies (eqs. 32, 34–35), local
//     buffers (eq. 38), dual-spectrum processing (eq. 39), column gather/scatter (eqs. 40–41),
//     sign correction (eqs. 42–43).
// Convention: x[n] = Σ_k X[k]·e^{+2πi·k·n/N} (docs/conventions.md).
#include "ocean/fft.hpp"

#include <bit>
#include <cmath>
#include <string>

namespace ocean::fft {

namespace {
Status validate_size(int n) {
  if (n < 2 || n > kMaxSize || !std::has_single_bit(static_cast<unsigned>(n))) {
    return invalid_argument("FFT size = " + std::to_string(n) +
                            " is out of range: must be a power of two in [2, " +
                            std::to_string(kMaxSize) + "]");
  }
  return {};
}
}  // namespace

Result<Plan1D> Plan1D::make(int n) {
  if (Status s = validate_size(n); !s.ok()) return s;
  Plan1D plan;
  plan.n_ = n;
  plan.log2n_ = std::countr_zero(static_cast<unsigned>(n));
  const auto size = static_cast<std::size_t>(n);
  plan.bit_reverse_.resize(size);
  // Reverse the low log2 N bits (Aebi, VR Ocean, eq. 36).
  for (std::uint32_t i = 0; i < size; ++i) {
    std::uint32_t r = 0;
    for (int b = 0; b < plan.log2n_; ++b) r |= ((i >> b) & 1u) << (plan.log2n_ - 1 - b);
    plan.bit_reverse_[i] = r;
  }
  plan.twiddle_re_.resize(size / 2);
  plan.twiddle_im_.resize(size / 2);
  for (std::size_t t = 0; t < size / 2; ++t) {
    const double angle = 2.0 * 3.14159265358979323846 * static_cast<double>(t) / n;
    plan.twiddle_re_[t] = static_cast<float>(std::cos(angle));
    plan.twiddle_im_[t] = static_cast<float>(std::sin(angle));
  }
  return plan;
}

void Plan1D::load_bit_reversed(const float* src_re, const float* src_im, std::ptrdiff_t stride,
                               float* dst_re, float* dst_im) const {
  for (int i = 0; i < n_; ++i) {
    const std::ptrdiff_t from =
        static_cast<std::ptrdiff_t>(bit_reverse_[static_cast<std::size_t>(i)]) * stride;
    dst_re[i] = src_re[from];
    dst_im[i] = src_im[from];
  }
}

void Plan1D::butterflies(std::span<const SplitComplex> local) const {
  // Stage p combines pairs at distance m = 2^p with twiddle W^(j·N/2m), W = e^{2πi/N}.
  for (int half = 1, step = n_ / 2; half < n_; half *= 2, step /= 2) {
    for (int group = 0; group < n_; group += 2 * half) {
      for (int j = 0; j < half; ++j) {
        const float wr = twiddle_re_[static_cast<std::size_t>(j * step)];
        const float wi = twiddle_im_[static_cast<std::size_t>(j * step)];
        const int a = group + j;
        const int b = a + half;
        for (const SplitComplex& s : local) {  // same twiddle for every plane (eq. 39)
          const float br = s.re[b] * wr - s.im[b] * wi;
          const float bi = s.re[b] * wi + s.im[b] * wr;
          const float ar = s.re[a];
          const float ai = s.im[a];
          s.re[a] = ar + br;
          s.im[a] = ai + bi;
          s.re[b] = ar - br;
          s.im[b] = ai - bi;
        }
      }
    }
  }
}

void Plan1D::inverse(std::span<const SplitComplex> signals) const {
  std::vector<float> re(static_cast<std::size_t>(n_));
  std::vector<float> im(static_cast<std::size_t>(n_));
  for (const SplitComplex& s : signals) {
    load_bit_reversed(s.re, s.im, 1, re.data(), im.data());
    const SplitComplex local{re.data(), im.data()};
    butterflies({&local, 1});
    for (int i = 0; i < n_; ++i) {
      s.re[i] = re[static_cast<std::size_t>(i)];
      s.im[i] = im[static_cast<std::size_t>(i)];
    }
  }
}

Result<Plan2D> Plan2D::make(int n) {
  Result<Plan1D> plan = Plan1D::make(n);
  if (!plan.ok()) return plan.status();
  Plan2D p;
  p.plan_ = std::move(plan).value();
  return p;
}

void Plan2D::inverse(std::span<const SplitComplex> planes, TaskRunner& runner,
                     bool sign_correct) const {
  const int n = plan_.size();
  const std::size_t count = planes.size();
  // One pass over rows (stride 1) or columns (stride N). Local buffers live on the stack:
  // kMaxPlanes·2·kMaxSize floats = 256 KiB at most (Aebi, VR Ocean, §3.6.5).
  const auto pass = [&](bool columns) {
    runner.parallel_for(static_cast<std::size_t>(n), 4, [&](std::size_t begin, std::size_t end) {
      float local_re[kMaxPlanes][kMaxSize];
      float local_im[kMaxPlanes][kMaxSize];
      SplitComplex local[kMaxPlanes];
      for (std::size_t p = 0; p < count; ++p) local[p] = {local_re[p], local_im[p]};
      const std::ptrdiff_t stride = columns ? n : 1;
      for (std::size_t line = begin; line < end; ++line) {
        const std::ptrdiff_t origin =
            columns ? static_cast<std::ptrdiff_t>(line) : static_cast<std::ptrdiff_t>(line) * n;
        for (std::size_t p = 0; p < count; ++p) {
          plan_.load_bit_reversed(planes[p].re + origin, planes[p].im + origin, stride, local_re[p],
                                  local_im[p]);
        }
        plan_.butterflies({local, count});
        for (std::size_t p = 0; p < count; ++p) {
          for (int i = 0; i < n; ++i) {
            float scale = 1.0f;
            // (−1)^(x+y): x + y is line + i on either pass (eq. 43, branch-free parity test).
            if (columns && sign_correct)
              scale = ((line + static_cast<std::size_t>(i)) & 1u) ? -1.0f : 1.0f;
            planes[p].re[origin + i * stride] = local_re[p][i] * scale;
            planes[p].im[origin + i * stride] = local_im[p][i] * scale;
          }
        }
      }
    });
  };
  pass(false);
  pass(true);
}

}  // namespace ocean::fft
