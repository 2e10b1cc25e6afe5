#include "dataset_layouts.h"

#include "mat_file.h"

#include <gmcc/geometry/rational.h>
#include <gmcc/input/file_digest.h>
#include <gmcc/input/input_error.h>
#include <gmcc/input/text_file.h>

#include <dlfcn.h>
#include <matio.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <cmath>
#include <filesystem>
#include <memory>
#include <set>
#include <sstream>
#include <type_traits>

namespace gmcc {
namespace {

namespace fs = std::filesystem;

// The image `stem` with one of these endings, in `dir` or `dir/PNG`, as a path relative to dir.
std::string find_image(const fs::path& dir, const std::string& stem, const std::string& listed_in) {
  for (const char* sub : {"", "PNG"})
    for (const char* ending : {".PNG", ".png"}) {
      const fs::path p = fs::path(sub) / (stem + ending);
      if (fs::exists(dir / p)) {
        require_regular_file((dir / p).string(), "image");
        return p.string();
      }
    }
  throw InputError(listed_in, 0, "no image " + stem + ".PNG in " + dir.string() + " or its PNG/ folder");
}

// libmatio, loaded on the first MATLAB 7.3 (HDF5) file rather than linked: linking it loads
// HDF5, libcurl and GnuTLS into every gmcc process, about 8 ms of start-up that every other
// command paid (docs/performance-history.md "Start-up"). MATLAB 5 files (what the datasets ship) are read
// by mat_file.h from the bytes gmcc read itself. GMCC_MATIO_SONAME is the soname of the libmatio
// the build found (input/datasets/CMakeLists.txt); its header gives the types and signatures.
struct Matio {
  decltype(&::Mat_Open) open = nullptr;
  decltype(&::Mat_Close) close = nullptr;
  decltype(&::Mat_VarRead) read = nullptr;
  decltype(&::Mat_VarReadInfo) read_info = nullptr;
  decltype(&::Mat_VarFree) free = nullptr;
  decltype(&::Mat_VarGetCell) cell = nullptr;
};

// libmatio's last message (it would print it on stderr), quoted in gmcc's error instead.
thread_local std::string matio_message;
void keep_matio_message(int, char* message) { matio_message = message ? message : ""; }

Matio load_matio(const std::string& file) {
  void* lib = dlopen(GMCC_MATIO_SONAME, RTLD_NOW | RTLD_LOCAL);
  if (!lib) {
    const char* why = dlerror();
    throw InputError(file, 0, std::string("reading a MATLAB file needs libmatio (" GMCC_MATIO_SONAME "), which did not load: ") +
                                  (why ? why : "unknown reason"));
  }
  Matio m;
  auto get = [&](auto& f, const char* name) {
    f = reinterpret_cast<std::remove_reference_t<decltype(f)>>(dlsym(lib, name));
    if (!f) throw InputError(file, 0, std::string(GMCC_MATIO_SONAME " has no ") + name);
  };
  get(m.open, "Mat_Open");
  get(m.close, "Mat_Close");
  get(m.read, "Mat_VarRead");
  get(m.read_info, "Mat_VarReadInfo");
  get(m.free, "Mat_VarFree");
  get(m.cell, "Mat_VarGetCell");
  // One line per error, always gmcc's: libmatio's log goes to keep_matio_message, and HDF5's
  // automatic printing of its error stack (14 lines for a truncated file) is turned off.
  // (Both looked up, not required: a libmatio without Mat_LogInitFunc still reads the file.)
  if (auto log_init = reinterpret_cast<decltype(&::Mat_LogInitFunc)>(dlsym(lib, "Mat_LogInitFunc")))
    log_init("gmcc", keep_matio_message);
  using SetAuto = int (*)(std::int64_t, void*, void*);  // H5Eset_auto2(H5E_DEFAULT = 0, NULL, NULL)
  if (auto set_auto = reinterpret_cast<SetAuto>(dlsym(lib, "H5Eset_auto2"))) set_auto(0, nullptr, nullptr);
  return m;  // the library stays loaded for the process
}

// The loaded library (loaded once; `file` names the MATLAB file in an error).
const Matio& matio(const std::string& file) {
  static const Matio m = load_matio(file);
  return m;
}

struct MatFile {
  mat_t* mat = nullptr;
  ~MatFile() {
    if (mat) matio("").close(mat);
  }
};
struct MatVar {
  matvar_t* var = nullptr;
  ~MatVar() {
    if (var) matio("").free(var);
  }
};

template <class T>
void append(const void* data, std::size_t n, std::vector<double>& out) {
  const T* p = static_cast<const T*>(data);
  for (std::size_t i = 0; i < n; ++i) out.push_back(static_cast<double>(p[i]));
}

// A libmatio variable as a MatArray, every count checked against the bytes libmatio holds.
MatArray array_of(const matvar_t* v, const std::string& file, int depth) {
  MatArray a;
  if (depth > 8) throw InputError(file, 0, "cells nested more than 8 deep");
  std::size_t n = 1;
  for (int k = 0; k < v->rank; ++k) {
    a.dims.push_back(v->dims[k]);
    n *= v->dims[k];
  }
  a.complex = v->isComplex != 0;
  auto hold = [&](std::size_t size) {
    if (n != 0 && (!v->data || v->nbytes / size < n))
      throw InputError(file, 0, "an array of " + std::to_string(n) + " elements holds fewer");
  };
  switch (v->class_type) {
    case MAT_C_CELL:
      a.kind = MatArray::cell;
      hold(sizeof(matvar_t*));
      for (std::size_t i = 0; i < n; ++i) {
        const matvar_t* c = matio(file).cell(const_cast<matvar_t*>(v), static_cast<int>(i));
        if (!c) throw InputError(file, 0, "a missing cell");
        a.cells.push_back(array_of(c, file, depth + 1));
      }
      return a;
    case MAT_C_CHAR: {
      a.kind = MatArray::chars;
      const bool wide = v->data_type == MAT_T_UINT16 || v->data_type == MAT_T_UTF16;
      hold(wide ? 2 : 1);
      for (std::size_t i = 0; i < n; ++i) {
        const unsigned c = wide ? static_cast<const std::uint16_t*>(v->data)[i] : static_cast<const unsigned char*>(v->data)[i];
        a.text += c < 128 ? static_cast<char>(c) : '?';
      }
      return a;
    }
    case MAT_C_DOUBLE: hold(8); a.kind = MatArray::numeric; append<double>(v->data, n, a.numbers); return a;
    case MAT_C_SINGLE: hold(4); a.kind = MatArray::numeric; append<float>(v->data, n, a.numbers); return a;
    case MAT_C_UINT16: hold(2); a.kind = MatArray::numeric; append<std::uint16_t>(v->data, n, a.numbers); return a;
    case MAT_C_INT16: hold(2); a.kind = MatArray::numeric; append<std::int16_t>(v->data, n, a.numbers); return a;
    case MAT_C_UINT32: hold(4); a.kind = MatArray::numeric; append<std::uint32_t>(v->data, n, a.numbers); return a;
    case MAT_C_INT32: hold(4); a.kind = MatArray::numeric; append<std::int32_t>(v->data, n, a.numbers); return a;
    case MAT_C_UINT8: hold(1); a.kind = MatArray::numeric; append<std::uint8_t>(v->data, n, a.numbers); return a;
    default: a.kind = MatArray::other; return a;
  }
}

// The variables `names` of a MATLAB 7.3 (HDF5) file, through libmatio: each one's declared size
// checked against what the file's bytes can hold (deflate's 1032:1) before it is read.
std::map<std::string, MatArray> mat73_variables(const std::string& file, std::size_t file_bytes,
                                                const std::vector<const char*>& names) {
  matio_message.clear();
  MatFile mat{matio(file).open(file.c_str(), MAT_ACC_RDONLY)};
  if (!mat.mat) throw InputError(file, 0, "not a MATLAB file libmatio reads" + (matio_message.empty() ? "" : ": " + matio_message));
  std::map<std::string, MatArray> out;
  for (const char* name : names) {
    matio_message.clear();
    MatVar info{matio(file).read_info(mat.mat, name)};
    if (!info.var) {
      // Absent, or HDF5 could not read the file as far as the variable (a truncated file).
      if (!matio_message.empty()) throw InputError(file, 0, std::string(name) + ": unreadable (" + matio_message + ")");
      continue;
    }
    double declared = 8;
    for (int k = 0; k < info.var->rank; ++k) declared *= static_cast<double>(info.var->dims[k]);
    if (declared > 1032.0 * static_cast<double>(file_bytes) + 4096)
      throw InputError(file, 0, std::string(name) + ": declares more values than the file's " + std::to_string(file_bytes) + " bytes can hold");
    MatVar m{matio(file).read(mat.mat, name)};
    if (!m.var) throw InputError(file, 0, std::string(name) + ": unreadable" + (matio_message.empty() ? "" : " (" + matio_message + ")"));
    out.emplace(name, array_of(m.var, file, 0));
  }
  return out;
}

// The variables of the MATLAB file `file`, read whole by gmcc (a regular file: a FIFO or device
// is refused, since libmatio would open it again) within `max_bytes`; `names` are those a
// MATLAB 7.3 file is asked for (a MATLAB 5 file's are all read).
std::map<std::string, MatArray> mat_variables(const std::string& file, std::size_t max_bytes, const char* noun,
                                              const std::vector<const char*>& names) {
  require_regular_file(file, noun);
  const std::string bytes = read_binary_file(file, max_bytes, noun);
  if (is_mat5(bytes)) return read_mat5(bytes, file);
  if (bytes.size() > 520 && bytes.compare(512, 8, "\x89HDF\r\n\x1a\n") == 0) return mat73_variables(file, bytes.size(), names);
  throw InputError(file, 0, "not a MATLAB 5 or 7.3 MAT-file");
}

// "no variable NAME", and for a MATLAB 7.3 file that HDF5 reads only in part, that it may be damaged.
std::string no_variable(const char* name, const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  char head[10] = {};
  in.read(head, sizeof head);
  return std::string("no variable ") + name +
         (std::string(head, sizeof head) == "MATLAB 7.3" ? " (or the MATLAB 7.3 file is truncated or damaged)" : "");
}

// A real numeric matrix's values as doubles, column-major, with its rows and columns.
struct Numbers {
  std::size_t rows = 0, cols = 0;
  std::vector<double> v;
  double at(std::size_t i, std::size_t j) const { return v[i + j * rows]; }
};

Numbers numbers_of(const MatArray& a, const char* name, const std::string& file) {
  if (a.dims.size() != 2 || a.complex) throw InputError(file, 0, std::string(name) + ": expected a real matrix");
  if (a.kind != MatArray::numeric) throw InputError(file, 0, std::string(name) + ": expected numbers");
  for (double x : a.numbers)
    if (!std::isfinite(x)) throw InputError(file, 0, std::string(name) + ": a value that is not finite");
  return Numbers{a.dims[0], a.dims[1], a.numbers};
}

Numbers numbers(const std::map<std::string, MatArray>& vars, const char* name, const std::string& file) {
  const auto it = vars.find(name);
  if (it == vars.end()) throw InputError(file, 0, no_variable(name, file));
  return numbers_of(it->second, name, file);
}

// Text for a message: control characters as '?', at most 80 characters.
std::string printable(const std::string& s) {
  std::string out;
  for (char c : s.substr(0, 80)) out += static_cast<unsigned char>(c) < 32 || c == 127 ? '?' : c;
  return s.size() > 80 ? out + "…" : out;
}

// A level (black or saturation) as an integer code 0..65535.
std::uint32_t level(const Numbers& x, const char* name, const std::string& file) {
  if (x.v.size() != 1) throw InputError(file, 0, std::string(name) + ": expected one number");
  const double v = x.v[0];
  if (v < 0 || v > 65535 || v != std::floor(v))
    throw InputError(file, 0, std::string(name) + ": expected an integer code from 0 to 65535");
  return static_cast<std::uint32_t>(v);
}

}  // namespace

std::vector<TruthRow> read_nus_camera(const std::string& dir_text) {
  const fs::path dir(dir_text);
  std::vector<fs::path> found;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.size() > 7 && name.compare(name.size() - 7, 7, "_gt.mat") == 0) found.push_back(e.path());
  }
  if (ec) throw InputError(dir_text, 0, "cannot read the folder: " + ec.message());
  if (found.size() != 1)
    throw InputError(dir_text, 0, found.empty() ? "no <camera>_gt.mat (a NUS camera folder)" : "several *_gt.mat files");
  const std::string file = found[0].string();
  const std::map<std::string, MatArray> vars =
      mat_variables(file, mat_max_file_bytes, "ground-truth file",
                    {"groundtruth_illuminants", "CC_coords", "darkness_level", "saturation_level", "all_image_names"});
  const Numbers lights = numbers(vars, "groundtruth_illuminants", file);
  const Numbers coords = numbers(vars, "CC_coords", file);
  const std::uint32_t black = level(numbers(vars, "darkness_level", file), "darkness_level", file);
  const std::uint32_t saturation = level(numbers(vars, "saturation_level", file), "saturation_level", file);
  const auto names = vars.find("all_image_names");
  if (names == vars.end() || names->second.kind != MatArray::cell) throw InputError(file, 0, "all_image_names: expected a cell array");
  const std::size_t n = names->second.cells.size();
  if (lights.rows != n || lights.cols != 3) throw InputError(file, 0, "groundtruth_illuminants: expected one r,g,b per image");
  if (coords.rows != n || coords.cols != 4) throw InputError(file, 0, "CC_coords: expected y1,y2,x1,x2 per image");
  std::vector<TruthRow> rows;
  std::set<std::string> seen;
  for (std::size_t i = 0; i < n; ++i) {
    const MatArray& cell = names->second.cells[i];
    // Names may be wrapped in one more cell (a cell of 1×1 cells).
    const MatArray* c = &cell;
    if (cell.kind == MatArray::cell) {
      if (cell.cells.empty()) throw InputError(file, 0, "all_image_names: an empty cell");
      c = &cell.cells[0];
    }
    if (c->kind != MatArray::chars) throw InputError(file, 0, "all_image_names: a cell that is not text");
    const std::string& name = c->text;
    // A name is a file name in the folder: no path (it would be read outside --images).
    if (name.empty() || name == "." || name == ".." || name.find_first_of("/\\") != std::string::npos ||
        std::any_of(name.begin(), name.end(), [](char ch) { return static_cast<unsigned char>(ch) < 32 || ch == 127; }))
      throw InputError(file, 0, "all_image_names: image " + std::to_string(i + 1) + " is not a file name (a path, empty, or a control character): " + printable(name));
    if (!seen.insert(name).second)
      throw InputError(file, 0, "all_image_names: " + printable(name) + " named twice (an image would be in its own training set)");
    TruthRow row;
    row.line = i + 1;
    row.image = find_image(dir, name, file);
    Rational e[3];
    for (int k = 0; k < 3; ++k) {
      e[k] = Rational(lights.at(i, static_cast<std::size_t>(k)));
      if (sgn(e[k]) <= 0) throw InputError(file, 0, "groundtruth_illuminants: image " + std::to_string(i + 1) + " has a channel <= 0");
    }
    row.light = {e[0], e[1], e[2]};
    row.black_level = black;
    row.saturation = saturation;
    const double y1 = coords.at(i, 0), y2 = coords.at(i, 1), x1 = coords.at(i, 2), x2 = coords.at(i, 3);
    const Rational l(std::min(x1, x2) - 1), r(std::max(x1, x2) + 1), t(std::min(y1, y2) - 1), b(std::max(y1, y2) + 1);
    row.chart = {{l, t}, {r, t}, {r, b}, {l, b}};
    rows.push_back(std::move(row));
  }
  if (rows.empty()) throw InputError(file, 0, "no images");
  return rows;
}

