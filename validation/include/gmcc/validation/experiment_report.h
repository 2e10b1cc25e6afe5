#pragma once
/// \file experiment_report.h
/// Reports of an experiment: CSV, a text table laid out like the paper's Fig. 3, and gnuplot
/// data and script for the figure (one row per light: mean error and mean worst-case error
/// against the number of surfaces, one line per rule). Deterministic text: the same result
/// gives the same bytes.

#include <gmcc/validation/gamut_experiment.h>

#include <string>

namespace gmcc {

/// One row per (light, surfaces, rule), with the columns
/// illuminant,surfaces,rule,mean_error_deg,mean_worst_case_deg,scenes,median_error_deg,
/// median_worst_case_deg,mean_illuminant_error_deg,median_illuminant_error_deg,
/// mean_reproduction_error_deg,max_error_deg,empty_scenes,truth_in_feasible_set.
/// `scenes` counts the scenes that had a feasible map (those averaged); `empty_scenes` the others.
std::string experiment_csv(const ExperimentResult& result);

/// A readable table: per light, mean map-space error and mean worst case per rule and count,
/// and the 3-D mean's improvement over the better of the other two.
std::string experiment_table(const ExperimentResult& result);

/// gnuplot data (one block per light) and a script that reads it from `stem`.dat and writes
/// the PNG and SVG named by the variables png_file and svg_file.
std::string experiment_plot_data(const ExperimentResult& result);
std::string experiment_plot_script(const ExperimentResult& result, const std::string& stem);

}  // namespace gmcc
