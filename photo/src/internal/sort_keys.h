#pragma once
// The in-place key sort of image_colours, reachable by its test (tests/photo/test_image_pixels.cpp,
// against std::sort). Internal to gmcc::photo.

#include <cstdint>
#include <vector>

namespace gmcc::internal {

// Sorts keys below 2^48 ascending in place (American flag sort; McIlroy, Bostic & McIlroy 1993),
// each bucket of at most 2^20 keys through a buffer of its size: how image_colours sorts its
// colour keys with at most 8 MiB more than they take (issue 42).
void sort_keys_in_place(std::vector<std::uint64_t>& keys);

}  // namespace gmcc::internal
