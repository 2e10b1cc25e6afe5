#include <gmcc/validation/experiment_report.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

namespace gmcc {
namespace {

// A 2-D rule's position in a cell's or scene's rules (the 2-D rules come first, in all_rules order).
std::size_t index(Rule rule) { return static_cast<std::size_t>(rule); }

// The 2-D rules' keys, space-separated: "max_area mean_2d mean_3d".
std::string rule_keys() {
  std::string keys;
  for (Rule rule : all_rules) keys += (keys.empty() ? "" : " ") + to_string(rule);
  return keys;
}

std::string num(double x, const char* format = "%.6f") {
  if (std::isnan(x)) return "";  // undefined in CSV (no scene in the cell, a spread of one value)
  char b[64];
  std::snprintf(b, sizeof b, format, x);
  return b;
}

// The shortest decimal that reads back as the same double (std::to_chars); null if not finite.
std::string json_number(double x) {
  if (!std::isfinite(x)) return "null";
  char b[64];
  const auto end = std::to_chars(b, b + sizeof b, x).ptr;
  return std::string(b, end);
}

// A JSON string; the names written here are the program's own and the lights' (from data files).
std::string json_string(const std::string& t) {
  std::string out = "\"";
  for (unsigned char c : t) {
    if (c == '"' || c == '\\') out += '\\', out += static_cast<char>(c);
    else if (c < 0x20) {
      char b[8];
      std::snprintf(b, sizeof b, "\\u%04x", c);
      out += b;
    } else out += static_cast<char>(c);
  }
  return out + "\"";
}

std::string json_set(const ConvexSet2& set) {
  std::string out = "{\"kind\":" + json_string(to_string(set.kind)) + ",\"vertices\":[";
  for (std::size_t i = 0; i < set.vertices.size(); ++i)
    out += (i ? "," : "") + std::string("[") + json_string(to_string(set.vertices[i].x)) + "," +
           json_string(to_string(set.vertices[i].y)) + "]";
  return out + "]}";
}

// The four quantities of RuleStats, in report order, with their column and member names.
struct Quantity {
  const char* name;
  ErrorStatistics RuleStats::*member;
};
const Quantity quantities[] = {{"error", &RuleStats::error},
                               {"worst_case", &RuleStats::worst_case},
                               {"illuminant_error", &RuleStats::illuminant},
                               {"reproduction_error", &RuleStats::reproduction}};

struct Statistic {
  const char* name;
  double ErrorStatistics::*member;
};
const Statistic statistics[] = {{"mean", &ErrorStatistics::mean},       {"se", &ErrorStatistics::standard_error},
                                {"median", &ErrorStatistics::median},   {"trimean", &ErrorStatistics::trimean},
                                {"best25", &ErrorStatistics::best25},   {"worst25", &ErrorStatistics::worst25},
                                {"p95", &ErrorStatistics::p95},         {"max", &ErrorStatistics::max}};

// The statistic columns among the original fourteen.
bool original_column(const std::string& column) {
  for (const char* c : {"mean_error_deg", "mean_worst_case_deg", "median_error_deg", "median_worst_case_deg",
                        "mean_illuminant_error_deg", "median_illuminant_error_deg",
                        "mean_reproduction_error_deg", "max_error_deg"})
    if (column == c) return true;
  return false;
}

}  // namespace

std::vector<std::string> experiment_csv_added_columns() {
  std::vector<std::string> columns;
  for (const Quantity& q : quantities)
    for (const Statistic& st : statistics) {
      const std::string column = std::string(st.name) + "_" + q.name + "_deg";
      if (!original_column(column)) columns.push_back(column);
    }
  columns.push_back("positive_map_scenes");
  return columns;
}

std::string experiment_csv(const ExperimentResult& r, const std::string& provenance) {
  std::ostringstream out;
  if (!provenance.empty()) out << "# gmcc-provenance: " << provenance << '\n';
  out << "illuminant,surfaces,rule,mean_error_deg,mean_worst_case_deg,scenes,median_error_deg,"
         "median_worst_case_deg,mean_illuminant_error_deg,median_illuminant_error_deg,"
         "mean_reproduction_error_deg,max_error_deg,empty_scenes,truth_in_feasible_set";
  for (const std::string& column : experiment_csv_added_columns()) out << ',' << column;
  out << '\n';
  // A baseline (no feasible set: no worst case, no truth-in-F) leaves those columns empty.
  auto row = [&](const ExperimentCell& c, const std::string& rule, const RuleStats& s, std::uint64_t scenes,
                 bool baseline) {
    auto worst = [&](double x) { return baseline ? std::string() : num(x); };
    out << c.light << ',' << c.surfaces << ',' << rule << ','
        << num(s.error.mean) << ',' << worst(s.worst_case.mean) << ','
        << scenes << ',' << num(s.error.median) << ','
        << worst(s.worst_case.median) << ',' << num(s.illuminant.mean) << ','
        << num(s.illuminant.median) << ',' << num(s.reproduction.mean) << ','
        << num(s.error.max) << ',' << c.empty << ',' << (baseline ? std::string() : std::to_string(s.truth_in_feasible_set));
    for (const Quantity& q : quantities)
      for (const Statistic& st : statistics)
        if (!original_column(std::string(st.name) + "_" + q.name + "_deg")) {
          const double x = s.*q.member.*st.member;
          const bool undefined = std::isnan(x) || (baseline && q.member == &RuleStats::worst_case);
          out << ',' << (undefined ? std::string() : num(x));  // undefined (se of one value): empty
        }
    out << ',' << s.illuminant.n << '\n';
  };
  for (const ExperimentCell& c : r.cells) {
    for (std::size_t k = 0; k < c.rules.size(); ++k) row(c, r.rules[k], c.rules[k], c.scenes - c.empty, false);
    // Baselines over the rules' scenes, then over every scene of the cell (rule name + "_all").
    for (std::size_t b = 0; b < c.baselines.size() && b < r.baselines.size(); ++b)
      row(c, r.baselines[b], c.baselines[b], c.scenes - c.empty, true);
    for (std::size_t b = 0; b < c.baselines_all.size() && b < r.baselines.size(); ++b)
      row(c, r.baselines[b] + "_all", c.baselines_all[b], c.scenes, true);
  }
  return out.str();
}

std::string experiment_setup_json(const ExperimentResult& r) {
  const ExperimentConfig& c = r.config;
  std::string out = "{\"format\":\"gmcc-reproduce\",\"format_version\":1,";
  out += "\"experiment\":" + json_string(r.name) + ",\"figure\":" + json_string(r.figure) + ",\"lights\":[";
  for (std::size_t i = 0; i < r.lights.size(); ++i) out += (i ? "," : "") + json_string(r.lights[i]);
  out += "],\"rules\":[";
  for (std::size_t i = 0; i < r.rules.size(); ++i) out += (i ? "," : "") + json_string(r.rules[i]);
  out += "],\"min_surfaces\":" + std::to_string(c.min_surfaces) + ",\"max_surfaces\":" +
         std::to_string(c.max_surfaces) + ",\"scenes\":" + std::to_string(c.scenes) + ",\"seed\":" +
         std::to_string(c.seed) + ",\"expansion\":{\"policy\":" + json_string(to_string(c.expansion.policy)) +
         ",\"factor\":" + json_string(to_string(c.expansion.factor)) + "},\"noise\":" + json_number(c.noise) +
         ",\"shading\":" + json_number(c.shading) + ",\"crule\":" + (c.crule ? "true" : "false") +
         ",\"mean3d\":" + json_string(to_string(c.mean3d.method)) +
         // The seed-claim conditions only when set, so that older runs' records keep their bytes.
         (c.crule_black == CanonicalBlack::exclude ? ",\"crule_black\":\"exclude\"" : "") +
         (c.crule_extended ? ",\"crule_extended\":true" : "") +
         (c.specular > 0 ? ",\"specular\":" + json_number(c.specular) : std::string()) +
         (c.intensity > 0 ? ",\"intensity\":" + json_number(c.intensity) : std::string()) +
         ",\"canonical_gamut\":" + json_set(r.canonical_gamut) +
         ",\"constraint\":" + (c.constraint ? json_set(*c.constraint) : std::string("null")) +
         ",\"surface_indices\":" + json_string(r.surface_indices);
  if (!r.baselines.empty()) {
    out += ",\"baselines\":[";
    for (std::size_t i = 0; i < r.baselines.size(); ++i) out += (i ? "," : "") + json_string(r.baselines[i]);
    out += "]";
  }
  if (!r.canonical_gamuts.empty())  // one per light's set; canonical_gamut is the first
    out += ",\"canonical_gamuts\":" + std::to_string(r.canonical_gamuts.size());
  if (c.shard_count > 1)
    out += ",\"shard\":" + json_string(std::to_string(c.shard_index) + "/" + std::to_string(c.shard_count));
  return out + "}";
}

std::string experiment_scenes_jsonl(const ExperimentResult& r, const std::string& provenance) {
  std::string out = provenance.empty() ? std::string() : "{\"provenance\":" + provenance + "}\n";
  out += experiment_setup_json(r) + "\n";
  for (const SceneRecord& s : r.scenes) {
    out += "{\"light\":" + json_string(r.lights.at(s.light)) + ",\"light_index\":" + std::to_string(s.light) +
           ",\"surfaces\":" + std::to_string(s.surfaces) + ",\"scene\":" + std::to_string(s.scene) + ",\"drawn\":[";
    for (std::size_t i = 0; i < s.drawn.size(); ++i) out += (i ? "," : "") + std::to_string(s.drawn[i]);
    out += "],\"feasible_set\":{\"kind\":" + json_string(to_string(s.kind)) + ",\"area\":" + json_number(s.area) + "}";
    if (!s.baselines.empty()) {  // only with baselines (gehler-shi): estimates scored in every scene
      out += ",\"baselines\":{";
      for (std::size_t b = 0; b < s.baselines.size(); ++b) {
        const RuleRecord& x = s.baselines[b];
        out += (b ? "," : "") + json_string(r.baselines.at(b)) + ":";
        if (!x.scored) {
          out += "null";
          continue;
        }
        out += "{\"map\":[" + json_number(x.map[0]) + "," + json_number(x.map[1]) + "],\"error_deg\":" +
               json_number(x.error_deg) + ",\"illuminant_error_deg\":" +
               (x.positive_map ? json_number(x.illuminant_error_deg) : "null") + ",\"reproduction_error_deg\":" +
               (x.positive_map ? json_number(x.reproduction_error_deg) : "null") + "}";
      }
      out += "}";
    }
    out += ",\"rules\":";
    if (s.rules.empty()) {
      out += "null}\n";
      continue;
    }
    out += "{";
    for (std::size_t k = 0; k < s.rules.size(); ++k) {
      const RuleRecord& x = s.rules[k];
      out += (k ? "," : "") + json_string(r.rules.at(k)) + ":";
      if (!x.scored) {
        out += "null";
        continue;
      }
      out += "{\"map\":[" + json_number(x.map[0]) + "," + json_number(x.map[1]) + "],\"error_deg\":" +
             json_number(x.error_deg) + ",\"worst_case_deg\":" + json_number(x.worst_case_deg) +
             ",\"illuminant_error_deg\":" + (x.positive_map ? json_number(x.illuminant_error_deg) : "null") +
             ",\"reproduction_error_deg\":" + (x.positive_map ? json_number(x.reproduction_error_deg) : "null") +
             ",\"truth_in_feasible_set\":" + (x.truth_in_feasible_set ? "true" : "false") + "}";
    }
    out += "}}\n";
  }
  return out;
}

std::string experiment_json(const ExperimentResult& r, const std::string& provenance) {
  std::string out = provenance.empty() ? "{" : "{\"provenance\":" + provenance + ",";
  out += "\"setup\":" + experiment_setup_json(r) + ",\"cells\":[";
  for (std::size_t i = 0; i < r.cells.size(); ++i) {
    const ExperimentCell& c = r.cells[i];
    out += std::string(i ? "," : "") + "\n{\"light\":" + json_string(c.light) + ",\"surfaces\":" +
           std::to_string(c.surfaces) + ",\"scenes\":" + std::to_string(c.scenes) + ",\"empty_scenes\":" +
           std::to_string(c.empty) + ",\"rules\":{";
    for (std::size_t k = 0; k < c.rules.size(); ++k) {
      const RuleStats& s = c.rules[k];
      out += (k ? "," : "") + json_string(r.rules.at(k)) + ":{\"truth_in_feasible_set\":" +
             std::to_string(s.truth_in_feasible_set);
      for (const Quantity& q : quantities) {
        const ErrorStatistics& e = s.*q.member;
        out += ",\"" + std::string(q.name) + "_deg\":{\"n\":" + std::to_string(e.n);
        for (const Statistic& st : statistics) out += ",\"" + std::string(st.name) + "\":" + json_number(e.*st.member);
        out += "}";
      }
      out += "}";
    }
    out += "}";
    // Baselines (gehler-shi): over the rules' scenes, and over every scene ("_all").
    for (int all = 0; all < 2 && !r.baselines.empty(); ++all) {
      out += all ? ",\"baselines_all\":{" : ",\"baselines\":{";
      const std::vector<RuleStats>& stats = all ? c.baselines_all : c.baselines;
      for (std::size_t b = 0; b < stats.size() && b < r.baselines.size(); ++b) {
        out += (b ? "," : "") + json_string(r.baselines[b]) + ":{";
        bool first = true;
        for (const Quantity& q : quantities) {
          if (q.member == &RuleStats::worst_case) continue;
          const ErrorStatistics& e = stats[b].*q.member;
          out += (first ? "\"" : ",\"") + std::string(q.name) + "_deg\":{\"n\":" + std::to_string(e.n);
          first = false;
          for (const Statistic& st : statistics) out += ",\"" + std::string(st.name) + "\":" + json_number(e.*st.member);
          out += "}";
        }
        out += "}";
      }
      out += "}";
    }
    out += "}";
  }
  return out + "\n]}\n";
}

std::string experiment_table(const ExperimentResult& r) {
  std::ostringstream out;
  out << "gmcc reproduce " << r.name << ": " << r.config.scenes << " scenes per light and count, seed "
      << r.config.seed << ", canonical gamut " << to_string(r.canonical_gamut.kind) << " with "
      << r.canonical_gamut.vertices.size() << " vertices, expansion "
      << to_string(r.config.expansion.policy);
  if (r.config.expansion.policy != ExpansionPolicy::none) out << " by " << to_string(r.config.expansion.factor);
  if (r.config.noise > 0) out << ", noise " << num(r.config.noise, "%g");
  if (r.config.specular > 0) out << ", specular " << num(r.config.specular, "%g");
  if (r.config.intensity > 0) out << ", intensity " << num(r.config.intensity, "%g");
  if (r.config.crule && r.config.crule_black == CanonicalBlack::exclude) out << ", CRULE without black";
  if (r.config.constraint)
    out << ", illumination constraint (" << to_string(r.config.constraint->kind) << " with "
        << r.config.constraint->vertices.size() << " vertices)";
  if (r.config.shard_count > 1) out << ", shard " << r.config.shard_index << "/" << r.config.shard_count;
  out << "\nangular error of the perspective map in degrees (Finlayson & Hordley 1999, " << r.figure << ")\n";
  std::string light;
  for (const ExperimentCell& c : r.cells) {
    if (c.light != light) {
      light = c.light;
      out << "\n" << light << "\n"
          << "  n   mean error:  max-area  2-D mean  3-D mean   worst case:  max-area  2-D mean  "
             "3-D mean   3-D gain  empty"
          << (c.rules.size() > rule_count ? "   CRULE mean error: max-volume  centroid" : "")
          << (c.rules.size() > rule_count + 2 ? " max-trace cone-mean" : "") << "\n";
    }
    // The paper's table: its three rules (a rule added to rule.h is in the CSV, JSON and
    // records), then CRULE's after every 2-D rule.
    const auto& s = c.rules;
    const RuleStats &area = s[index(Rule::max_area)], &mean2 = s[index(Rule::mean_2d)], &mean3 = s[index(Rule::mean_3d)];
    const std::size_t crule = rule_count;
    const double best_other = std::min(area.error.mean, mean2.error.mean);
    const double gain = mean3.error.mean > 0 ? best_other / mean3.error.mean - 1 : 0;
    char line[256];
    std::snprintf(line, sizeof line,
                  "  %-3d %22.3f %9.3f %9.3f %22.3f %9.3f %9.3f %9.0f%% %6llu", c.surfaces,
                  area.error.mean, mean2.error.mean, mean3.error.mean,
                  area.worst_case.mean, mean2.worst_case.mean, mean3.worst_case.mean,
                  100 * gain, static_cast<unsigned long long>(c.empty));
    out << line;
    if (s.size() > crule) {
      std::snprintf(line, sizeof line, " %30.3f %9.3f", s[crule].error.mean, s[crule + 1].error.mean);
      out << line;
    }
    if (s.size() > crule + 3) {
      std::snprintf(line, sizeof line, " %9.3f %9.3f", s[crule + 2].error.mean, s[crule + 3].error.mean);
      out << line;
    }
    out << "\n";
  }
  out << "\n3-D gain: how much larger the better of max-area and 2-D mean's mean error is than the "
         "3-D mean's.\n";
  out << "\nmap-space error statistics in degrees (docs/reproduction.md, Statistics): mean, standard "
         "error, median, trimean,\nmean of the best and of the worst 25%, 95th percentile, maximum, over "
         "the scenes with a map\n";
  light.clear();
  for (const ExperimentCell& c : r.cells) {
    if (c.light != light) {
      light = c.light;
      out << "\n" << light << "\n"
          << "  n   rule                  mean      se  median trimean  best25 worst25     p95     max\n";
    }
    for (std::size_t k = 0; k < c.rules.size(); ++k) {
      const ErrorStatistics& e = c.rules[k].error;
      char line[256];
      const std::string se = std::isnan(e.standard_error) ? "-" : num(e.standard_error, "%.3f");
      std::snprintf(line, sizeof line, "  %-3d %-16s %9.3f %7s %7.3f %7.3f %7.3f %7.3f %7.3f %7.3f\n",
                    c.surfaces, r.rules[k].c_str(), e.mean, se.c_str(), e.median, e.trimean, e.best25,
                    e.worst25, e.p95, e.max);
      out << line;
    }
  }
  return out.str();
}

std::string experiment_plot_data(const ExperimentResult& r) {
  // gnuplot skips NaN: a cell without scenes leaves a gap in its curve.
  auto num = [](double x) { return std::isnan(x) ? std::string("NaN") : gmcc::num(x); };
  std::ostringstream out;
  std::string light;
  for (const ExperimentCell& c : r.cells) {
    if (c.light != light) {
      if (!light.empty()) out << "\n\n";
      light = c.light;
      out << "# " << light << ": surfaces, mean error (" << rule_keys() << "), mean worst case (same)"
          << (r.baselines.empty() ? "" : ", mean recovery error (same, then grey_world max_rgb on the same scenes)")
          << "\n";
    }
    out << c.surfaces;
    for (const auto& s : c.rules) out << ' ' << num(s.error.mean);
    for (const auto& s : c.rules) out << ' ' << num(s.worst_case.mean);
    if (!r.baselines.empty()) {
      for (const auto& s : c.rules) out << ' ' << num(s.illuminant.mean);
      for (const auto& s : c.baselines) out << ' ' << num(s.illuminant.mean);
    }
    out << '\n';
  }
  return out.str();
}

std::string experiment_plot_script(const ExperimentResult& r, const std::string& stem) {
  std::vector<std::string> lights;
  for (const ExperimentCell& c : r.cells)
    if (lights.empty() || lights.back() != c.light) lights.push_back(c.light);
  const std::size_t rows = lights.size();
  const std::size_t columns = r.baselines.empty() ? 2 : 3;  // with baselines: recovery error too
  std::ostringstream g;
  g << "# gmcc reproduce " << r.name << ": laid out like Finlayson & Hordley (1999) " << r.figure << "\n"
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
    << (r.rules.size() > rule_count + 2 ? "set style line 6 lc rgb '#e377c2' lw 2 pt 15 dt 3\n"
                             "set style line 7 lc rgb '#7f7f7f' lw 2 pt 4 dt 3\n"
                           : "")
    << "do for [term = 1:2] {\n"
    << "  if (term == 1) { set terminal pngcairo size " << 500 * columns << "," << 260 * rows
    << " font ',9'; set output png_file }\n"
    << "  if (term == 2) { set terminal svg size " << 500 * columns << "," << 260 * rows
    << " font 'sans,9'; set output svg_file }\n"
    << "  set multiplot layout " << rows << "," << columns << "\n";
  const std::size_t R = r.rules.size();
  std::vector<std::string> titles;
  for (Rule rule : all_rules) titles.push_back(rule_label(rule));
  for (const char* t : {"CRULE max-volume", "CRULE centroid", "CRULE max-trace", "CRULE cone mean"}) titles.push_back(t);
  for (std::size_t i = 0; i < rows; ++i)
    for (int panel = 0; panel < 2; ++panel) {  // mean error, then mean worst case
      g << "  set ylabel '" << lights[i] << (panel ? ": mean worst case (deg)'\n" : ": mean error (deg)'\n")
        << "  plot ";
      for (std::size_t k = 0; k < R; ++k)
        g << (k ? ", '' " : ("'" + stem + ".dat' ")) << "index " << i << " using 1:"
          << 2 + panel * R + k << " with linespoints ls " << k + 1 << " title '" << titles[k] << "'";
      g << "\n";
      if (panel == 1 && columns == 3) {  // recovery error of the rules and the baselines
        g << "  set ylabel '" << lights[i] << ": mean recovery (deg)'\n  plot ";
        const char* baseline_titles[] = {"grey world", "max-RGB"};
        for (std::size_t k = 0; k < R + r.baselines.size(); ++k)
          g << (k ? ", '' " : ("'" + stem + ".dat' ")) << "index " << i << " using 1:" << 2 + 2 * R + k
            << " with linespoints ls " << k + 1 << " title '" << (k < R ? titles[k] : baseline_titles[k - R]) << "'";
        g << "\n";
      }
    }
  g << "  unset multiplot\n  set output\n}\n";
  return g.str();
}

}  // namespace gmcc
