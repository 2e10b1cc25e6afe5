#include <gmcc/validation/accuracy_study.h>

#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/rational.h>
#include <gmcc/selection/mean_3d_analytic.h>
#include <gmcc/selection/mean_3d_double.h>
#include <gmcc/selection/mean_3d_monte_carlo.h>
#include <gmcc/selection/mean_3d_quadrature.h>
#include <gmcc/numerics/internal_check.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace gmcc {
namespace {

// ---- The study's fixed settings (docs/accuracy.md) ---------------------------------------------

// The test polygon P(w): the hull of centre + w·o_i, each coordinate clipped to >= 1/100 so that
// the widest (w = 10) stays in the positive quadrant; only w = 10 is clipped. The o_i are a
// strictly convex, counter-clockwise 7-gon of height 1 (and width 19/20) with no symmetry;
// the centre (1.1, 0.7) is that of the cancellation example in docs/accuracy.md.
const char* const centre_text[2] = {"11/10", "7/10"};
const char* const offset_text[7][2] = {{"1/2", "0"},     {"3/10", "2/5"},   {"-1/10", "1/2"},
                                       {"-9/20", "1/5"}, {"-2/5", "-3/10"}, {"-1/20", "-1/2"},
                                       {"7/20", "-7/20"}};
const char* const clip_text = "1/100";
const char* const width_text[] = {"10",   "1",    "1e-1", "1e-2",  "1e-3",  "1e-4",  "1e-5",
                                  "1e-6", "1e-7", "1e-8", "1e-9", "1e-10", "1e-11", "1e-12"};
// The cancellation (docs/accuracy.md "Reading") asks for >= 53 + 2·log2(1/ε) + ~20 bits (~175 at w = 1e-12): 4096 is far beyond.
constexpr unsigned reference_bits = 4096;
constexpr unsigned quadrature_orders[] = {2, 4, 8, 16};
constexpr std::uint64_t monte_carlo_counts[] = {10000, 100000, 1000000, 10000000};
// Log-scale plots cannot show 0 (an estimate equal to the rounded reference): drawn here.
constexpr double plot_floor = 1e-17;

}  // namespace

ConvexSet2 accuracy_test_polygon(const Rational& w) {
  const Rational cx = parse_rational(centre_text[0]), cy = parse_rational(centre_text[1]);
  const Rational clip = parse_rational(clip_text);
  std::vector<Point2> points;
  for (const auto& o : offset_text)
    points.push_back({std::max<Rational>(cx + w * parse_rational(o[0]), clip),
                      std::max<Rational>(cy + w * parse_rational(o[1]), clip)});
  ConvexSet2 F = convex_hull(points);
  GMCC_CHECK(F.kind == ConvexKind::polygon, "accuracy: the test polygon is a polygon");
  return F;
}

namespace {

// ---- Measurements --------------------------------------------------------------------------------

// Both components' correctly_rounded flags, as `yes yes`.
std::string rounded_text(const MapEstimate& e) {
  return std::string(e.correctly_rounded[0] ? "yes" : "no") + " " + (e.correctly_rounded[1] ? "yes" : "no");
}

AccuracyMeasurement row(std::string route, std::string parameter) {
  AccuracyMeasurement m;
  m.route = std::move(route);
  m.parameter = std::move(parameter);
  return m;
}



// max_k |estimate_k − reference_k|: the exact difference of the two doubles, rounded once.
double error_abs(const std::array<double, 2>& estimate, const std::array<double, 2>& reference) {
  double e = 0;
  for (int k = 0; k < 2; ++k) {
    if (std::isnan(estimate[k])) return NAN;
    if (std::isinf(estimate[k])) return INFINITY;
    const Rational d(rational_from_double(estimate[k]) - rational_from_double(reference[k]));
    e = std::max(e, std::fabs(to_double_nearest(d)));
  }
  return e;
}

std::string number(double x, const char* format = "%.17g") {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  if (x == 0) return "0";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, x);
  return buffer;
}
std::string brief(double x) { return number(x, "%.1e"); }

// 10000 -> 1e4; other counts as integers.
std::string count_text(std::uint64_t n) {
  int exponent = 0;
  std::uint64_t m = n;
  while (m >= 10 && m % 10 == 0) m /= 10, ++exponent;
  return m == 1 && exponent > 0 ? "1e" + std::to_string(exponent) : std::to_string(n);
}