std::vector<TruthRow> read_cube_plus(const std::string& dir_text) {
  const fs::path dir(dir_text);
  const std::string file = (dir / "cube+_gt.txt").string();
  require_regular_file(file, "ground-truth file");
  std::string text = read_text_file(file, {std::size_t(16) << 20, "ground-truth file", "lines r g b"});
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);  // a UTF-8 byte-order mark, as truth tables take
  std::vector<TruthRow> rows;
  std::istringstream in(text);
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    std::istringstream fields(line);
    std::string f[3], extra;
    if (!(fields >> f[0] >> f[1] >> f[2]) || (fields >> extra))
      throw InputError(file, number, "expected three numbers r g b");
    Rational e[3];
    for (int k = 0; k < 3; ++k) {
      try {
        e[k] = parse_rational(f[k]);
      } catch (const std::invalid_argument& err) {
        throw InputError(file, number, std::string("rgb"[k] == 'r' ? "r" : k == 1 ? "g" : "b") + ": " + err.what());
      }
      if (sgn(e[k]) <= 0) throw InputError(file, number, "a light channel must be > 0");
    }
    TruthRow row;
    row.line = number;
    row.image = find_image(dir, std::to_string(rows.size() + 1), file);
    row.light = {e[0], e[1], e[2]};
    row.black_level = 2048;
    // The SpyderCube: rows from 1050, columns from 2050 (0-based) to the edge, as pixel squares.
    const Rational far(1 << 20);
    row.chart = {{Rational(2050), Rational(1050)}, {far, Rational(1050)}, {far, far}, {Rational(2050), far}};
    rows.push_back(std::move(row));
  }
  if (rows.empty()) throw InputError(file, 0, "no lights");
  return rows;
}

