#pragma once
/// \file image_hull_sets.h
/// An image's hull colour sets — the vertices of its colours' 3-D hull (Forsyth 1990 §3) and of
/// its chromaticity hull (Finlayson 1996 §2) — without finding its distinct colours: the kept
/// pixels stream twice through a sieve (colour_hull_sieve.h) and only those it keeps are sorted
/// and handed to the exact hulls. For a caller that needs the hulls and not the count of distinct
/// colours (the dataset benchmark), at a full-size photograph's millions of distinct colours
/// (docs/photographs.md §6).
#include <gmcc/photo/image_pixels.h>

#include <vector>

namespace gmcc {

/// What image_colour_sets(image, rules, kept, sets) gives, colour for colour and in the same
/// order, with two counts left 0: `colours` (the distinct colours are not found) and
/// `no_chromaticity`. Each of `sets` must be ColourSet::hull_3d or ColourSet::hull; otherwise, and
/// with binning, a pre-filter, no kept pixel, or (for ColourSet::hull) a kept pixel whose blue
/// channel is 0 after the black level, this is image_colour_sets itself, counts and all.
///
/// The route: one pass over the kept pixels finds the colours extreme along 26 directions, whose
/// hull Q lies inside the image's (ExtremeColours); a second keeps the colours not strictly inside
/// Q, exactly (ColourHullSieve: integer channels below 2^16); those are sorted and the exact 3-D
/// hull takes them (colour_hull_vertex_indices: a colour strictly inside Q is no vertex, so its
/// vertices are the image's). The chromaticity hull is that of the 3-D hull's vertices: the
/// chromaticities (r/b, g/b) of colours with b > 0 are a section of the cone they span, and a cone
/// spanned by a set is spanned by its hull's vertices (chromaticity_hull_of_pixels on them).
/// Memory: 8 bytes a colour the sieve keeps, not a kept pixel.
/// \throws as image_colour_sets.
std::vector<ImageColours> image_hull_sets(const RgbImage& image, const PixelRules& rules, const KeptPixels& kept,
                                          const std::vector<ColourSet>& sets);

}  // namespace gmcc
