#include <gmcc/validation/experiment_report.h>

#include <cstdio>
#include <algorithm>
#include <sstream>
#include <vector>

namespace gmcc {
namespace {

std::string num(double x, const char* format = "%.6f") {
  char b[64];
  std::snprintf(b, sizeof b, format, x);
  return b;
}

}  // namespace

std::string experiment_csv(const ExperimentResult& r) {
  std::ostringstream out;
  out << "illuminant,surfaces,rule,mean_error_deg,mean_worst_case_deg,scenes,median_error_deg,"
         "median_worst_case_deg,mean_illuminant_error_deg,median_illuminant_error_deg,"
         "mean_reproduction_error_deg,max_error_deg,empty_scenes,truth_in_feasible_set\n";
  for (const ExperimentCell& c : r.cells)
    for (std::size_t k = 0; k < c.rules.size(); ++k) {
      const RuleStats& s = c.rules[k];
      out << c.light << ',' << c.surfaces << ',' << r.rules[k] << ','
          << num(s.mean_error_deg) << ',' << num(s.mean_worst_case_deg) << ','
          << c.scenes - c.empty << ',' << num(s.median_error_deg) << ','
          << num(s.median_worst_case_deg) << ',' << num(s.mean_illuminant_error_deg) << ','
          << num(s.median_illuminant_error_deg) << ',' << num(s.mean_reproduction_error_deg) << ','
          << num(s.max_error_deg) << ',' << c.empty << ',' << s.truth_in_feasible_set << '\n';
    }
  return out.str();
}

std::string experiment_table(const ExperimentResult& r) {
  std::ostringstream out;
  out << "gmcc reproduce " << r.name << ": " << r.config.scenes << " scenes per light and count, seed "
      << r.config.seed << ", canonical gamut " << to_string(r.canonical_gamut.kind) << " with "
      << r.canonical_gamut.vertices.size() << " vertices, expansion "
      << to_string(r.config.expansion.policy);
  if (r.config.expansion.policy != ExpansionPolicy::none) out << " by " << to_string(r.config.expansion.factor);
  if (r.config.noise > 0) out << ", noise " << num(r.config.noise, "%g");
  if (r.config.constraint)
    out << ", illumination constraint (" << to_string(r.config.constraint->kind) << " with "
        << r.config.constraint->vertices.size() << " vertices)";
  out << "\nangular error of the perspective map in degrees (Finlayson & Hordley 1999, Fig. 3)\n";
  std::string light;
  for (const ExperimentCell& c : r.cells) {
    if (c.light != light) {
      light = c.light;
      out << "\n" << light << "\n"
          << "  n   mean error:  max-area  2-D mean  3-D mean   worst case:  max-area  2-D mean  "
             "3-D mean   3-D gain  empty"
          << (c.rules.size() > 3 ? "   CRULE mean error: max-volume  centroid" : "") << "\n";
    }
    const auto& s = c.rules;
    const double best_other = std::min(s[0].mean_error_deg, s[1].mean_error_deg);
    const double gain = s[2].mean_error_deg > 0 ? best_other / s[2].mean_error_deg - 1 : 0;
    char line[256];
    std::snprintf(line, sizeof line,
                  "  %-3d %22.3f %9.3f %9.3f %22.3f %9.3f %9.3f %9.0f%% %6llu", c.surfaces,
                  s[0].mean_error_deg, s[1].mean_error_deg, s[2].mean_error_deg,
                  s[0].mean_worst_case_deg, s[1].mean_worst_case_deg, s[2].mean_worst_case_deg,
                  100 * gain, static_cast<unsigned long long>(c.empty));
    out << line;
    if (s.size() > 3) {
      std::snprintf(line, sizeof line, " %30.3f %9.3f", s[3].mean_error_deg, s[4].mean_error_deg);
      out << line;
    }
    out << "\n";
  }
  out << "\n3-D gain: how much larger the better of max-area and 2-D mean's mean error is than the "
         "3-D mean's.\n";
  return out.str();
}

std::string experiment_plot_data(const ExperimentResult& r) {
  std::ostringstream out;
  std::string light;
  for (const ExperimentCell& c : r.cells) {
    if (c.light != light) {
      if (!light.empty()) out << "\n\n";
      light = c.light;
      out << "# " << light << ": surfaces, mean error (max_area mean_2d mean_3d), mean worst case (same)\n";
    }
    out << c.surfaces;
    for (const auto& s : c.rules) out << ' ' << num(s.mean_error_deg);
    for (const auto& s : c.rules) out << ' ' << num(s.mean_worst_case_deg);
    out << '\n';
  }
  return out.str();
}

std::string experiment_plot_script(const ExperimentResult& r, const std::string& stem) {
  std::vector<std::string> lights;
  for (const ExperimentCell& c : r.cells)
    if (lights.empty() || lights.back() != c.light) lights.push_back(c.light);
  const std::size_t rows = lights.size();
  std::ostringstream g;
  g << "# gmcc reproduce " << r.name << ": laid out like Finlayson & Hordley (1999) Fig. 3\n"
    << "if (!exists('png_file')) png_file = '" << stem << ".png'\n"
    << "if (!exists('svg_file')) svg_file = '" << stem << ".svg'\n"
    << "set datafile commentschars '#'\n"
    << "set xlabel 'number of surfaces'\nset xrange [0.5:" << r.config.max_surfaces << ".5]\n"
    << "set yrange [0:*]\nset grid lc rgb '#dddddd'\nset key top right\n"
    << "set style line 1 lc rgb '#d62728' lw 2 pt 7\n"
    << "set style line 2 lc rgb '#1f77b4' lw 2 pt 5\n"
    << "set style line 3 lc rgb '#2ca02c' lw 2 pt 9\n"
    << "set style line 4 lc rgb '#9467bd' lw 2 pt 11 dt 2\n"
    << "set style line 5 lc rgb '#8c564b' lw 2 pt 13 dt 2\n"
    << "do for [term = 1:2] {\n"
    << "  if (term == 1) { set terminal pngcairo size 1000," << 260 * rows << " font ',9'; set output png_file }\n"
    << "  if (term == 2) { set terminal svg size 1000," << 260 * rows << " font 'sans,9'; set output svg_file }\n"
    << "  set multiplot layout " << rows << ",2\n";
  const std::size_t R = r.rules.size();
  const char* titles[] = {"max-area", "2-D mean", "3-D mean", "CRULE max-volume", "CRULE centroid"};
  for (std::size_t i = 0; i < rows; ++i)
    for (int panel = 0; panel < 2; ++panel) {  // mean error, then mean worst case
      g << "  set ylabel '" << lights[i] << (panel ? ": mean worst case (deg)'\n" : ": mean error (deg)'\n")
        << "  plot ";
      for (std::size_t k = 0; k < R; ++k)
        g << (k ? ", '' " : ("'" + stem + ".dat' ")) << "index " << i << " using 1:"
          << 2 + panel * R + k << " with linespoints ls " << k + 1 << " title '" << titles[k] << "'";
      g << "\n";
    }
  g << "  unset multiplot\n  set output\n}\n";
  return g.str();
}

}  // namespace gmcc