namespace {

// A PNG's width and height from its header (IHDR), without decoding it.
std::pair<std::size_t, std::size_t> png_size(const fs::path& file) {
  require_regular_file(file.string(), "image");
  std::ifstream in(file, std::ios::binary);
  unsigned char h[24] = {};
  in.read(reinterpret_cast<char*>(h), sizeof h);
  if (!in || h[1] != 'P' || h[2] != 'N' || h[3] != 'G' || h[12] != 'I' || h[13] != 'H')
    throw InputError(file.string(), 0, "not a PNG");
  auto be = [&](int k) { return (std::size_t(h[k]) << 24) | (std::size_t(h[k + 1]) << 16) | (std::size_t(h[k + 2]) << 8) | h[k + 3]; };
  return {be(16), be(20)};
}

// A Gehler-Shi coordinate file's frame (its first line: the width and height of the image the
// coordinates were taken in, whole numbers, "4368 2912" or "4368.000000 2912.000000") and the
// chart's four corners (the next four lines), read exactly.
struct ChartFrame {
  Rational width, height;
  std::array<std::array<Rational, 2>, 4> corner;
};

ChartFrame read_chart_frame(const std::string& coords) {
  const std::string text = read_text_file(coords, {std::size_t(1) << 20, "chart coordinates", "lines x y"});
  std::istringstream in(text);
  std::string line;
  std::vector<std::pair<std::size_t, std::array<std::string, 2>>> lines;  // number, the two fields
  for (std::size_t number = 1; lines.size() < 5 && std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream fields(line);
    std::array<std::string, 2> f;
    std::string extra;
    if (!(fields >> f[0])) continue;  // a blank line
    if (!(fields >> f[1]) || (fields >> extra)) throw InputError(coords, number, "expected two numbers x y");
    lines.push_back({number, f});
  }
  if (lines.size() < 5) throw InputError(coords, 0, "expected a frame line \"width height\" and four corners");
  ChartFrame c;
  std::array<Rational, 2> v[5];
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 2; ++j) try {
        v[k][j] = parse_rational(lines[k].second[j]);
      } catch (const std::invalid_argument& e) {
        throw InputError(coords, lines[k].first, e.what());
      }
  // 22 of the files as shipped (all for images outside the 568) have no frame line: their first
  // line is a corner, with a fraction; read as a frame it would scale the chart wrongly.
  for (int j = 0; j < 2; ++j)
    if (sgn(v[0][j]) <= 0 || v[0][j].get_den() != 1)
      throw InputError(coords, lines[0].first,
                       "no frame line: the first line must be the frame's width and height, whole numbers "
                       "(\"4368 2912\"); found " + lines[0].second[0] + " " + lines[0].second[1] + ", a corner");
  c.width = v[0][0];
  c.height = v[0][1];
  for (int k = 0; k < 4; ++k) c.corner[k] = v[k + 1];
  return c;
}

