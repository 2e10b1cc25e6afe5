#include <gmcc/photo/image_rules.h>

#include <gmcc/input/input_error.h>

namespace gmcc {

ImagePixelRules image_pixel_rules(const TruthRow& row) {
  ImagePixelRules own;
  own.black_level = row.black_level;
  own.saturation = row.saturation;
  if (!row.chart.empty()) own.exclude_polygons.push_back(row.chart);
  return own;
}

ImageLevels levels_to_read(const RunPixelRules& run, const ImagePixelRules& own) {
  ImageLevels levels;
  levels.run_black = run.rules.black_level;
  if (run.black_level_given) levels.black = run.rules.black_level;
  levels.saturation = run.rules.saturation;
  if (own.black_level) levels.black = own.black_level;
  if (own.saturation) levels.saturation = own.saturation;
  return levels;
}

PixelRules rules_for_image(const RunPixelRules& run, const ImagePixelRules& own, const CameraImage& read,
                           const std::string& path, const RgbImage* mask, const std::string& mask_path) {
  PixelRules rules = run.rules;
  rules.black_level = read.black_level;
  if (read.saturation) rules.saturation = read.saturation;
  // Neither the run nor the image gave a saturation (a raw file's white level is given or its own).
  if (run.saturation_max && !run.rules.saturation && !own.saturation)
    rules.saturation = (1u << read.image.bits) - 1;
  rules.exclude_polygons.insert(rules.exclude_polygons.end(), own.exclude_polygons.begin(),
                                own.exclude_polygons.end());
  if (mask) {
    const RgbImage& image = read.image;
    if (mask->width != image.width || mask->height != image.height)
      throw InputError(path, 0,
                       "the mask is " + std::to_string(mask->width) + "x" + std::to_string(mask->height) +
                           (mask_path.empty() ? std::string() : " (" + mask_path + ")") + ", this image " +
                           std::to_string(image.width) + "x" + std::to_string(image.height));
    rules.keep.resize(image.width * image.height);
    for (std::size_t p = 0; p < rules.keep.size(); ++p)
      rules.keep[p] = mask->samples[3 * p] || mask->samples[3 * p + 1] || mask->samples[3 * p + 2];
  }
  return rules;
}

}  // namespace gmcc
