// ocean/spectrum.hpp — ocean wave spectra, directional spreading, dispersion and the initial
// Fourier amplitudes h0(k). Pure CPU math: no GPU headers, no global state, thread-safe.
//
// Conventions (docs/conventions.md): SI units throughout; angular frequency ω in rad/s;
// wavenumber k in rad/m; one-sided frequency spectra S(ω) in m²·s/rad with m0 = ∫S(ω)dω the
// height variance; wave-vector spectra F(kx, kz) in m⁴ (variance per unit k-area) with
// ∫∫F dkx dkz = m0. Directions are angles in the horizontal x–z plane measured from +x towards
// +z (Y is up); a component's direction is where its waves travel TO. Equation numbers (M.n)
// refer to docs/math.md.
//
// Errors: every make_* function validates its parameters and returns a Status naming the
// parameter, its value and the valid range. Evaluation functions on validated objects never fail.
#pragma once

#include <array>
#include <complex>
#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>

#include "ocean/core.hpp"
#include "ocean/names.hpp"
#include "ocean/parameters.hpp"

namespace ocean {

inline constexpr double kPi = 3.14159265358979323846;
/// Default gravitational acceleration, m/s² (the value the source documents and DNV-RP-C205 use).
inline constexpr double kDefaultGravity = 9.81;
inline constexpr double kInfiniteDepth = std::numeric_limits<double>::infinity();
inline constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();

// ---------------------------------------------------------------------------------------------
// Dispersion (docs/math.md §2)
// ---------------------------------------------------------------------------------------------

struct DispersionParams {
  double gravity_mps2 = kDefaultGravity;  ///< g ∈ [0.1, 100]
  /// Water depth h ∈ [1e-100, ∞] m; infinity = deep water.
  double depth_m = kInfiniteDepth;
  /// Surface tension / density T ∈ [0, 1] m³/s² (σ/ρ; every liquid is below 1e-3); 0 = pure
  /// gravity waves; sea water 7.1e-5 (σ = 0.0728 N/m, ρ = 1025 kg/m³), kSeaWaterCapillarity.
  double capillarity_m3ps2 = 0.0;
};
inline constexpr double kSeaWaterCapillarity = 0.0728 / 1025.0;

/// A validated dispersion relation ω²(k) = (g·k + T·k³)·tanh(k·h)   (M.2.1)
///
/// Domain (M.2.5): k = 0 or k ∈ [kMinWavenumber, kMaxWavenumber]; ω = 0 or ω ∈ [min_omega(),
/// max_omega()]. On it every result is finite (positive for k, ω > 0), every intermediate a
/// normal double, and k(ω) the converged inverse; wavelengths from 6e-200 m to 6e200 m reach far
/// beyond any water wave. Outside is a precondition violation (asserted): check_wavenumber and
/// check_omega refuse a user's value there with the usual out-of-range message.
class Dispersion {
 public:
  static constexpr double kMinWavenumber = 1e-200;  ///< rad/m
  static constexpr double kMaxWavenumber = 1e200;   ///< rad/m

  /// Deep water, g = kDefaultGravity, no capillarity.
  Dispersion() = default;
  static Result<Dispersion> make(const DispersionParams& params);

  /// ω(k), rad/s; 0 at k = 0.
  [[nodiscard]] double omega(double k) const;
  /// Phase velocity c = ω/k, m/s, for k in the domain; at k = 0 its limit √(g·h) in finite
  /// depth (deep water has no finite limit: k = 0 is outside the domain there).
  [[nodiscard]] double phase_velocity(double k) const;
  /// Group velocity dω/dk, m/s (M.2.3), defined where phase_velocity is.
  [[nodiscard]] double group_velocity(double k) const;
  /// Inverse k(ω), rad/m: safeguarded Newton on ln ω(ln k) inside a bracket that provably holds
  /// the root (M.2.2); relative accuracy 1e-15. 0 at ω = 0.
  [[nodiscard]] double wavenumber(double omega) const;
  [[nodiscard]] const DispersionParams& params() const { return params_; }

  /// ω(kMinWavenumber) and ω(kMaxWavenumber), rad/s: the frequency domain.
  [[nodiscard]] double min_omega() const { return omega(kMinWavenumber); }
  [[nodiscard]] double max_omega() const { return omega(kMaxWavenumber); }
  /// ok when k ∈ [kMinWavenumber, kMaxWavenumber], else "<name> = <k> is out of range: ...".
  [[nodiscard]] static Status check_wavenumber(std::string_view name, double k);
  /// ok when ω ∈ [min_omega(), max_omega()], else "<name> = <ω> is out of range: ...".
  [[nodiscard]] Status check_omega(std::string_view name, double omega) const;