// The PNG must be the frame scaled by one factor s, each side rounded to a whole pixel: w = s·fw
// + dw, h = s·fh + dh with |dw|, |dh| <= 1/2, so |h·fw - w·fh| = |dh·fw - dw·fh| <= (fw + fh)/2.
// A rotated (portrait against landscape) or cropped image would put the chart in the wrong place.
void check_frame_shape(const std::string& png, std::size_t w, std::size_t h, const ChartFrame& c,
                       const std::string& coords) {
  const Rational W(static_cast<long>(w)), H(static_cast<long>(h));
  if (2 * abs(H * c.width - W * c.height) > c.width + c.height)
    throw InputError(png, 0,
                     std::to_string(w) + "x" + std::to_string(h) + " pixels, not the shape of its chart's frame " +
                         to_string(c.width) + "x" + to_string(c.height) + " (" + coords +
                         ", line 1): a rotated or cropped image would have its chart masked in the wrong place");
}

}  // namespace

std::vector<TruthRow> read_gehler_shi(const std::string& dir_text, std::map<std::string, int>& folds) {
  const fs::path dir(dir_text);
  fs::path images;
  for (const char* sub : {"png", "images"})
    if (fs::is_directory(dir / sub)) images = sub;
  if (images.empty()) throw InputError(dir_text, 0, "no png/ or images/ folder (a Gehler-Shi folder)");
  std::vector<std::string> names;
  for (const fs::directory_entry& e : fs::directory_iterator(dir / images)) {
    const std::string n = e.path().filename().string();
    if (n.size() > 4 && (n.compare(n.size() - 4, 4, ".png") == 0 || n.compare(n.size() - 4, 4, ".PNG") == 0))
      names.push_back(n);
  }
  std::sort(names.begin(), names.end());
  fs::path lights_file = dir / "real_illum_568.mat";
  if (!fs::exists(lights_file)) lights_file = dir / "real_illum_568..mat";
  const std::string file = lights_file.string();
  const Numbers lights = numbers(mat_variables(file, mat_max_file_bytes, "ground-truth file", {"real_rgb"}), "real_rgb", file);
  if (lights.rows != names.size() || lights.cols != 3)
    throw InputError(file, 0, "real_rgb: expected one r,g,b per image of " + (dir / images).string() + " (" +
                                  std::to_string(names.size()) + ")");
  std::vector<TruthRow> rows;
  for (std::size_t i = 0; i < names.size(); ++i) {
    TruthRow row;
    row.line = i + 1;
    row.image = (images / names[i]).string();
    Rational e[3];
    for (int k = 0; k < 3; ++k) {
      e[k] = Rational(lights.at(i, static_cast<std::size_t>(k)));
      if (sgn(e[k]) <= 0) throw InputError(file, 0, "real_rgb: image " + std::to_string(i + 1) + " has a channel <= 0");
    }
    row.light = {e[0], e[1], e[2]};
    // Shi's description.txt: 129 subtracted from images 87-568 (the Canon 5D's, IMG_*), nothing
    // from images 1-86 (the Canon 1D's, 8D5U*).
    row.black_level = names[i].rfind("IMG", 0) == 0 ? 129 : 0;
    const std::string stem = names[i].substr(0, names[i].find('.'));
    const std::string coords = (dir / "coordinates" / (stem + "_macbeth.txt")).string();
    require_regular_file(coords, "chart coordinates");
    const ChartFrame chart = read_chart_frame(coords);
    const fs::path png = dir / images / names[i];
    const auto [w, h] = png_size(png);
    check_frame_shape(png.string(), w, h, chart, coords);
    for (int k : {0, 1, 3, 2})
      row.chart.push_back({chart.corner[k][0] * Rational(static_cast<long>(w)) / chart.width,
                           chart.corner[k][1] * Rational(static_cast<long>(h)) / chart.height});
    rows.push_back(std::move(row));
  }
  if (rows.empty()) throw InputError(dir_text, 0, "no images");
  // The standard split, when shipped: te_split{f} lists the 1-based indices of fold f's images.
  const fs::path split = dir / "threefoldCVsplit.mat";
  folds.clear();
  if (fs::exists(split)) {
    const std::string sfile = split.string();
    const std::map<std::string, MatArray> vars = mat_variables(sfile, mat_max_file_bytes, "split file", {"te_split"});
    const auto te = vars.find("te_split");
    if (te == vars.end() || te->second.kind != MatArray::cell) throw InputError(sfile, 0, "te_split: expected a cell array");
    const std::size_t n = te->second.cells.size();
    for (std::size_t f = 0; f < n; ++f) {
      const MatArray& c = te->second.cells[f];
      for (double x : numbers_of(c, "te_split", sfile).v) {
        if (x < 1 || x > double(rows.size()) || x != std::floor(x))
          throw InputError(sfile, 0, "te_split: an index outside 1.." + std::to_string(rows.size()));
        if (!folds.emplace(rows[static_cast<std::size_t>(x) - 1].image, static_cast<int>(f)).second)
          throw InputError(sfile, 0, "te_split: image " + std::to_string(static_cast<long>(x)) + " in two folds");
      }
    }
    if (folds.size() != rows.size()) throw InputError(sfile, 0, "te_split: not every image is in a fold");
  }
  return rows;
}

std::vector<std::string> dataset_layout_names() { return {"nus", "cube+", "gehler-shi"}; }

std::vector<TruthRow> read_dataset(const std::string& layout, const std::string& dir, std::map<std::string, int>& folds) {
  if (layout == "nus") return read_nus_camera(dir);
  if (layout == "cube+") return read_cube_plus(dir);
  if (layout == "gehler-shi") return read_gehler_shi(dir, folds);
  throw std::invalid_argument(quoted_text(layout) + " is not one of nus, cube+, gehler-shi");
}

}  // namespace gmcc
