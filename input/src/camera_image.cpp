#include <gmcc/input/camera_image.h>

#include <gmcc/input/raw_file.h>
#include <gmcc/input/text_file.h>

#include <mutex>

namespace gmcc {
namespace {

std::mutex& levels_mutex() {
  static std::mutex m;
  return m;
}
std::vector<ImageLevelsUsed>& levels_log() {
  static std::vector<ImageLevelsUsed> used;
  return used;
}
void record_levels(ImageLevelsUsed used) {
  const std::lock_guard<std::mutex> lock(levels_mutex());
  for (const ImageLevelsUsed& seen : levels_log())
    if (seen.path == used.path) return;
  levels_log().push_back(std::move(used));
}

}  // namespace

std::vector<ImageLevelsUsed> image_levels_used() {
  const std::lock_guard<std::mutex> lock(levels_mutex());
  return levels_log();
}

RgbImage read_camera_image(const std::string& path, const ImageLevels& levels, PixelRules& rules,
                           RawImage* raw_metadata) {
  const std::string bytes = read_binary_file(path, max_image_file_bytes, "image file");
  if (is_raw_file_name(path) || is_raw_file_content(bytes)) {
    RawImage raw = decode_raw_image(bytes, path, RawLevels{levels.black, levels.saturation});
    rules.black_level = 0;
    rules.saturation = raw_saturated_value;
    record_levels({path, {raw.black.begin(), raw.black.end()}, raw.white, raw.black_given ? "given" : "file",
                   raw.white_given ? "given" : "file"});
    RgbImage image = std::move(raw.image);
    if (raw_metadata) *raw_metadata = std::move(raw);
    return image;
  }
  RgbImage image = decode_image(bytes, path);
  if (levels.black) rules.black_level = *levels.black;
  if (levels.saturation) rules.saturation = *levels.saturation;
  record_levels({path, {rules.black_level}, levels.saturation, levels.black ? "given" : "run",
                 levels.saturation ? "given" : "run"});
  return image;
}

}  // namespace gmcc
