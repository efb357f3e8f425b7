// src/waves/kelvin_table.hpp — the steady Kelvin wake of one (U, L) on a table in the object's
// frame, computed once (W.5–W.7) and sampled bilinearly per frame.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace ocean::waves::detail {

/// What a table is computed for. Values are assumed valid (LocalLayer::make checks them).
struct KelvinTableSpec {
  double speed_mps = 5.0;       ///< U
  double hull_length_m = 10.0;  ///< L
  double gravity_mps2 = 9.81;   ///< g
  double spacing_m = 1.0;       ///< wanted cell size (the layer's); grown if the table gets too big
  double length_m = 100.0;      ///< distance behind the object the table covers
  double fade_m = 10.0;         ///< the pattern fades out over the table's last fade_m (W.7)
};

/// The most cells (s, ζ) a table holds: 2^24, 192 MiB of (h, D_s, D_ζ) floats. A table that
/// would hold more at the wanted spacing is computed on a coarser one (W.7).
inline constexpr std::size_t kMaxKelvinTableCells = std::size_t{1} << 24;
/// The longest lateral transform: four transforms of fft::kMaxSize (W.5).
inline constexpr int kMaxKelvinLateral = 16384;

class KelvinTable {
 public:
  /// Computes the pattern (W.5–W.7), normalised so that its largest |height| is 1.
  static KelvinTable make(const KelvinTableSpec& spec);

  /// (h, D_s, D_ζ) at s metres behind the object and ζ metres to its left (ζ along the heading
  /// turned +90°), with D_s along s (backwards): bilinear in the table, 0 outside it (ahead of
  /// the object, beyond its length or width). Never allocates.
  [[nodiscard]] std::array<double, 3> sample(double s, double zeta) const;

  [[nodiscard]] double speed_mps() const { return spec_.speed_mps; }
  [[nodiscard]] double hull_length_m() const { return spec_.hull_length_m; }
  [[nodiscard]] double gravity_mps2() const { return spec_.gravity_mps2; }
  [[nodiscard]] double length_m() const { return spec_.length_m; }
  [[nodiscard]] double fade_m() const { return spec_.fade_m; }
  /// The spacing the spec asked for (spacing_m() may be larger).
  [[nodiscard]] double requested_spacing_m() const { return spec_.spacing_m; }
  [[nodiscard]] double spacing_m() const { return spacing_m_; }
  /// 2πU²/g, the wavelength of the transverse waves.
  [[nodiscard]] double transverse_wavelength_m() const;
  /// True when the transverse waves are shorter than the table resolves (the table is then 0).
  [[nodiscard]] bool unresolved() const { return unresolved_; }
  /// The pattern's largest |height| before it was normalised, for the amplitude function
  /// A(θ) = (k·a)²·p̂(k)/p̂(0) of W.4 (η = −∫A·sin ψ dθ, W.3): the peak of a pattern whose
  /// amplitude function is c·A is c·raw_peak() (W.24).
  [[nodiscard]] double raw_peak() const { return raw_peak_; }
  /// ∫_{−π/2}^{π/2} A(θ)²·cos³θ dθ of that A (W.24).
  [[nodiscard]] static double pattern_energy(const KelvinTableSpec& spec);

 private:
  KelvinTableSpec spec_;
  double spacing_m_ = 1.0;
  int rows_ = 0;  ///< s = row·spacing, row ∈ [0, rows)
  bool unresolved_ = false;
  double raw_peak_ = 0.0;
  /// Row r holds ζ = col·spacing for col ∈ [0, row_start_[r + 1] − row_start_[r]) (the pattern
  /// is mirror-symmetric): the wedge and its Airy tail, 0.45·s + 2·2πU²/g + L, widening with s.
  std::vector<std::size_t> row_start_;
  std::vector<float> values_;  ///< (h, D_s, D_ζ) per cell, index row_start_[row] + col
};

}  // namespace ocean::waves::detail