 private:
  DispersionParams params_;
};

/// Loop-period quantisation ω' = ⌊ω/ω0⌋·ω0, ω0 = 2π/T  (Aebi, VR Ocean, eq. 16, M.2.4). T > 0;
/// ω' = 0 (a wave that does not move) for ω < 2π/T.
double quantize_omega(double omega, double loop_period_s);

/// The evolution phase ω'·t of every wave vector at one time, exact for arbitrarily large t
/// (M.7.3): with a loop period T, ω' = j·2π/T and the phase is 2π·frac(j·frac(t/T)) in double
/// precision; without one, ω·t mod 2π, as exact as the double ω·t (t finite, |ω·t| < 1e300).
/// Exact while the harmonic j = ω'·T/2π stays below 2^53.
class EvolutionPhase {
 public:
  EvolutionPhase(double time_s, double loop_period_s);
  /// Phase in [0, 2π) for a (quantised, when looping) angular frequency, rad.
  [[nodiscard]] double operator()(double omega) const;

  // The same recipe split for vectorised evaluation: phase = 2π·frac(rate(ω, T)·clock()).
  /// Turns per unit of clock(): the integer harmonic j = ω'/ω0 when looping, ω/2π otherwise.
  [[nodiscard]] static double rate(double omega, double loop_period_s);
  /// frac(t/T) when looping, t otherwise.
  [[nodiscard]] double clock() const { return omega0_ > 0.0 ? tau_ : time_s_; }

