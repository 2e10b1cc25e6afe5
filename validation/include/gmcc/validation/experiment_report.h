#pragma once
/// \file experiment_report.h
/// Reports of an experiment: CSV, JSON, per-scene JSON Lines, a text table laid out like the
/// paper's figure (Fig. 3 for the synthetic experiment, Fig. 5 for the camera analogue), and
/// gnuplot data and script for the figure (one row per light: mean error and mean worst-case
/// error against the number of surfaces, one line per rule). Deterministic text: the same result
/// gives the same bytes. Every statistic comes from error_statistics.h.

#include <gmcc/validation/gamut_experiment.h>

#include <string>
#include <vector>

namespace gmcc {

/// One row per (light, surfaces, rule), with the columns
/// illuminant,surfaces,rule,mean_error_deg,mean_worst_case_deg,scenes,median_error_deg,
/// median_worst_case_deg,mean_illuminant_error_deg,median_illuminant_error_deg,
/// mean_reproduction_error_deg,max_error_deg,empty_scenes,truth_in_feasible_set, then the
/// columns of experiment_csv_added_columns (docs/cli.md lists them all).
/// `scenes` counts the scenes that had a feasible map (those averaged); `empty_scenes` the others.
/// With baselines (ExperimentResult::baselines), each cell's rules are followed by a row per
/// baseline over the same scenes, then one per baseline named `<baseline>_all` over every scene
/// (`scenes` = all of them); their worst-case and truth_in_feasible_set fields are empty.
/// \param result the experiment's result (run_gamut_experiment, or merged shards).
/// \param provenance a JSON object (docs/cli.md "Provenance") written first as the comment line
///        `# gmcc-provenance: …`; none when empty.
std::string experiment_csv(const ExperimentResult& result, const std::string& provenance = {});

/// The columns experiment_csv appends to the original fourteen, in order: for each quantity
/// (error, worst_case, illuminant_error, reproduction_error) the statistics of ErrorStatistics
/// not among the fourteen (se_, median_, trimean_, best25_, worst25_, p95_, max_ + quantity +
/// _deg), then positive_map_scenes.
std::vector<std::string> experiment_csv_added_columns();

/// The setup of an experiment as one JSON object on one line (no newline): experiment, figure,
/// lights, rules, surface counts, scenes, seed, expansion, noise, shading, crule, mean3d,
/// canonical gamut and constraint (exact vertices), and `shard` when the run was a part.
/// The first line of experiment_scenes_jsonl and the `setup` member of experiment_json.
std::string experiment_setup_json(const ExperimentResult& result);

/// Per-scene records (ExperimentResult::scenes) as JSON Lines: the setup object, then one object
/// per scene in canonical order (docs/reproduction.md "Per-scene records"). Numbers are the
/// shortest decimal that reads back as the same double, so a merge reproduces every statistic.
/// \param result the experiment's result; its `scenes` (kept with ExperimentConfig::keep_scenes)
///        are written one per line.
/// \param provenance a JSON object written first as the line `{"provenance": …}`; none when empty.
std::string experiment_scenes_jsonl(const ExperimentResult& result, const std::string& provenance = {});

/// The aggregates as one JSON document: `setup`, then `cells`, each with every rule's
/// statistics of the four quantities (numbers as in experiment_scenes_jsonl, NaN as null).
/// \param result the experiment's result.
/// \param provenance a JSON object, the document's first member `provenance`; none when empty.
std::string experiment_json(const ExperimentResult& result, const std::string& provenance = {});

/// A readable table: per light, mean map-space error and mean worst case per rule and count,
/// and the 3-D mean's improvement over the better of the other two; then, per light, count and
/// rule, every statistic of the map-space error.
std::string experiment_table(const ExperimentResult& result);

/// gnuplot data (one block per light) and a script that reads it from `stem`.dat and writes
/// the PNG and SVG named by the variables png_file and svg_file.
std::string experiment_plot_data(const ExperimentResult& result);
/// The gnuplot script of experiment_plot_data: a row of panels per light laid out like the paper's
/// figure (mean error and mean worst case against the number of surfaces, one line per rule).
/// \param result the experiment's result. \param stem the data file's name without `.dat`.
std::string experiment_plot_script(const ExperimentResult& result, const std::string& stem);

}  // namespace gmcc
