// gmcc: gamut-mapping colour constancy with exact geometry. The command line's one edge where
// errors become messages and exit statuses: 0 success, 2 bad input or usage, 1 internal error.
#include "accuracy.h"
#include "reproduce.h"
#include "select.h"

#include <gmcc/validation/colour_csv.h>

#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"gmcc — gamut-mapping colour constancy with exact geometry "
               "(Finlayson & Hordley 1999, \"Selection for gamut mapping colour constancy\")"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "gmcc 0.1.0");
  gmcc::cli::SelectOptions select_options;
  CLI::App* select = gmcc::cli::add_select_command(app, select_options);
  gmcc::cli::AccuracyOptions accuracy_options;
  CLI::App* accuracy = gmcc::cli::add_accuracy_command(app, accuracy_options);
  gmcc::cli::ReproduceOptions reproduce_options;
  CLI::App* reproduce = gmcc::cli::add_reproduce_command(app, reproduce_options);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "gmcc: error: " << e.what() << "\nRun with --help for usage.\n";
    return 2;
  }
  try {
    if (select->parsed()) return gmcc::cli::run_select(select_options);
    if (accuracy->parsed()) return gmcc::cli::run_accuracy(accuracy_options);
    if (reproduce->parsed()) return gmcc::cli::run_reproduce(*reproduce, reproduce_options);
  } catch (const gmcc::InputError& e) {
    std::cerr << "gmcc: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "gmcc: internal error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
