#pragma once
/// \file image_lights.h
/// A file of images' true lights (docs/cli.md "gmcc canonical"; `--truths` of `gmcc estimate`
/// and `gmcc canonical --from-images`): a header `image,r,g,b`, then one line per image, its name
/// and its light's RGB as the camera sees it.

#include <gmcc/geometry/colour.h>
#include <gmcc/input/input_error.h>

#include <map>
#include <string>

namespace gmcc {

/// Read it: channels read exactly (parse_rational) and > 0, names unique; blank lines and `#`
/// lines skipped. \throws InputError naming the file and line.
std::map<std::string, Colour> read_image_lights(const std::string& path);

/// The light of the image at `image_path`: the line named as the path was given, else by its
/// file name. \throws InputError naming the light file and the image when there is none.
const Colour& light_of_image(const std::map<std::string, Colour>& lights,
                             const std::string& image_path, const std::string& lights_path);

}  // namespace gmcc