 private:
  double time_s_;
  double omega0_ = 0.0;  // 2π/T, 0 without a loop
  double tau_ = 0.0;     // frac(t/T)
};

// ---------------------------------------------------------------------------------------------
// One-sided frequency spectra S(ω) (docs/math.md §3)
// ---------------------------------------------------------------------------------------------

enum class SpectrumModel { pierson_moskowitz, jonswap, tma, phillips };
/// Fetch law for the fetch-limited JONSWAP peak frequency.
enum class FetchLaw {
  hasselmann_1973,  ///< ωp = 2π·3.5·(g/U)·(gF/U²)^−0.33 (Hasselmann et al. 1973) — default
  cube_root,  ///< ωp = 22·(g²/(U·F))^(1/3) (Vincevičius 2024, eq. 1.9; ≈3 % lower at typical fetch)
};
/// Kitaigorodskii depth attenuation used by TMA.
enum class DepthFactor {
  exact,             ///< Φ from finite-depth dispersion (M.3.9)
  thompson_vincent,  ///< Thompson & Vincent's piecewise-quadratic approximation (M.3.10)
};
/// Normalisation of the Hs/Tp JONSWAP form.
enum class JonswapNormalization {
  dnv,    ///< A_γ = 1 − 0.287·ln γ (DNV-RP-C205 §3.5.5.2; exact to ~1 % for 1 ≤ γ ≤ 7)
  exact,  ///< numerically scaled so that 4·√m0 equals the requested Hs exactly
};

/// The names of the spectrum models, fetch laws, depth factors and normalisations in presets,
/// flags and messages (ocean::name_of, value_of, name_list read them).
inline constexpr std::array<EnumName<SpectrumModel>, 4> kSpectrumModelNames{{
    {SpectrumModel::pierson_moskowitz, "pierson-moskowitz"},
    {SpectrumModel::jonswap, "jonswap"},
    {SpectrumModel::tma, "tma"},
    {SpectrumModel::phillips, "phillips"},
}};
inline constexpr std::array<EnumName<FetchLaw>, 2> kFetchLawNames{{
    {FetchLaw::hasselmann_1973, "hasselmann"},
    {FetchLaw::cube_root, "cube-root"},
}};
inline constexpr std::array<EnumName<DepthFactor>, 2> kDepthFactorNames{{
    {DepthFactor::exact, "exact"},
    {DepthFactor::thompson_vincent, "thompson-vincent"},
}};
inline constexpr std::array<EnumName<JonswapNormalization>, 2> kJonswapNormalizationNames{{
    {JonswapNormalization::dnv, "dnv"},
    {JonswapNormalization::exact, "exact"},
}};

/// The model's name in kSpectrumModelNames.
std::string_view to_string(SpectrumModel model);
/// The model of a name in kSpectrumModelNames; invalid_argument listing the names otherwise.
Result<SpectrumModel> parse_spectrum_model(std::string_view name);

struct FrequencySpectrumParams {
  SpectrumModel model = SpectrumModel::jonswap;
  // Sea state, either (Hs, Tp) or wind (with fetch for JONSWAP/TMA).
  double significant_wave_height_m = kUnset;  ///< Hs = 4·√m0, m (with peak_period_s)
  double peak_period_s = kUnset;              ///< Tp, s
  /// Wind speed, m/s: U10 for JONSWAP/TMA/Phillips; U19.5 for Pierson–Moskowitz (their
  /// definition, Pierson & Moskowitz 1964).
  double wind_speed_mps = kUnset;
  double fetch_m = kUnset;  ///< JONSWAP/TMA from wind: fetch F, m (required there)
  /// JONSWAP peak enhancement γ ≥ 1. Unset = "auto": the DNV-RP-C205 rule γ(Tp/√Hs) in the
  /// Hs/Tp form, Hasselmann's mean 3.3 in the wind/fetch form.
  double gamma = kUnset;
  double sigma_a = 0.07;  ///< JONSWAP peak width for ω ≤ ωp
  double sigma_b = 0.09;  ///< JONSWAP peak width for ω > ωp
  FetchLaw fetch_law = FetchLaw::hasselmann_1973;
  JonswapNormalization normalization = JonswapNormalization::dnv;
  double depth_m = kInfiniteDepth;  ///< TMA only: water depth h, m
  DepthFactor depth_factor = DepthFactor::exact;
  double gravity_mps2 = kDefaultGravity;
  // Phillips only (Tessendorf 2001; Aebi, VR Ocean, §3.2).
  /// Dimensionless amplitude A ∈ (0, 1e6] of F(k) = A·e^(−1/(kL)²)/k⁴·D. Unset = calibrated so that
  /// Hs equals Pierson–Moskowitz's for the same wind without the cutoff (M.3.13).
  double phillips_amplitude = kUnset;
  double small_wave_cutoff_m = 0.0;  ///< l of the factor e^(−k²l²) (Aebi, VR Ocean, eq. 10), m ≥ 0
};

/// The default wind sea, m/s and m: U10 = 10 m/s (a fresh breeze) over a 100 km fetch, what
/// default_sea_state() (ocean/sim.hpp) simulates and what a spectrum given no sea state draws.
inline constexpr double kDefaultWindSpeedMps = 10.0;
inline constexpr double kDefaultFetchM = 100e3;

/// The sea state's numbers as every front end names them (ocean/parameters.hpp): the library's
/// field, the tool's flag, the Python keyword, the range FrequencySpectrum::make and
/// SpreadingParams check, and the doc line. The tool's help, its messages (fields rewritten to
/// flags in this order), Python's keywords and the library's checks read this one table.
inline constexpr std::array<params::ParameterDoc, 10> kSeaStateParameters{{
    {"significant_wave_height_m", "--hs", "hs", 1e-6, 50.0, "m",
     "significant wave height Hs, m (with --tp)"},
    {"peak_period_s", "--tp", "tp", 1e-3, 100.0, "s", "peak period Tp, s (with --hs)"},
    {"wind_speed_mps", "--wind-speed", "wind_speed", 1e-3, 100.0, "m/s",
     "wind speed, m/s: U10 (U19.5 for pierson-moskowitz)"},
    {"fetch_m", "--fetch", "fetch", 1.0, 1e8, "m", "fetch, m (jonswap/tma from wind)"},
    {"gamma", "--gamma", "gamma", 1.0, 20.0, "", "JONSWAP peak enhancement, >= 1, or 'auto'"},
    {"depth_m", "--depth", "depth", 1e-100, std::numeric_limits<double>::infinity(), "m",
     "water depth, m (tma)"},
    {"gravity_mps2", "--gravity", "gravity", 0.1, 100.0, "m/s^2",
     "gravitational acceleration, m/s^2 (default 9.81)"},
    {"phillips_amplitude", "--phillips-amplitude", "phillips_amplitude", 0.0, 1e6, "",
     "Phillips amplitude A (dimensionless; default: Hs of Pierson-Moskowitz)"},
    {"small_wave_cutoff_m", "--cutoff-length", "cutoff_length", 0.0,
     std::numeric_limits<double>::infinity(), "m",
     "Phillips small-wave cutoff length l, m (factor exp(-k^2 l^2))"},
    {"alpha", "--alpha", "alpha", 0.0, 1.0, "",
     "power-cosine wind alignment in [0,1]: s = 1 + 5 alpha^2, counter-wave energy 0.01 + "
     "0.49 (1 - alpha)^2"},
}};
/// The row of kSeaStateParameters for a field ("fetch_m").
constexpr const params::ParameterDoc& sea_state_parameter(std::string_view field) {
  return params::parameter(kSeaStateParameters, field);
}

/// A frequency spectrum as a front end gathers it: the names as given (kSpectrumModelNames,
/// kDepthFactorNames, kFetchLawNames, kJonswapNormalizationNames) and each number given or not
/// (gamma not given is "auto"). The defaults are the tool's.
struct SpectrumInputs {
  std::string_view model = "jonswap";
  std::optional<double> hs, tp, wind_speed, fetch, depth, gravity, phillips_amplitude,
      cutoff_length, gamma;
  std::string_view depth_factor = "exact";
  std::string_view fetch_law = "hasselmann";
  std::string_view normalization = "dnv";
};
/// The spectrum's parameters, checked later by FrequencySpectrum::make; errors name the flags
/// (kSeaStateParameters), in this order: an unknown model ("--model: ..."), a NaN number ("--hs
/// = nan must be a finite number"), an unknown name. With none of Hs, Tp and the wind speed
/// given, the default wind sea (kDefaultWindSpeedMps, and kDefaultFetchM for jonswap and tma when
/// no fetch is given); tma needs a depth.
Result<FrequencySpectrumParams> resolve(const SpectrumInputs& inputs);

/// A validated S(ω) with its derived constants resolved.
class FrequencySpectrum {
 public:
  static Result<FrequencySpectrum> make(const FrequencySpectrumParams& params);

