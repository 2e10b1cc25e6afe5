// Writes small colour-constancy datasets in the layouts they ship in, for tests/cli/test_datasets.py:
//   OUT/nus/TestCam_gt.mat (MATLAB 5, by libmatio's writer: all_image_names, groundtruth_illuminants,
//   darkness_level, saturation_level, CC_coords) and OUT/nus/PNG/<name>.PNG, and the same as
//   MATLAB 7.3 (HDF5) in OUT/nus73;
//   OUT/cube/cube+_gt.txt and OUT/cube/<k>.PNG (2060 × 1060, so that the SpyderCube corner exists);
// and, for each, OUT/<layout>_table.csv: the same dataset as a truth table with black_level,
// saturation and chart columns, written from what the tool drew (not from the readers).
//   make_datasets OUT
#include <gmcc/geometry/rational.h>
#include <gmcc/input/image_file.h>

#include <matio.h>

#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

using namespace gmcc;

namespace {

// An image of random surfaces under `light` above `black`, with one saturated pixel and a chart box
// (rows y1..y2, columns x1..x2, 1-based as MATLAB) painted white.
RgbImage draw(std::mt19937& rng, std::size_t w, std::size_t h, const double light[3], int black, int saturation,
              int y1, int y2, int x1, int x2) {
  RgbImage im;
  im.width = w;
  im.height = h;
  im.bits = 16;
  std::uniform_int_distribution<int> s(30, 900);
  for (std::size_t y = 0; y < h; ++y)
    for (std::size_t x = 0; x < w; ++x) {
      const int surface[3] = {s(rng), s(rng), s(rng)};
      const bool chart = int(y) + 1 >= y1 && int(y) + 1 <= y2 && int(x) + 1 >= x1 && int(x) + 1 <= x2;
      for (int c = 0; c < 3; ++c) {
        const int v = chart ? saturation - 1 : black + int(surface[c] * light[c]);
        im.samples.push_back(static_cast<std::uint16_t>(std::min(v, 65535)));
      }
    }
  for (int c = 0; c < 3; ++c) im.samples[3 * (w + 1) + c] = static_cast<std::uint16_t>(saturation);  // clipped
  return im;
}

// Write a variable and free it (Mat_VarWrite does not take ownership).
void put(mat_t* mat, matvar_t* var) {
  Mat_VarWrite(mat, var, MAT_COMPRESSION_NONE);
  Mat_VarFree(var);
}

void write(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// The light's doubles as exact rationals (the MATLAB file holds the doubles themselves).
std::string exact(const double e[3]) {
  return Rational(e[0]).get_str() + "," + Rational(e[1]).get_str() + "," + Rational(e[2]).get_str();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_datasets OUT\n");
    return 2;
  }
  const std::string out = argv[1];
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> l(2, 20);
  // NUS: 6 images, 40 × 30, black 512, saturation 15000.
  {
    const std::string dir = out + "/nus";
    std::system(("mkdir -p " + dir + "/PNG").c_str());
    const int n = 6, black = 512, saturation = 15000;
    std::vector<double> lights(3 * n), coords(4 * n);
    std::vector<std::string> names;
    std::ofstream table(out + "/nus_table.csv");
    table << "image,r,g,b,black_level,saturation,chart\n";
    for (int i = 0; i < n; ++i) {
      const double e[3] = {l(rng), l(rng), l(rng)};
      const int y1 = 3 + i, y2 = 10 + i, x1 = 20, x2 = 28 + i;  // 1-based, inclusive
      names.push_back("TestCam_" + std::to_string(1000 + i));
      write(dir + "/PNG/" + names.back() + ".PNG", encode_png16(draw(rng, 40, 30, e, black, saturation, y1, y2, x1, x2)));
      for (int k = 0; k < 3; ++k) lights[i + k * n] = e[k];  // column-major
      const double c[4] = {double(y1), double(y2), double(x1), double(x2)};
      for (int k = 0; k < 4; ++k) coords[i + k * n] = c[k];
      table << "PNG/" << names.back() << ".PNG," << exact(e) << "," << black << "," << saturation << ","
            << x1 - 1 << " " << y1 - 1 << " " << x2 + 1 << " " << y1 - 1 << " " << x2 + 1 << " " << y2 + 1 << " "
            << x1 - 1 << " " << y2 + 1 << "\n";
    }
    // The same ground truth as MATLAB 5 (what NUS ships) and, in OUT/nus73 beside copies of the
    // images, as MATLAB 7.3 (HDF5), the other route of the reader (issue 42).
    std::system(("mkdir -p " + out + "/nus73 && cp -r " + dir + "/PNG " + out + "/nus73/").c_str());
    for (const auto& [path, version] : {std::pair{dir + "/TestCam_gt.mat", MAT_FT_MAT5}, {out + "/nus73/TestCam_gt.mat", MAT_FT_MAT73}}) {
      mat_t* mat = Mat_CreateVer(path.c_str(), nullptr, version);
      std::size_t dims[2] = {std::size_t(n), 3};
      put(mat, Mat_VarCreate("groundtruth_illuminants", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, lights.data(), 0));
      dims[1] = 4;
      put(mat, Mat_VarCreate("CC_coords", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, coords.data(), 0));
      double b = black, s = saturation;
      std::size_t one[2] = {1, 1};
      put(mat, Mat_VarCreate("darkness_level", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, one, &b, 0));
      put(mat, Mat_VarCreate("saturation_level", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, one, &s, 0));
      std::size_t cell_dims[2] = {std::size_t(n), 1};
      matvar_t* cell = Mat_VarCreate("all_image_names", MAT_C_CELL, MAT_T_CELL, 2, cell_dims, nullptr, 0);
      for (int i = 0; i < n; ++i) {
        std::size_t d[2] = {1, names[i].size()};
        Mat_VarSetCell(cell, i, Mat_VarCreate(nullptr, MAT_C_CHAR, MAT_T_UINT8, 2, d, names[i].data(), 0));
      }
      Mat_VarWrite(mat, cell, MAT_COMPRESSION_NONE);
      Mat_VarFree(cell);
      Mat_Close(mat);
    }
  }
  // Cube+: 4 images, 2060 × 1060, black 2048; the SpyderCube corner (rows >= 1050, columns >= 2050)
  // painted bright.
  {
    const std::string dir = out + "/cube";
    std::system(("mkdir -p " + dir).c_str());
    std::ofstream gt(dir + "/cube+_gt.txt"), table(out + "/cube_table.csv");
    table << "image,r,g,b,black_level,chart\n";
    for (int i = 1; i <= 4; ++i) {
      const double e[3] = {l(rng), l(rng), l(rng)};
      RgbImage im = draw(rng, 2060, 1060, e, 2048, 65535, 1051, 1060, 2051, 2060);
      write(dir + "/" + std::to_string(i) + ".PNG", encode_png16(im));
      char light_text[200];
      std::snprintf(light_text, sizeof light_text, "%.17g %.17g %.17g", e[0], e[1], e[2]);
      gt << light_text << "\n";  // decimals, as the dataset ships them: read exactly as written
      std::snprintf(light_text, sizeof light_text, "%.17g,%.17g,%.17g", e[0], e[1], e[2]);
      table << i << ".PNG," << light_text << ",2048,2050 1050 2060 1050 2060 1060 2050 1060\n";
    }
  }
  // Gehler-Shi: 6 images (IMG_* of the Canon 5D, black 129; 8D5U* of the Canon 1D, black 0),
  // 48 × 32, the lights in real_illum_568.mat, chart corners in a half-size frame, and a split.
  {
    const std::string dir = out + "/gehler";
    std::system(("mkdir -p " + dir + "/png " + dir + "/coordinates").c_str());
    const std::vector<std::string> names = {"8D5U5524", "8D5U5525", "IMG_0301", "IMG_0302", "IMG_0303", "IMG_0304"};
    const int n = static_cast<int>(names.size());
    std::vector<double> lights(3 * n);
    std::ofstream table(out + "/gehler_table.csv"), folds(out + "/gehler_folds.csv");
    table << "image,r,g,b,black_level,chart\n";
    folds << "image,fold\n";
    for (int i = 0; i < n; ++i) {
      const double e[3] = {l(rng), l(rng), l(rng)};
      const int black = names[i].rfind("IMG", 0) == 0 ? 129 : 0;
      // The chart in image pixels: columns 30..44, rows 20..30 (1-based box for draw).
      write(dir + "/png/" + names[i] + ".png", encode_png16(draw(rng, 48, 32, e, black, 65535, 21, 30, 31, 44)));
      for (int k = 0; k < 3; ++k) lights[i + k * n] = e[k];
      // Corners in a 24 × 16 frame (half size), listed 1, 2, 4, 3 around the chart.
      std::ofstream(dir + "/coordinates/" + names[i] + "_macbeth.txt")
          << "24 16\n15 10\n22 10\n15 15\n22 15\n";
      table << "png/" << names[i] << ".png," << exact(e) << "," << black << ",30 20 44 20 44 30 30 30\n";
      folds << "png/" << names[i] << ".png," << (i % 3) << "\n";
    }
    mat_t* mat = Mat_CreateVer((dir + "/real_illum_568..mat").c_str(), nullptr, MAT_FT_MAT5);  // as shipped
    std::size_t dims[2] = {std::size_t(n), 3};
    put(mat, Mat_VarCreate("real_rgb", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, lights.data(), 0));
    Mat_Close(mat);
    mat = Mat_CreateVer((dir + "/threefoldCVsplit.mat").c_str(), nullptr, MAT_FT_MAT5);
    std::size_t cell_dims[2] = {1, 3};
    matvar_t* te = Mat_VarCreate("te_split", MAT_C_CELL, MAT_T_CELL, 2, cell_dims, nullptr, 0);
    for (int f = 0; f < 3; ++f) {
      std::vector<double> idx;
      for (int i = f; i < n; i += 3) idx.push_back(i + 1);  // 1-based
      std::size_t d[2] = {1, idx.size()};
      Mat_VarSetCell(te, f, Mat_VarCreate(nullptr, MAT_C_DOUBLE, MAT_T_DOUBLE, 2, d, idx.data(), 0));
    }
    Mat_VarWrite(mat, te, MAT_COMPRESSION_NONE);
    Mat_VarFree(te);
    Mat_Close(mat);
  }
  return 0;
}