std::vector<std::uint64_t> sample_counts(std::uint64_t cap) {
  std::vector<std::uint64_t> counts;
  for (std::uint64_t n : monte_carlo_counts) {
    const std::uint64_t c = std::min(n, cap);
    if (counts.empty() || counts.back() != c) counts.push_back(c);
  }
  return counts;
}

}  // namespace

AccuracyWidth measure_accuracy(const std::string& width, const AccuracySettings& o) {
  const ConvexSet2 F = accuracy_test_polygon(parse_rational(width));
  AccuracyWidth r;
  r.width = width;
  r.vertices = F.vertices.size();
  r.reference = mean_3d_analytic(F, {reference_bits});
  const auto& ref = r.reference.map;
  const double scale = std::max(std::fabs(ref[0]), std::fabs(ref[1]));
  auto add = [&](AccuracyMeasurement m, const std::array<double, 2>& estimate) {
    m.error_abs = error_abs(estimate, ref);
    m.error_rel = m.error_abs / scale;
    r.rows.push_back(std::move(m));
  };

  AccuracyMeasurement reference = row("reference", std::to_string(reference_bits));
  reference.bound = r.reference.error_bound;
  reference.precision_bits = r.reference.precision_bits;
  reference.extra = "precision_bits=" + std::to_string(r.reference.precision_bits) + ";map=" +
                    number(ref[0]) + " " + number(ref[1]);
  add(reference, ref);

  add(row("double", ""), mean_3d_double(F));

  const MapEstimate a = mean_3d_analytic(F);
  AccuracyMeasurement analytic = row("analytic", "auto");
  analytic.bound = a.error_bound;
  analytic.precision_bits = a.precision_bits;
  analytic.rounded = a.correctly_rounded[0] && a.correctly_rounded[1];
  analytic.extra = "precision_bits=" + std::to_string(a.precision_bits) + ";correctly_rounded=" +
                   rounded_text(a);
  add(analytic, a.map);

  for (unsigned n : quadrature_orders) {
    const MapEstimate q = mean_3d_quadrature(F, n);
    AccuracyMeasurement m = row("quadrature", std::to_string(n));
    m.bound = q.error_bound;
    m.extra = "correctly_rounded=" + rounded_text(q);
    m.rounded = q.correctly_rounded[0] && q.correctly_rounded[1];
    add(m, q.map);
  }

  for (std::uint64_t n : sample_counts(o.max_samples)) {
    const MapEstimate mc = mean_3d_monte_carlo(F, n, o.seed);
    AccuracyMeasurement m = row("monte-carlo", std::to_string(n));
    m.kept = mc.samples_kept;
    m.extra = "kept=" + std::to_string(mc.samples_kept);
    if (!mc.valid) {
      m.valid = false;
      m.extra += ";too few samples in the cone (fewer than " +
                 std::to_string(monte_carlo_min_kept) + ")";
      r.rows.push_back(std::move(m));
      continue;
    }
    m.bound = mc.error_bound;
    m.extra += ";se=" + number(mc.standard_error[0]) + " " + number(mc.standard_error[1]);
    add(m, mc.map);
  }
  return r;
}

namespace {

const AccuracyMeasurement* find(const AccuracyWidth& r, const std::string& route, const std::string& p) {
  for (const AccuracyMeasurement& m : r.rows)
    if (m.route == route && m.parameter == p) return &m;
  return nullptr;
}

// ---- Output --------------------------------------------------------------------------------------

// Left-aligned columns, two spaces apart, each line indented by two.
std::string columns(const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::size_t> width;
  for (const auto& row : rows)
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (width.size() <= i) width.push_back(0);
      width[i] = std::max(width[i], row[i].size());
    }
  std::string out;
  for (const auto& row : rows) {
    std::string line = " ";
    for (std::size_t i = 0; i < row.size(); ++i)
      line += " " + row[i] + (i + 1 < row.size() ? std::string(width[i] - row[i].size() + 1, ' ') : "");
    out += line + "\n";
  }
  return out;
}

std::string polygon_text() {
  std::string s;
  for (const auto& o : offset_text) s += std::string(s.empty() ? "" : " ") + "(" + o[0] + ", " + o[1] + ")";
  return s;
}

}  // namespace

