#pragma once
// The sort of colour_set_of_doubles (image_pixels.cpp), reachable by its test
// (tests/photo/test_image_pixels.cpp, against std::sort). Internal to gmcc::photo.

#include <array>
#include <vector>

namespace gmcc::internal {

// Sorts colours lexicographically, as std::sort does: from 256 to 2^20 colours whose first
// channels are all >= +0 (no −0, no NaN), by a counting pass over buckets of the first channel's
// bit pattern (for such doubles the patterns, as unsigned integers, are in the values' order),
// each bucket then by std::sort, through one copy of the colours; otherwise by std::sort.
void sort_double_colours(std::vector<std::array<double, 3>>& colours);

}  // namespace gmcc::internal
