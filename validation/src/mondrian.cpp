#include <gmcc/validation/mondrian.h>

#include <array>
#include <random>
#include <stdexcept>

namespace gmcc {
namespace {

// floor(q + ½) for q >= 0.
std::uint32_t round_half_up(const Rational& q) {
  const Rational shifted = q + Rational(1, 2);
  mpz_class f;
  mpz_fdiv_q(f.get_mpz_t(), shifted.get_num_mpz_t(), shifted.get_den_mpz_t());
  return static_cast<std::uint32_t>(f.get_ui());
}

}  // namespace

Mondrian render_mondrian(const std::vector<Colour>& colours, const MondrianSpec& spec) {
  if (colours.empty()) throw std::invalid_argument("render_mondrian: no colours");
  if (spec.width == 0 || spec.height == 0 || spec.columns == 0 || spec.rows == 0 ||
      spec.columns > spec.width || spec.rows > spec.height)
    throw std::invalid_argument("render_mondrian: sizes must be positive, cells at most pixels");
  if (spec.peak == 0 || std::uint64_t(spec.black_level) + spec.peak > 65534)
    throw std::invalid_argument("render_mondrian: black level + peak must be 1 to 65534");
  std::seed_seq seq{spec.seed};
  std::mt19937_64 g(seq);
  Mondrian m;
  m.surfaces.resize(spec.columns * spec.rows);
  for (std::size_t& s : m.surfaces) s = static_cast<std::size_t>(g() % colours.size());
  Rational brightest = 0;
  for (std::size_t s : m.surfaces)
    for (const Rational* c : {&colours[s].r, &colours[s].g, &colours[s].b})
      if (*c > brightest) brightest = *c;
  if (sgn(brightest) <= 0)
    throw std::invalid_argument("render_mondrian: every colour shown is black");
  const Rational scale = Rational(spec.peak) / brightest;
  std::vector<std::array<std::uint16_t, 3>> cell_samples;
  for (std::size_t s : m.surfaces) {
    const Colour& c = colours[s];
    cell_samples.push_back(
        {static_cast<std::uint16_t>(spec.black_level + round_half_up(c.r * scale)),
         static_cast<std::uint16_t>(spec.black_level + round_half_up(c.g * scale)),
         static_cast<std::uint16_t>(spec.black_level + round_half_up(c.b * scale))});
  }
  RgbImage& im = m.image;
  im.width = spec.width;
  im.height = spec.height;
  im.bits = 16;
  im.samples.resize(spec.width * spec.height * 3);
  for (std::size_t y = 0; y < spec.height; ++y) {
    const std::size_t row = y * spec.rows / spec.height;
    for (std::size_t x = 0; x < spec.width; ++x) {
      const std::size_t column = x * spec.columns / spec.width;
      const auto& v = cell_samples[row * spec.columns + column];
      for (int c = 0; c < 3; ++c)
        im.samples[(y * spec.width + x) * 3 + static_cast<std::size_t>(c)] = v[c];
    }
  }
  for (std::size_t k = 0; k < spec.saturated_pixels; ++k) {
    const std::size_t p = static_cast<std::size_t>(g() % (spec.width * spec.height));
    for (int c = 0; c < 3; ++c) im.samples[p * 3 + static_cast<std::size_t>(c)] = 65535;
  }
  return m;
}

}  // namespace gmcc
