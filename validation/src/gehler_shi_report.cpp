#include <gmcc/validation/gehler_shi_report.h>

#include <cstdio>
#include <ostream>
#include <sstream>

namespace gmcc {

namespace {

// Each camera's images, patches and canonical gamut.
void camera_lines(std::ostream& out, const GehlerShiSetup& setup) {
  char line[512];
  for (const GehlerShiCamera& c : setup.cameras) {
    std::snprintf(line, sizeof line, "  %s: %zu images, %zu usable patches, %zu dropped (near-black or clipped), %zu missing",
                  c.camera.c_str(), c.images, c.usable_patches, c.dropped_patches, c.missing_patches);
    out << line;
    if (c.excluded_patches) out << ", " << c.excluded_patches << " left out by --exclude-patches";
    out << "; canonical gamut " << c.hull_vertices << " vertices";
    if (c.canonical_images.empty()) {
      out << " (all images), recomputed without each of the " << c.recomputed_hulls
          << " images with a patch at a vertex\n";
    } else {
      out << " (chart of";
      for (const std::string& name : c.canonical_images) out << ' ' << name;
      out << "); test images: " << c.yellowish << " yellowish, " << c.bluish << " bluish, " << c.untested
          << " neither\n";
    }
  }
}

// Recovery angular error (mean / median) per light group and surface count, rules and baselines.
void recovery_table(std::ostream& out, const ExperimentResult& r) {
  char line[512];
  const std::size_t R = r.rules.size(), B = r.baselines.size();
  std::string group;
  for (const ExperimentCell& c : r.cells) {
    if (c.light != group) {
      group = c.light;
      out << "\n" << group << "\n  n  scenes  empty   ";
      for (std::size_t k = 0; k < R; ++k) {
        std::snprintf(line, sizeof line, "%-17s", r.rules[k].c_str());
        out << line;
      }
      for (std::size_t b = 0; b < B; ++b) {
        std::snprintf(line, sizeof line, "%-17s", r.baselines[b].c_str());
        out << line;
      }
      for (std::size_t b = 0; b < B; ++b) {
        std::snprintf(line, sizeof line, "%-17s", (r.baselines[b] + " (all)").c_str());
        out << line;
      }
      out << "\n";
    }
    std::snprintf(line, sizeof line, "  %-2d %6llu %5.1f%%  ", c.surfaces, static_cast<unsigned long long>(c.scenes),
                  c.scenes ? 100.0 * static_cast<double>(c.empty) / static_cast<double>(c.scenes) : 0.0);
    out << line;
    auto cell = [&](const ErrorStatistics& e) {
      if (e.n == 0) std::snprintf(line, sizeof line, " %7s /%7s", "-", "-");  // no scene to average
      else std::snprintf(line, sizeof line, " %7.2f /%7.2f", e.mean, e.median);
      out << line;
    };
    for (std::size_t k = 0; k < R; ++k) cell(c.rules[k].illuminant);
    for (std::size_t b = 0; b < B; ++b) cell(c.baselines[b].illuminant);
    for (std::size_t b = 0; b < B; ++b) cell(c.baselines_all[b].illuminant);
    out << "\n";
  }
}

// The paper's map-space error, its worst case, truth in F and the reproduction error.
void map_error_table(std::ostream& out, const ExperimentResult& r) {
  char line[512];
  const std::size_t B = r.baselines.size();
  std::string group;
  for (const ExperimentCell& c : r.cells) {
    if (c.light != group) {
      group = c.light;
      out << "\n" << group << "\n  n   error: max-area  2-D mean  3-D mean   worst case: max-area  2-D mean  "
                               "3-D mean   truth in F   reproduction: 3-D mean  grey world\n";
    }
    // The paper's three rules (a rule added to rule.h is in the CSV, JSON and records).
    const auto& s = c.rules;
    const RuleStats &area = s[static_cast<std::size_t>(Rule::max_area)], &mean2 = s[static_cast<std::size_t>(Rule::mean_2d)],
                    &mean3 = s[static_cast<std::size_t>(Rule::mean_3d)];
    const std::uint64_t answered = c.scenes - c.empty;
    std::snprintf(line, sizeof line, "  %-3d %16.3f %9.3f %9.3f %22.3f %9.3f %9.3f %11.1f%% %23.3f %10.3f\n",
                  c.surfaces, area.error.mean, mean2.error.mean, mean3.error.mean, area.worst_case.mean,
                  mean2.worst_case.mean, mean3.worst_case.mean,
                  answered ? 100.0 * static_cast<double>(mean3.truth_in_feasible_set) / static_cast<double>(answered) : 0.0,
                  mean3.reproduction.mean, B ? c.baselines[0].reproduction.mean : 0.0);
    out << line;
  }
}

}  // namespace

std::string gehler_shi_table(const ExperimentResult& r, const GehlerShiSetup& setup) {
  std::ostringstream out;
  out << "gmcc reproduce gehler-shi: " << r.figure << "; " << r.config.scenes
      << " scenes per image and count, seed " << r.config.seed << ", canonical light (1, 1, 1), expansion "
      << to_string(r.config.expansion.policy);
  if (r.config.expansion.policy != ExpansionPolicy::none) out << " by " << to_string(r.config.expansion.factor);
  out << "\n";
  camera_lines(out, setup);
  out << "\nrecovery angular error in degrees (true vs estimated illuminant), mean / median over the scenes\n"
         "with a feasible map; baselines on the same scenes, and (all) over every scene\n";
  recovery_table(out, r);
  out << "\nmap-space angular error (the paper's measure) and its worst case, means in degrees; truth in F:\n"
         "share of answered scenes whose true map lies in the feasible set\n";
  map_error_table(out, r);
  out << "\nEvery statistic of every cell (se, trimean, best/worst 25%, p95, max) is in --csv and --json\n"
         "(docs/reproduction.md \"Real camera data (Gehler-Shi)\").\n";
  return out.str();
}

}  // namespace gmcc
