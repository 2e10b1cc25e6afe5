// Spectral data, CIE daylight and Planckian lights against published values.
#include <gmcc/validation/illuminants.h>
#include <gmcc/input/spectral_table.h>
#include <gmcc/validation/synthetic_experiment.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace gmcc;

namespace {
std::string data(const char* name) { return std::string(GMCC_DATA_DIR) + "/" + name; }
}  // namespace

BOOST_AUTO_TEST_SUITE(spectral_data)

BOOST_AUTO_TEST_CASE(shipped_tables_load_with_their_documented_shapes) {
  const SpectralTable munsell = read_spectral_csv(data("munsell_matt_1269_joensuu_5nm.csv"));
  BOOST_TEST(munsell.spectra.size() == 1269u);
  BOOST_TEST(munsell.wavelengths.size() == 81u);
  BOOST_TEST(munsell.spectrum("2.5R9/2").at(Rational(450)) == parse_rational("0.69482"));
  BOOST_TEST(read_spectral_csv(data("sfu_macbeth_24_4nm.csv")).spectra.size() == 24u);
  BOOST_TEST(read_spectral_csv(data("sfu_reflect_db_1995_4nm.csv")).spectra.size() == 1995u);
  const SpectralTable sony = read_spectral_csv(data("camera_sony_dxc930_sfu_4nm.csv"));
  BOOST_TEST(sony.wavelengths.size() == 101u);
  BOOST_TEST(sony.wavelengths.front() == Rational(380));
  BOOST_TEST(read_spectral_csv(data("sfu_lab_11_illuminants_4nm.csv")).spectra.size() == 11u);
}

BOOST_AUTO_TEST_CASE(parsing_is_exact_and_errors_name_the_line) {
  const SpectralTable t = parse_spectral_csv("wavelength_nm,a,b\n400,0.1,1/3\n410,0.2,2\n", "t.csv");
  BOOST_TEST(t.spectrum("b").at(Rational(400)) == Rational(1, 3));
  BOOST_TEST(t.spectrum("a").at(Rational(410)) == Rational(1, 5));
  BOOST_CHECK_THROW(t.spectrum("c"), InputError);
  BOOST_CHECK_THROW(t.spectrum("a").at(Rational(405)), std::out_of_range);
  auto message = [](const std::string& text) {
    try {
      parse_spectral_csv(text, "t.csv");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  BOOST_TEST(message("wavelength_nm,a\n400,1\n400,2\n").find("t.csv:3:") == 0u);
  BOOST_TEST(message("wavelength_nm,a\n400,1,2\n").find("t.csv:2:") == 0u);
  BOOST_TEST(message("lambda,a\n400,1\n").find("t.csv:1:") == 0u);
  BOOST_TEST(message("wavelength_nm,a\n400,x\n").find("t.csv:2:") == 0u);
}

BOOST_AUTO_TEST_CASE(resampling_interpolates_exactly) {
  const Spectrum s{"s", {Rational(400), Rational(410)}, {Rational(1), Rational(2)}};
  const Spectrum r = resample(s, {Rational(400), Rational(403), Rational(410)});
  BOOST_TEST(r.values[1] == Rational(13, 10));
  BOOST_CHECK_THROW(resample(s, {Rational(420)}), std::out_of_range);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(illuminant_spectra)

BOOST_AUTO_TEST_CASE(cie_rule_temperatures) {
  BOOST_TEST(std::round(cie_daylight_cct(5500).get_d()) == 5503);
  BOOST_TEST(std::round(cie_daylight_cct(7500).get_d()) == 7504);
  BOOST_TEST(std::round(cie_daylight_cct(10000).get_d()) == 10006);
}

// CIE 15's tabulated D55, D65, D75 (data/cie_illuminants_A_D50_D55_D65_D75.csv) are the basis
// method with M1, M2 rounded to three decimals: the computed spectra must match the table.
BOOST_AUTO_TEST_CASE(daylight_from_the_basis_matches_the_cie_tables) {
  const SpectralTable basis = read_spectral_csv(data("cie_daylight_basis_S0_S1_S2.csv"));
  const SpectralTable table = read_spectral_csv(data("cie_illuminants_A_D50_D55_D65_D75.csv"));
  for (const char* name : {"D55", "D65", "D75"}) {
    const int nominal = std::stoi(std::string(name).substr(1)) * 100;
    const Spectrum d = cie_daylight(cie_daylight_cct(nominal), basis);
    BOOST_TEST(d.at(Rational(560)) == Rational(100));
    double worst = 0;
    for (const Rational& l : table.wavelengths)
      worst = std::max(worst, std::fabs(Rational(d.at(l) - table.spectrum(name).at(l)).get_d()));
    BOOST_TEST(worst <= 0.002, name << " differs from CIE 15 by " << worst);
  }
  BOOST_CHECK_THROW(cie_daylight(3000, basis), std::domain_error);
}

BOOST_AUTO_TEST_CASE(planckian_follows_plancks_law) {
  const std::vector<Rational> w{Rational(450), Rational(560), Rational(575), Rational(580),
                                Rational(585), Rational(610)};
  const Spectrum p = planckian(5000, w);
  BOOST_TEST(p.at(Rational(560)) == Rational(100));
  // An independent double evaluation of the ratio P(450)/P(610).
  auto planck = [](double nm, double T) { return std::pow(nm, -5) / std::expm1(1.4388e-2 / (nm * 1e-9 * T)); };
  BOOST_TEST(Rational(p.at(Rational(450)) / p.at(Rational(610))).get_d() == planck(450, 5000) / planck(610, 5000),
             boost::test_tools::tolerance(1e-12));
  // Wien: the peak of a 5000 K radiator is at 2.8978e-3/5000 m ≈ 579.6 nm.
  BOOST_TEST(p.at(Rational(580)) > p.at(Rational(575)));
  BOOST_TEST(p.at(Rational(580)) > p.at(Rational(585)));
}

// Issue 13: P1e-5 divided by zero (every value underflowed to 0) and P0.0001 took gigabytes (exact
// powers of e^-(10^8)). The named lights now stop at documented limits, with the name in the
// message; at the limits themselves every sensor sees a positive, modest amount of light.
BOOST_AUTO_TEST_CASE(named_lights_within_their_limits) {
  const SpectralTable basis = read_spectral_csv(data("cie_daylight_basis_S0_S1_S2.csv"));
  for (const char* bad : {"P1e-5", "P1e-400", "P0.0001", "P1/3", "P999.99", "P100000.01", "P1e6", "D39", "D250",
                          "D1000"}) {
    try {
      named_light(bad, basis);
      BOOST_ERROR(std::string(bad) + " accepted");
    } catch (const std::domain_error& e) {
      BOOST_TEST(std::string(e.what()).find(bad) != std::string::npos, e.what());
    }
  }
  for (const char* bad : {"P", "P0", "P-5", "Px", "Q100", "D0"})
    BOOST_CHECK_THROW(named_light(bad, basis), std::invalid_argument);
  for (const char* good : {"P1000", "P100000", "D40", "D249"}) {
    const Spectrum s = named_light(good, basis);
    for (const Rational& w : narrow_band_wavelengths) {
      const Rational v = s.at(w);
      BOOST_TEST(sgn(v) > 0, good);
      BOOST_TEST(v.get_num().get_str().size() + v.get_den().get_str().size() < 400u, good);
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