  /// S(ω), m²·s/rad, for every ω ≥ 0 (0 at ω = 0): always finite, and exactly 0 where the
  /// value is below the smallest double (far below and far above the peak).
  [[nodiscard]] double operator()(double omega) const;
  [[nodiscard]] const FrequencySpectrumParams& params() const { return params_; }
  [[nodiscard]] double peak_omega() const { return omega_p_; }  ///< ωp, rad/s
  [[nodiscard]] double gamma() const { return gamma_; }         ///< γ in use (1 for PM/Phillips)
  [[nodiscard]] double alpha() const { return alpha_; }  ///< Phillips constant α (PM/JONSWAP wind)
  /// Spectral moment m_n = ∫ωⁿ S(ω) dω, −1 ≤ n ≤ 2, by Simpson's rule on a log grid (M.1.1;
  /// rel. err < 1e-7). An ω⁻⁵ tail makes m_n diverge for n ≥ 4 and converge slowly at n = 3.
  [[nodiscard]] double moment(int n) const;
  /// Significant wave height of the spectrum, 4·√m0.
  [[nodiscard]] double hs_m() const { return 4.0 * std::sqrt(moment(0)); }

 private:
  FrequencySpectrumParams params_;
  double omega_p_ = 0.0;  // peak angular frequency (JONSWAP/TMA/PM: ωp; Phillips: g/U ...)
  double alpha_ = 0.0;  // high-frequency level α (wind forms) or 5/16·Hs²·ωp⁴/g² (Hs/Tp forms)
  double gamma_ = 1.0;
  double scale_ = 1.0;  // JONSWAP normalisation A_γ (or exact factor)
  double phillips_a_ = 0.0;
  FrequencySpectrum() = default;
  double jonswap_shape(double omega) const;
};

// Closed forms, exposed for tests and tools (all one-sided, m²·s/rad). Their parameters are those
// FrequencySpectrum::make accepts (g ∈ [0.1, 100] m/s², U ∈ [1e-3, 100] m/s, Hs ∈ [1e-6, 50] m,
// Tp ∈ [1e-3, 100] s, F ∈ [1, 1e8] m, h ∈ [1e-100, ∞] m); every ω ≥ 0 is valid and gives a
// finite value, exactly 0 where the value is below the smallest double.
/// Pierson–Moskowitz, wind form: α·g²/ω⁵·exp(−β(g/(U·ω))⁴), α = 0.0081, β = 0.74  (M.3.1)
double pierson_moskowitz_wind(double omega, double wind_speed_mps, double gravity_mps2);
/// Bretschneider / PM Hs–Tp form: 5/16·Hs²·ωp⁴/ω⁵·exp(−5/4·(ωp/ω)⁴), ωp = 2π/Tp  (M.3.3)
double pierson_moskowitz_hs_tp(double omega, double hs_m, double tp_s);
/// DNV-RP-C205 peak-enhancement rule γ(Tp/√Hs)  (M.3.6)
double jonswap_gamma_dnv(double hs_m, double tp_s);
/// Hasselmann 1973 / Vincevičius 2024 fetch law: returns {α, ωp}  (M.3.7, M.3.8)
std::array<double, 2> jonswap_fetch_law(double wind_speed_mps, double fetch_m, double gravity_mps2,
                                        FetchLaw law);
/// Kitaigorodskii depth factor Φ(ω, h): exact (M.3.9) or Thompson–Vincent (M.3.10).
double tma_depth_factor(double omega, double depth_m, double gravity_mps2, DepthFactor factor);

// ---------------------------------------------------------------------------------------------
// Directional spreading D(ω, θ), ∫D dθ = 1 over (−π, π]  (docs/math.md §4)
// ---------------------------------------------------------------------------------------------

enum class SpreadingModel { power_cosine, cos2s, mitsuyasu, hasselmann, donelan_banner };
/// The names of the spreading models in presets, flags and messages.
inline constexpr std::array<EnumName<SpreadingModel>, 5> kSpreadingModelNames{{
    {SpreadingModel::power_cosine, "power-cosine"},
    {SpreadingModel::cos2s, "cos2s"},
    {SpreadingModel::mitsuyasu, "mitsuyasu"},
    {SpreadingModel::hasselmann, "hasselmann"},
    {SpreadingModel::donelan_banner, "donelan-banner"},
}};
/// The model's name in kSpreadingModelNames.
std::string_view to_string(SpreadingModel model);
/// The model of a name in kSpreadingModelNames; invalid_argument listing the names otherwise.
Result<SpreadingModel> parse_spreading_model(std::string_view name);

struct SpreadingParams {
  SpreadingModel model = SpreadingModel::donelan_banner;
  /// power_cosine: exponent of |cos θ|^s; unset = s(α) = 1 + 5α² (Aebi, VR Ocean, eq. 6).
  /// cos2s: exponent of cos^(2s)(θ/2) (required). Others: unused (frequency dependent).
  double s = kUnset;
  /// power_cosine: wind alignment α ∈ [0, 1]; sets s(α) when s is unset and the counter-wave
  /// energy fraction σ(α) = 0.01 + 0.49(1 − α)² (Aebi, VR Ocean, eq. 8) for |θ| > π/2.
  double alpha = 1.0;
  /// power_cosine: apply σ(α) to the back half-plane. false = symmetric |cos θ|^s
  /// (Tessendorf's classic |k̂·ŵ|^n).
  bool counter_wave_suppression = true;
};

/// Conditions that frequency-dependent models need.
struct SpreadingContext {
  double omega_p = kUnset;         ///< peak angular frequency, rad/s (ratio models)
  double wind_speed_mps = kUnset;  ///< U10 (Mitsuyasu s_max, Hasselmann U/cp)
  double gravity_mps2 = kDefaultGravity;
};

class Spreading {
 public:
  /// Validates params; context is required for mitsuyasu/hasselmann (ωp and U) and
  /// donelan_banner (ωp).
  static Result<Spreading> make(const SpreadingParams& params, const SpreadingContext& context);

