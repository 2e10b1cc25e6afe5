#include "integer_option.h"

#include <gmcc/geometry/rational.h>
#include <gmcc/input/colour_csv.h>

#include <stdexcept>

namespace gmcc::cli {

std::uint64_t integer_option(const std::string& name, const std::string& text, std::uint64_t lo,
                             std::uint64_t hi) {
  const std::string wanted =
      "must be an integer from " + std::to_string(lo) + " to " + std::to_string(hi);
  Rational value;
  try {
    value = parse_rational(text);
  } catch (const std::invalid_argument&) {  // its message would ask for a decimal or p/q
    throw InputError(name, 0, wanted + ", not " + quoted_text(text));
  }
  if (value.get_den() != 1 || value < Rational(mpz_class(std::to_string(lo))) ||
      value > Rational(mpz_class(std::to_string(hi))))
    throw InputError(name, 0, wanted + ", not " + quoted_text(text));
  return std::stoull(value.get_num().get_str());
}

}  // namespace gmcc::cli
