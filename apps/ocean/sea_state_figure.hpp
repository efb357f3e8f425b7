// The sea-state figure: spectra, spreading, depth attenuation and dispersion in one picture.
#pragma once

#include "ocean/spectrum.hpp"
#include "plot/plot.hpp"

namespace ocean::cli {

/// A 2×2 figure for the given sea state: S(ω) of the chosen model beside the other families for
/// the same wind or Hs/Tp; the five spreading functions at ωp; TMA's depth factor (exact vs
/// Thompson–Vincent); wavelength against period for several depths.
Result<plot::Figure> make_sea_state_figure(const FrequencySpectrumParams& chosen);

}  // namespace ocean::cli