  /// D(ω, θ), 1/rad; θ measured from the mean direction, any real value (wrapped to (−π, π]).
  [[nodiscard]] double operator()(double omega, double theta) const;
  /// The exponent of the model at ω (s for power-cosine/cos-2s families, β_s for Donelan–Banner).
  [[nodiscard]] double spread_parameter(double omega) const;
  [[nodiscard]] const SpreadingParams& params() const { return params_; }

 private:
  SpreadingParams params_;
  SpreadingContext context_;
  double s_max_ = 0.0;       // Mitsuyasu peak exponent
  double sigma_back_ = 1.0;  // power-cosine back-half energy fraction
  double norm_ = 1.0;        // power-cosine / cos2s constant normaliser
};

/// cos-2s normaliser G(s) = Γ(s+1)/(2√π·Γ(s+½)) so that ∫G·cos^(2s)(θ/2) dθ = 1, for every
/// finite s ≥ 0 (relative error < 1e-13)  (M.4.3)
double cos2s_normalization(double s);
/// ∫ over (−π, π] of |cos θ|^s with weight σ on |θ| > π/2: (1+σ)·√π·Γ((s+1)/2)/Γ(s/2+1), for
/// every finite s ≥ 0  (M.4.2)
double power_cosine_integral(double s, double sigma_back);
/// Donelan–Banner β_s(ω/ωp) (Donelan, Hamilton & Hui 1985; Banner 1990)  (M.4.6)
double donelan_banner_beta(double omega_ratio);

// ---------------------------------------------------------------------------------------------
// Sea state: wind sea (+ optional swell) and its wave-vector spectrum F(k)  (docs/math.md §5)
// ---------------------------------------------------------------------------------------------

/// One wave system: a frequency spectrum, a spreading and a mean direction.
struct WaveSystemParams {
  FrequencySpectrumParams spectrum;
  SpreadingParams spreading;
  double direction_rad = 0.0;  ///< mean direction waves travel towards, from +x towards +z
};

class WaveSystem {
 public:
  static Result<WaveSystem> make(const WaveSystemParams& params);
  const FrequencySpectrum& spectrum() const { return spectrum_; }
  const Spreading& spreading() const { return spreading_; }
  double direction_rad() const { return direction_rad_; }

