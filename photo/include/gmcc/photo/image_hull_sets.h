#pragma once
/// \file image_hull_sets.h
/// An image's hull colour sets — the vertices of its colours' 3-D hull (Forsyth 1990 §3) and of
/// its chromaticity hull (Finlayson 1996 §2) — without finding its distinct colours: the kept
/// pixels stream once through a sieve (colour_hull_sieve.h) and only those it keeps are sorted
/// and handed to the exact hulls. For a caller that needs the hulls and not the count of distinct
/// colours (the dataset benchmark), at a full-size photograph's millions of distinct colours
/// (docs/photographs.md §6).
#include <gmcc/photo/image_pixels.h>

#include <vector>

namespace gmcc {

/// What image_colour_sets(image, rules, kept, sets) gives, colour for colour and in the same
/// order, with two counts left 0: `colours` (the distinct colours are not found) and
/// `no_chromaticity`. Each of `sets` must be ColourSet::hull_3d or ColourSet::hull; otherwise, and
/// with binning, a pre-filter or no kept pixel, this is image_colour_sets itself, counts and all.
///
/// The route: the kept pixels fall into 8 slabs of red (cut at the range of red of a sample of
/// about 2^18 kept pixels, every k-th pixel); each slab's colours extreme along 26 directions
/// among the sample's with b > 0 (S+, the colours with a chromaticity) span a hull Q inside
/// conv(S+) and so inside the image's hull (ExtremeColours: any colours of the image will do, the
/// sample's only make Q a little smaller); one pass over the kept pixels keeps the colours not
/// strictly inside their slab's Q, exactly (ColourHullSieve: integer channels below
/// 2^16). A colour strictly inside Q is in the interior of both conv(S+) and the image's hull, so
/// the colours kept hold every vertex of both (a colour with b = 0 is never inside Q, whose corners
/// have b >= 1). They are sorted; the exact 3-D hull takes them all (colour_hull_vertex_indices);
/// the chromaticity hull takes those with b > 0
/// (chromaticity_hull_of_pixels: the chromaticities (r/b, g/b) are a section of the cone S+ spans,
/// which the vertices of conv(S+) span). Memory: 8 bytes a colour the sieve keeps, not a kept
/// pixel.
/// \throws as image_colour_sets.
std::vector<ImageColours> image_hull_sets(const RgbImage& image, const PixelRules& rules, const KeptPixels& kept,
                                          const std::vector<ColourSet>& sets);

}  // namespace gmcc
