// numerics/may_be_largest.h: the one "may still be the largest" filter, over double midpoint–
// radius enclosures and x87 intervals of known exact values (the independent answer).
#include "../test_support.h"

#include <gmcc/geometry/rational_enclosure.h>
#include <gmcc/numerics/may_be_largest.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <limits>
#include <vector>

using namespace gmcc;
using gmcc::numerics::LDInterval;
using gmcc::numerics::may_be_largest;
using gmcc::test::Rng;
using gmcc::test::random_rational;

namespace {

bool has(const std::vector<std::size_t>& v, std::size_t i) { return std::find(v.begin(), v.end(), i) != v.end(); }

// Exact values on a grid (ties occur), enclosed in kind X by `of`; `nan` is a NaN-touched X.
template <class X, class Of>
void check(Of of, const X& nan) {
  Rng rng(43);
  for (int trial = 0; trial < 500; ++trial) {
    std::vector<Rational> exact;
    std::vector<X> values;
    for (int k = 0; k < 1 + trial % 9; ++k) {
      exact.push_back(random_rational(rng, -20, 20, trial % 2 ? 4 : 1 << 30));
      values.push_back(of(exact.back()));
    }
    const std::vector<std::size_t> kept = may_be_largest(values);
    const Rational top = *std::max_element(exact.begin(), exact.end());
    for (std::size_t i = 0; i < exact.size(); ++i) {
      if (exact[i] == top) BOOST_TEST(has(kept, i));  // every largest value, ties included
      if (!has(kept, i)) {  // dropped only when certainly below another value
        bool below = false;
        for (const X& other : values) below = below || upper(values[i]) < lower(other);
        BOOST_TEST(below);
      }
    }
    BOOST_TEST(std::is_sorted(kept.begin(), kept.end()));
    // A NaN-touched value, first or last, is kept and changes nothing else.
    for (bool first : {true, false}) {
      std::vector<X> with_nan = values;
      with_nan.insert(first ? with_nan.begin() : with_nan.end(), nan);
      std::vector<std::size_t> expected;
      if (first) expected.push_back(0);
      for (std::size_t i : kept) expected.push_back(first ? i + 1 : i);
      if (!first) expected.push_back(values.size());
      BOOST_TEST((may_be_largest(with_nan) == expected));
    }
    // A slack keeps more, never less.
    const std::vector<std::size_t> wide = may_be_largest(values, 0.5);
    for (std::size_t i : kept) BOOST_TEST(has(wide, i));
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(may_be_largest_suite)

BOOST_AUTO_TEST_CASE(keeps_every_largest_and_drops_only_the_certainly_smaller) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  check<Enclosure>([](const Rational& q) { return enclose_rational(q); }, Enclosure{nan, 0});
  // x87 intervals built directly around the nearest double (valid as enclosures everywhere:
  // they are widened by a relative 2^-40).
  check<LDInterval>(
      [](const Rational& q) {
        const long double d = mpq_get_d(q.get_mpq_t());
        return LDInterval::around(d, d, 0x1p-40L);
      },
      LDInterval{std::numeric_limits<long double>::quiet_NaN(), std::numeric_limits<long double>::quiet_NaN()});
}

BOOST_AUTO_TEST_CASE(slack_lowers_the_floor_relatively) {
  // Values 1, 0.9, 0.5 exactly: with slack 0.2 the floor is 0.8, so 0.9 stays and 0.5 goes.
  const std::vector<Enclosure> v{Enclosure::exact(1), Enclosure::exact(0.9), Enclosure::exact(0.5)};
  BOOST_TEST((may_be_largest(v) == std::vector<std::size_t>{0}));
  BOOST_TEST((may_be_largest(v, 0.2) == std::vector<std::size_t>{0, 1}));
  const std::vector<Enclosure> neg{Enclosure::exact(-1), Enclosure::exact(-1.1), Enclosure::exact(-2)};
  BOOST_TEST((may_be_largest(neg, 0.2) == std::vector<std::size_t>{0, 1}));  // floor −1.2
}

BOOST_AUTO_TEST_SUITE_END()