 private:
  FrequencySpectrum spectrum_;
  Spreading spreading_;
  double direction_rad_ = 0.0;
  WaveSystem(FrequencySpectrum s, Spreading d, double dir)
      : spectrum_(std::move(s)), spreading_(std::move(d)), direction_rad_(dir) {}
};

struct SeaStateParams {
  WaveSystemParams wind_sea;
  bool has_swell = false;
  WaveSystemParams swell;  ///< used when has_swell; typically JONSWAP Hs/Tp with cos2s, s ≥ 10
  /// Dispersion used for ω(k) in the ω→k conversion (depth should match TMA's depth).
  DispersionParams dispersion;
};

class SeaState {
 public:
  static Result<SeaState> make(const SeaStateParams& params);

  /// Wave-vector spectrum F(kx, kz) = Σ_systems S(ω)·D(ω, θ − θ_mean)·(dω/dk)/k, m⁴  (M.5.1)
  /// (Vincevičius 2024, eq. 1.15 without its grid factors). 0 at k = 0.
  [[nodiscard]] double wave_vector_spectrum(double kx, double kz) const;
  /// Total height variance m0 of all systems, m².
  [[nodiscard]] double variance_m2() const;
  [[nodiscard]] const Dispersion& dispersion() const { return dispersion_; }
  [[nodiscard]] const std::vector<WaveSystem>& systems() const { return systems_; }

