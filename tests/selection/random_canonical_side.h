#pragma once
// The random canonical side the select_scene tests share (test_select_scene.cpp,
// test_select_scene_record.cpp): 12 random colours, a 10% multiplicative expansion and the
// canonical light (9/10, 1, 11/10), prepared once for many scenes.

#include "../test_support.h"

#include <gmcc/selection/select_scene.h>

#include <vector>

namespace gmcc::test {

struct RandomCanonicalSide {
  std::vector<Colour> canonical;
  SelectSceneOptions options;
  PreparedCanonical prepared;
};

inline RandomCanonicalSide random_canonical_side(Rng& rng) {
  std::vector<Colour> canonical = random_colours(rng, 12, 1, 60, 7);
  SelectSceneOptions o;
  o.expansion = {ExpansionPolicy::multiplicative, Rational(1, 10)};
  o.canonical_illuminant = {Rational(9, 10), 1, Rational(11, 10)};
  PreparedCanonical pc = prepare_canonical(canonical, o);
  return {std::move(canonical), std::move(o), std::move(pc)};
}

}  // namespace gmcc::test