std::string accuracy_table(const std::vector<AccuracyWidth>& results, const AccuracySettings& o) {
  std::ostringstream out;
  out << "gmcc accuracy: error of the 3-D mean (Finlayson & Hordley 1999, 3.2) by route\n"
      << "polygon P(w) = hull of (" << centre_text[0] << ", " << centre_text[1]
      << ") + w*o_i, coordinates clipped to >= " << clip_text << ", with o_i =\n  "
      << polygon_text() << "\n"
      << "reference m* = mean_3d_analytic at " << reference_bits
      << " bits (certified; its bound is its rounding to double)\n"
      << "error = max_k |m_k - m*_k|, exact difference of doubles (0: equals the rounded "
         "reference)\n\n";

  std::vector<std::vector<std::string>> closed{
      {"width", "n", "reference map m*", "ref bound", "double", "analytic", "bound", "bits", "rounded"}};
  for (const AccuracyWidth& r : results) {
    const AccuracyMeasurement* a = find(r, "analytic", "auto");
    closed.push_back({r.width, std::to_string(r.vertices),
                      "(" + number(r.reference.map[0]) + ", " + number(r.reference.map[1]) + ")",
                      brief(r.reference.error_bound), brief(find(r, "double", "")->error_abs),
                      brief(a->error_abs), brief(*a->bound), std::to_string(a->precision_bits),
                      a->rounded ? "yes" : "no"});
  }
  out << "closed form (docs/math.md 2): double = naive sum in doubles, analytic = certified;\n"
         "rounded: both components certified correctly rounded\n"
      << columns(closed) << "\n";

  std::vector<std::vector<std::string>> quad{{"width"}};
  for (unsigned n : quadrature_orders) quad[0].push_back("n=" + std::to_string(n));
  for (const AccuracyWidth& r : results) {
    quad.push_back({r.width});
    for (unsigned n : quadrature_orders) {
      const AccuracyMeasurement* m = find(r, "quadrature", std::to_string(n));
      quad.back().push_back(brief(m->error_abs) + " / " + brief(*m->bound) + (m->rounded ? " r" : ""));
    }
  }
  out << "quadrature, Duffy-Gauss-Legendre n x n per fan triangle (docs/math.md 2): error / "
         "statement\n(2|Q_n - Q_2n| + rounding bound); r: correctly rounded as far as the "
         "statement holds\n"
      << columns(quad) << "\n";

  const std::vector<std::uint64_t> counts = sample_counts(o.max_samples);
  std::vector<std::vector<std::string>> mc{{"width"}};
  for (std::uint64_t n : counts) mc[0].push_back("N=" + count_text(n));
  for (const AccuracyWidth& r : results) {
    mc.push_back({r.width});
    for (std::uint64_t n : counts) {
      const AccuracyMeasurement* m = find(r, "monte-carlo", std::to_string(n));
      mc.back().push_back(m->valid ? brief(m->error_abs) + " / " + brief(*m->bound) + " (" +
                                         std::to_string(m->kept) + ")"
                                   : "too few (" + std::to_string(m->kept) + " kept)");
    }
  }
  out << "Monte Carlo, N points in [0,1)^3, mt19937_64 seed " << o.seed
      << " (docs/math.md 2): error / standard error (points kept)\n"
      << columns(mc);
  return out.str();
}

