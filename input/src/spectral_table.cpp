#include <gmcc/input/colour_csv.h>
#include <gmcc/input/spectral_table.h>
#include <gmcc/input/text_file.h>

#include <algorithm>
#include <sstream>
#include <utility>
#include <stdexcept>

namespace gmcc {
namespace {

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) {
    const auto a = field.find_first_not_of(" \t\r");
    const auto b = field.find_last_not_of(" \t\r");
    out.push_back(a == std::string::npos ? "" : field.substr(a, b - a + 1));
  }
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

}  // namespace

const Rational& Spectrum::at(const Rational& wavelength) const {
  const auto it = std::lower_bound(wavelengths.begin(), wavelengths.end(), wavelength);
  if (it == wavelengths.end() || *it != wavelength)
    throw std::out_of_range("spectrum '" + name + "' is not sampled at " + to_string(wavelength) +
                            " nm");
  return values[static_cast<std::size_t>(it - wavelengths.begin())];
}

const Spectrum& SpectralTable::spectrum(const std::string& name) const {
  for (const Spectrum& s : spectra)
    if (s.name == name) return s;
  throw InputError(file, 0, "no column named '" + name + "'");
}

SpectralTable parse_spectral_csv(const std::string& text, const std::string& file) {
  SpectralTable t;
  t.file = file;
  std::istringstream in(text);
  std::string line;
  std::size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos || line[0] == '#') continue;
    const std::vector<std::string> fields = split_fields(line);
    if (t.spectra.empty()) {  // the header
      if (fields.size() < 2 || fields[0] != "wavelength_nm")
        throw InputError(file, number, "expected a header 'wavelength_nm,NAME,...'");
      // Capped: a malformed file must not reserve more than its rows could fill.
      const auto rows = std::min<std::size_t>(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1, 4096);
      t.wavelengths.reserve(rows);
      t.spectra.reserve(fields.size() - 1);
      for (std::size_t j = 1; j < fields.size(); ++j) {
        t.spectra.push_back({fields[j], {}, {}});
        t.spectra.back().values.reserve(rows);
      }
      continue;
    }
    if (fields.size() != t.spectra.size() + 1)
      throw InputError(file, number, "expected " + std::to_string(t.spectra.size() + 1) +
                                         " values, found " + std::to_string(fields.size()));
    std::vector<Rational> row;
    row.reserve(fields.size());
    for (std::size_t j = 0; j < fields.size(); ++j) {
      try {
        row.push_back(parse_rational(fields[j]));
      } catch (const std::invalid_argument& e) {
        throw InputError(file, number, "column " + std::to_string(j + 1) + ": " + e.what());
      }
    }
    if (!t.wavelengths.empty() && row[0] <= t.wavelengths.back())
      throw InputError(file, number, "wavelengths must increase strictly");
    t.wavelengths.push_back(row[0]);
    for (std::size_t j = 1; j < row.size(); ++j) t.spectra[j - 1].values.push_back(std::move(row[j]));
  }
  if (t.spectra.empty() || t.wavelengths.empty())
    throw InputError(file, 0, "no spectral data (expected a header and rows)");
  for (Spectrum& s : t.spectra) s.wavelengths = t.wavelengths;
  return t;
}

SpectralTable read_spectral_csv(const std::string& path) {
  return parse_spectral_csv(
      read_text_file(path, {max_spectral_file_bytes, "spectral file",
                            "text rows wavelength_nm,value,..."}),
      path);
}

Spectrum resample(const Spectrum& s, const std::vector<Rational>& grid) {
  Spectrum out{s.name, grid, {}};
  for (const Rational& l : grid) {
    const auto it = std::lower_bound(s.wavelengths.begin(), s.wavelengths.end(), l);
    if (it == s.wavelengths.end() || (*it != l && it == s.wavelengths.begin()))
      throw std::out_of_range("spectrum '" + s.name + "' does not cover " + to_string(l) + " nm");
    const auto i = static_cast<std::size_t>(it - s.wavelengths.begin());
    if (*it == l) {
      out.values.push_back(s.values[i]);
      continue;
    }
    const Rational t = (l - s.wavelengths[i - 1]) / (s.wavelengths[i] - s.wavelengths[i - 1]);
    out.values.push_back(Rational(s.values[i - 1] + t * (s.values[i] - s.values[i - 1])));
  }
  return out;
}

}  // namespace gmcc
