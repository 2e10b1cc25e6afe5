#include <gmcc/input/camera_image.h>

#include <gmcc/input/raw_file.h>

namespace gmcc {

RgbImage read_camera_image(const std::string& path, const ImageLevels& levels, PixelRules& rules,
                           RawImage* raw_metadata) {
  if (is_raw_file_name(path)) {
    RawImage raw = read_raw_image(path, RawLevels{levels.black, levels.saturation});
    rules.black_level = 0;
    rules.saturation = raw_saturated_value;
    RgbImage image = std::move(raw.image);
    if (raw_metadata) *raw_metadata = std::move(raw);
    return image;
  }
  RgbImage image = read_image(path);
  if (levels.black) rules.black_level = *levels.black;
  if (levels.saturation) rules.saturation = *levels.saturation;
  return image;
}

}  // namespace gmcc