namespace {

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace

std::string accuracy_csv(const std::vector<AccuracyWidth>& results) {
  std::string out = "width,route,parameter,error_abs,error_rel,reported_bound,extra\n";
  for (const AccuracyWidth& r : results)
    for (const AccuracyMeasurement& m : r.rows)
      out += r.width + "," + m.route + "," + m.parameter + "," +
             (m.valid ? number(m.error_abs) : "n/a") + "," +
             (m.valid ? number(m.error_rel) : "n/a") + "," +
             (m.bound ? number(*m.bound) : m.valid ? "" : "n/a") + "," + csv_field(m.extra) +
             "\n";
  return out;
}

namespace {

// One plotted line: its key title, gnuplot style, which rows it draws, and whether it draws
// their relative error or their reported bound (relative).
struct Series {
  std::string title, style, route, parameter;
  bool bound = false;
};

std::vector<Series> plot_series(const AccuracySettings& o) {
  std::vector<Series> s{{"closed form, double", "lc rgb '#d62728' lw 2 pt 7", "double", ""}};
  const char* blue[] = {"#9ecae1", "#6baed6", "#3182bd", "#08519c"};
  for (std::size_t i = 0; i < std::size(quadrature_orders); ++i)
    s.push_back({"quadrature n=" + std::to_string(quadrature_orders[i]),
                 std::string("lc rgb '") + blue[i] + "' dt 2 pt 9",
                 "quadrature", std::to_string(quadrature_orders[i])});
  const char* green[] = {"#a1d99b", "#74c476", "#31a354", "#006d2c"};
  const std::vector<std::uint64_t> counts = sample_counts(o.max_samples);
  for (std::size_t i = 0; i < counts.size(); ++i)
    s.push_back({"Monte Carlo N=" + count_text(counts[i]),
                 std::string("lc rgb '") + green[4 - counts.size() + i] + "' dt 3 pt 13",
                 "monte-carlo", std::to_string(counts[i])});
  // Last, so that it is drawn over the quadrature's zeros.
  s.push_back({"closed form, certified", "lc rgb '#000000' lw 2 pt 5", "analytic", "auto"});
  s.push_back({"certified: its bound", "lc rgb '#000000' lw 1 dt 4 pt 0", "analytic", "auto", true});
  return s;
}

// Data blocks (gnuplot `index`), one per series: width, relative error. Zero errors are drawn at
// plot_floor; non-finite errors and Monte Carlo runs with too few samples are left out.
std::string plot_data(const std::vector<AccuracyWidth>& results, const std::vector<Series>& series) {
  std::string out = "# gmcc accuracy: relative error of the 3-D mean by route (docs/accuracy.md)\n"
                    "# one block per line of the plot; columns: width, relative error (or bound; 0 shown as " +
                    number(plot_floor, "%g") + ")\n";
  for (std::size_t i = 0; i < series.size(); ++i) {
    out += "\n\n# " + series[i].title + "\n";
    for (const AccuracyWidth& r : results) {
      const AccuracyMeasurement* m = find(r, series[i].route, series[i].parameter);
      const double scale = std::max(std::fabs(r.reference.map[0]), std::fabs(r.reference.map[1]));
      const double y = series[i].bound ? *m->bound / scale : m->error_rel;
      if (!m->valid || !std::isfinite(y)) continue;
      out += number(to_double_nearest(parse_rational(r.width))) + " " + number(std::max(y, plot_floor)) + "\n";
    }
  }
  return out;
}

std::string plot_script(const std::vector<Series>& series) {
  std::string out =
      "# gmcc accuracy: relative error of the 3-D mean against a 4096-bit certified reference,\n"
      "# by route, on the 7-gon of docs/accuracy.md. Written by `gmcc accuracy --plot DIR`;\n"
      "# to redraw by hand: cd DIR && gnuplot accuracy.gp\n"
      "if (!exists('png_file')) png_file = 'accuracy.png'\n"
      "if (!exists('svg_file')) svg_file = 'accuracy.svg'\n"
      "set logscale xy\n"
      "set format x '10^{%L}'\n"
      "set format y '10^{%L}'\n"
      "set xrange [5e-13:20]\n"
      "set yrange [" + number(plot_floor / 2, "%g") + ":*]\n"
      "set xlabel 'polygon width w'\n"
      "set ylabel 'relative error of the map (0 drawn at " + number(plot_floor, "%g") + ")'\n"
      "set key at graph 0.02, graph 0.13 left bottom Left reverse box opaque samplen 3\n"
      "set grid\n"
      "set arrow from graph 0, first 2**-53 to graph 1, first 2**-53 nohead dt 4 lc rgb '#888888'\n"
      "set label '2^{-53}' at graph 0.01, first 2**-53 offset 0, 0.6 textcolor rgb '#888888'\n"
      "set terminal pngcairo size 800,500 font ',9'\n"
      "set output png_file\n"
      "plot \\\n";
  for (std::size_t i = 0; i < series.size(); ++i)
    out += "  'accuracy.dat' index " + std::to_string(i) + " using 1:2 with linespoints " +
           series[i].style + " title '" + series[i].title + "'" +
           (i + 1 < series.size() ? ", \\\n" : "\n");
  out += "set terminal svg size 800,500 font ',9' dynamic\n"
         "set output svg_file\n"
         "replot\n"
         "set output\n";
  return out;
}

}  // namespace

const std::vector<std::string>& accuracy_widths() {
  static const std::vector<std::string> widths(std::begin(width_text), std::end(width_text));
  return widths;
}

std::string accuracy_plot_data(const std::vector<AccuracyWidth>& results, const AccuracySettings& settings) {
  return plot_data(results, plot_series(settings));
}

std::string accuracy_plot_script(const AccuracySettings& settings) { return plot_script(plot_series(settings)); }

}  // namespace gmcc
