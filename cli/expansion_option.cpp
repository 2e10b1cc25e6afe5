#include "expansion_option.h"

#include <gmcc/geometry/option_error.h>
#include <gmcc/geometry/rational.h>
#include <gmcc/input/input_error.h>

#include <stdexcept>

namespace gmcc::cli {

Expansion expansion_option(const std::string& factor, const std::string& policy) {
  Expansion x;
  try {
    x.policy = expansion_policy_from_string(policy);
  } catch (const std::invalid_argument& e) {
    throw InputError("--expand-policy", 0, e.what());
  }
  try {
    x.factor = parse_rational(factor);
    check_options(x);
  } catch (const OptionError& e) {
    throw InputError(e.option == "expand" ? "--expand" : "--expand-policy", 0, e.what());
  } catch (const std::invalid_argument& e) {
    throw InputError("--expand", 0, e.what());
  }
  return x;
}

}  // namespace gmcc::cli
