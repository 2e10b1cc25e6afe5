#include <gmcc/input/camera_image.h>

#include <gmcc/input/raw_file.h>

namespace gmcc {

RgbImage read_camera_image(const std::string& path, const ImageLevels& levels, PixelRules& rules) {
  if (is_raw_file_name(path)) {
    RawImage raw = read_raw_image(path, RawLevels{levels.black, levels.saturation});
    rules.black_level = 0;
    rules.saturation = raw_saturated_value;
    return std::move(raw.image);
  }
  RgbImage image = read_image(path);
  if (levels.black) rules.black_level = *levels.black;
  if (levels.saturation) rules.saturation = *levels.saturation;
  return image;
}

}  // namespace gmcc
