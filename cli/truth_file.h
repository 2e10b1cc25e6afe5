#pragma once
// A file of true lights for images (docs/cli.md "gmcc canonical"): a header `image,r,g,b`, then
// one line per image, its name and its light's RGB as the camera sees it.

#include <gmcc/geometry/colour.h>

#include <map>
#include <string>

namespace gmcc::cli {

/// Read it: channels read exactly and > 0, names unique; blank lines and `#` lines skipped.
/// \throws InputError naming the file and line.
std::map<std::string, Colour> read_truths(const std::string& path);

/// The light of the image at `image_path`: the line named as the path was given, else by its
/// file name. \throws InputError naming the truth file and the image when there is none.
const Colour& light_of_image(const std::map<std::string, Colour>& truths,
                             const std::string& image_path, const std::string& truths_path);

}  // namespace gmcc::cli
