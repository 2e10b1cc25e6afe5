#pragma once
/// \file spectral_table.h
/// Spectral data files: a wavelength column and one column per sample (reflectances, SPDs,
/// sensor sensitivities), read exactly (data/SOURCES.md gives provenance and units).

#include <gmcc/geometry/rational.h>
#include <gmcc/input/input_error.h>

#include <cstddef>
#include <string>
#include <vector>

namespace gmcc {

/// Largest spectral file accepted, in bytes (the shipped ones are below 1.5 MiB).
inline constexpr std::size_t max_spectral_file_bytes = std::size_t(256) << 20;

/// One sampled spectrum: values at strictly increasing wavelengths (nm), exact.
struct Spectrum {
  std::string name;  ///< its column's header
  std::vector<Rational> wavelengths;  ///< in nm, strictly increasing
  std::vector<Rational> values;  ///< values[i] at wavelengths[i] (reflectance, relative power or sensitivity)

  /// The value at a sampled wavelength. \throws std::out_of_range if λ is not sampled.
  const Rational& at(const Rational& wavelength) const;
};

/// A spectral CSV: header `wavelength_nm,NAME,…`, one row per wavelength (strictly increasing).
struct SpectralTable {
  std::string file;  ///< the file's name as given
  std::vector<Rational> wavelengths;  ///< the first column, nm, strictly increasing; shared by every spectrum
  std::vector<Spectrum> spectra;  ///< in column order

  /// The spectrum named `name`. \throws InputError naming the file if there is none.
  const Spectrum& spectrum(const std::string& name) const;
};

/// Parse spectral CSV text exactly (decimals as rationals). `file` names it in messages.
/// \throws InputError (%file:line) on a bad header, ragged rows, malformed numbers, or
///         wavelengths that do not strictly increase.
SpectralTable parse_spectral_csv(const std::string& text, const std::string& file);

/// Read and parse a spectral CSV file (read_text_file: any kind of file, NUL bytes and files
/// beyond max_spectral_file_bytes rejected). \throws InputError.
SpectralTable read_spectral_csv(const std::string& path);

/// The spectrum linearly interpolated onto `grid` (exact rational interpolation between the two
/// neighbouring samples). \throws std::out_of_range if the grid leaves the sampled range.
Spectrum resample(const Spectrum& s, const std::vector<Rational>& grid);

}  // namespace gmcc