 private:
  std::vector<WaveSystem> systems_;
  Dispersion dispersion_;
  SeaState(std::vector<WaveSystem> systems, Dispersion d)
      : systems_(std::move(systems)), dispersion_(std::move(d)) {}
};

// ---------------------------------------------------------------------------------------------
// Deterministic Gaussian draws and initial amplitudes h0(k)  (docs/math.md §6)
// ---------------------------------------------------------------------------------------------

/// Two independent standard normal variates for (seed, index): a counter-based hash (SplitMix64
/// finaliser) gives two uniforms, Box–Muller (Aebi, VR Ocean, eq. 12) turns them into Gaussians.
/// Depends only on its arguments, never on call order or thread: identical across runs and
/// thread counts, and across machines whose C library computes log/sin/cos identically.
std::array<double, 2> gaussian_pair(std::uint64_t seed, std::uint64_t index);
/// A uniform variate in [0, 1) for (seed, index), from the same counter-based hash: 53 bits.
double uniform_draw(std::uint64_t seed, std::uint64_t index);

/// The square N×N grid of wave vectors of a periodic patch: k(m,n) = 2π/L·(m − N/2, n − N/2)
/// (Aebi, VR Ocean, eq. 2), index i = n·N + m (m along x, n along z).
struct SpectrumGrid {
  int resolution = 256;        ///< N, a power of two in [16, 4096]
  double patch_size_m = 1000;  ///< L, the patch side, m > 0
};
Status validate(const SpectrumGrid& grid);

/// How h0 is scaled.
enum class AmplitudeConvention {
  /// E|h0(k)|² = F(k)·Δk²/2, so E[h²] = Σ F·Δk² ≈ m0 for h = Σ h̃·e^{ik·x} with
  /// h̃ = h0(k) + h0*(−k)  (M.6.2). The default.
  variance_preserving,
  /// Aebi's VR-Ocean Phillips: h0 = ξ/√2·√(P'(k)), P' from eqs. 3–5, 7–11 with its grid
  /// normalisation A = N^(−1/2)·(e/L)²; only for SpectrumModel::phillips with power_cosine.
  vr_ocean,
};

struct InitialSpectrumParams {
  SpectrumGrid grid;
  std::uint64_t seed = 1;
  AmplitudeConvention convention = AmplitudeConvention::variance_preserving;
  /// Loop period T of the quantised dispersion (Aebi, VR Ocean, eq. 16), s; 0 = no quantisation.
  double loop_period_s = 200.0;
  /// The band of wavenumbers this patch synthesises, |k| ∈ [k_min, k_max) rad/m: cascades
  /// split the spectrum so that no wave vector is counted twice.
  double k_min_radpm = 0.0;
  double k_max_radpm = std::numeric_limits<double>::infinity();
};

/// Per-wave-vector data of Aebi, VR Ocean, eqs. 18–22, planar arrays of N² entries (index n·N + m).
struct InitialSpectrum {
  int resolution = 0;
  double patch_size_m = 0;
  /// Pre-transformed packed amplitudes S' = (a+c, b+d, b−d, c−a) where (a, b) = h0(k) and
  /// (c, d) = h0*(−k), so that h̃(k, t) = S'xy·cos ω't + S'zw·sin ω't   (M.6.5)
  std::vector<std::array<float, 4>> packed;
  std::vector<float> omega;  ///< ω'(k), rad/s, quantised if loop_period_s > 0; 0 at DC
  /// h0(k) itself in double precision (the oracle for tests and height statistics).
  std::vector<std::complex<double>> h0;
};

/// h0 for every grid wave vector. Deterministic for a given seed. Zero at DC (Aebi, VR Ocean, eq.
/// 14), outside the band, and on the Nyquist row and column (index 0), whose single aliased
/// component cannot carry the odd-symmetric displacement and slope fields (M.6.3).
Result<InitialSpectrum> make_initial_spectrum(const SeaState& sea, const InitialSpectrumParams& p);

/// The variance each grid wave vector of make_initial_spectrum's patch adds to the height in
/// expectation, 2·E|h0(k)|², m², row-major like InitialSpectrum::h0 (0 where h0 is): Σ of it is
/// E[h²] of the patch, Σ k²· of it the patch's mean square slope. Not a realisation: no seed.
/// The errors are make_initial_spectrum's.
Result<std::vector<double>> expected_wave_power(const SeaState& sea,
                                                const InitialSpectrumParams& p);

/// The VR-Ocean Phillips power P'(k) of Aebi, VR Ocean, eqs. 3–11 (directional factor applied once,
/// counter-wave factor σ(α) on the back half-plane).
struct VrOceanPhillipsParams {
  double wind_speed_mps = 10;        ///< V, m/s
  double wind_direction_rad = 0;     ///< ŵ, from +x towards +z
  double alpha = 1.0;                ///< alignment α ∈ [0, 1] (eqs. 6, 8)
  double small_wave_cutoff_m = 0.0;  ///< l_cutoff (eq. 10); see vr_ocean_cutoff_length
  double gravity_mps2 = kDefaultGravity;
};
double vr_ocean_phillips_power(double kx, double kz, const VrOceanPhillipsParams& p,
                               const SpectrumGrid& grid);
/// l_cutoff(β) = 0.001·(0.25·L/0.001)^β, m, for β ∈ [0, 1]  (Aebi, VR Ocean, eq. 11)
double vr_ocean_cutoff_length(double beta, double patch_size_m);

// ---------------------------------------------------------------------------------------------
// The waves shorter than a grid resolves: their slope variance  (docs/math.md §9)
// ---------------------------------------------------------------------------------------------

/// Mean-square slopes along and across the wind (Cox & Munk 1954's σu², σc²).
struct SlopeVariance {
  double upwind = 0.0;     ///< ⟨s_u²⟩, the slope component along the wind
  double crosswind = 0.0;  ///< ⟨s_c²⟩, across it
  [[nodiscard]] double total() const { return upwind + crosswind; }
};

/// What the short-wave slope variance is computed from.
struct ShortWaveParams {
  double wind_speed_mps = 10.0;  ///< U10, m/s, in [0.5, 60]
  /// The waves left out are those outside the square |k·x̂|, |k·ẑ| ≤ this, rad/m (a grid's
  /// Nyquist wavenumber π·N/L: the finest cascade's); 0 gives every wave's slope variance.
  double grid_nyquist_radpm = 0.0;
  double wind_direction_rad = 0.0;  ///< from +x towards +z; the square is the grid's
  /// Inverse wave age Ω = U10/c_p of the long waves (Elfouhaily et al. 1997, eq. 37): 0.84 for a
  /// fully developed sea; it shapes only waves near the peak.
  double inverse_wave_age = 0.84;
  double gravity_mps2 = kDefaultGravity;
};

/// The slope variance of the waves outside a grid's square of wave vectors, integrated over the
/// unified directional spectrum of Elfouhaily, Chapron, Katsaros & Vandemark (1997), "A unified
/// directional spectrum for long and short wind-driven waves", J. Geophys. Res. 102(C7): the
/// curvature spectrum B = B_l + B_h (eqs. 31–45: the long waves' and the gravity–capillary
/// waves' parts, friction velocity from U10 with Wu's drag coefficient) and the spreading
/// Φ = (1 + Δ(k)·cos 2φ)/2π (eqs. 49, 57). What a renderer adds to the slope variance of the
/// cascades it draws (docs/rendering.md R.5). Over every wave (grid_nyquist_radpm = 0) it is
/// the spectrum's own Cox–Munk figure. Errors: invalid_argument naming the field.
Result<SlopeVariance> short_wave_slope_variance(const ShortWaveParams& params);

/// Elfouhaily et al. (1997)'s omnidirectional curvature spectrum B(k) = k³·S(k) (eq. 30) and
/// spreading Δ(k) (eq. 57) at wavenumber k > 0, rad/m, for U10 and Ω of `params`.
struct CurvatureSample {
  double curvature = 0.0;  ///< B(k), dimensionless
  double spreading = 0.0;  ///< Δ(k) in [0, 1]: the up/crosswind contrast of cos 2φ
};
CurvatureSample elfouhaily_curvature(double k_radpm, const ShortWaveParams& params);

/// Phase speed of gravity–capillary waves in deep water, m/s: c = √(g/k·(1 + (k/k_m)²)),
/// k_m = 370 rad/m (Elfouhaily et al. 1997, eq. 4); the frequency is ω = k·c.
double capillary_gravity_phase_speed(double k_radpm, double gravity_mps2 = kDefaultGravity);

/// One wave of a sum of sines that stands in for a band of the short waves (docs/math.md M.9.4):
/// η = amplitude·cos(k·x − ω·t + phase).
struct ShortWaveComponent {
  double kx_radpm = 0.0, kz_radpm = 0.0;  ///< wave vector, rad/m
  double amplitude_m = 0.0;
  double omega_radps = 0.0;  ///< ω = k·c(k), gravity–capillary (eq. 4)
  double phase_rad = 0.0;    ///< at x = 0, t = 0
  /// Its mean-square slope (a·k)²/2: the share of the band's slope variance it carries.
  [[nodiscard]] double slope_variance() const;
};

/// What the components are drawn from: the band [k_min, k_max] of Elfouhaily et al.'s spectrum
/// (eqs. 30, 49, 57) for `waves`, split into `bins` equal steps of ln k with `per_bin` waves each.
struct ShortWaveComponentParams {
  ShortWaveParams waves;
  double k_min_radpm = 100.0;   ///< > 0
  double k_max_radpm = 3000.0;  ///< > k_min, ≤ 2·10⁴
  int bins = 16;                ///< [1, 64]
  int per_bin = 3;              ///< [1, 16]
  std::uint64_t seed = 1;
};

/// A band of the short waves as bins·per_bin sines (M.9.4), ordered by increasing k. Each ln-k bin
/// carries the band's slope variance over the bin, ∫B(k) d ln k (Simpson), shared equally by its
/// waves; a wave's k is drawn uniformly in ln k within its bin, its direction at the quantiles
/// (j + u)/per_bin (one u per bin) of the spreading Φ = (1 + Δ(k)·cos 2φ)/π over the half circle
/// φ ∈ [−π/2, π/2) about the wind (eq. 49; the waves run downwind), its phase uniform.
/// Deterministic in the seed. Errors: invalid_argument naming the field.
Result<std::vector<ShortWaveComponent>> short_wave_components(const ShortWaveComponentParams& p);

}  // namespace ocean
