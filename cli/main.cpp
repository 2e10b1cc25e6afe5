// gmcc: gamut-mapping colour constancy with exact geometry. The command line's one edge where
// errors become messages and exit statuses: 0 success, 2 bad input or usage, 1 internal error;
// a signal ends the run with its default action, temporary files removed (docs/cli.md).
#include "accuracy.h"
#include "exit_cleanup.h"
#include "reproduce.h"
#include "select.h"
#include "write_stdout.h"

#include <gmcc/validation/colour_csv.h>

#include <CLI/CLI.hpp>

#include <exception>
#include <functional>
#include <iostream>
#include <sstream>

namespace {

// The command named on the command line, as far as it goes: "gmcc", "gmcc select",
// "gmcc reproduce synthetic" (for the usage hint).
std::string command_of(CLI::App& app, int argc, char** argv) {
  const std::function<bool(CLI::App*)> every = [](CLI::App*) { return true; };
  CLI::App* current = &app;
  std::string command = "gmcc";
  for (int i = 1; i < argc; ++i)
    for (CLI::App* sub : current->get_subcommands(every))
      if (sub->get_name() == argv[i]) {
        current = sub;
        command += " " + sub->get_name();
        break;
      }
  return command;
}

// Help and version text go through write_stdout: `gmcc --help > /dev/full` must fail too.
int print_help_or_version(const CLI::App& app, const CLI::Error& e) {
  std::ostringstream out, err;
  const int status = app.exit(e, out, err);
  try {
    gmcc::cli::write_stdout(out.str());
  } catch (const gmcc::InputError& error) {
    std::cerr << "gmcc: error: " << error.what() << "\n";
    return 2;
  }
  std::cerr << err.str();
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  gmcc::cli::install_exit_cleanup();
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
    return print_help_or_version(app, e);
  } catch (const CLI::CallForAllHelp& e) {
    return print_help_or_version(app, e);
  } catch (const CLI::CallForVersion& e) {
    return print_help_or_version(app, e);
  } catch (const CLI::ParseError& e) {
    // One line, like every other error.
    std::string problem = e.what();
    for (char& c : problem)
      if (c == '\n' || c == '\r') c = ' ';
    std::cerr << "gmcc: error: " << problem << " (run " << command_of(app, argc, argv)
              << " --help for usage)\n";
    return 2;
  }
  try {
    int status = 0;
    if (select->parsed()) status = gmcc::cli::run_select(select_options);
    else if (accuracy->parsed()) status = gmcc::cli::run_accuracy(accuracy_options);
    else if (reproduce->parsed()) status = gmcc::cli::run_reproduce(*reproduce, reproduce_options);
    gmcc::cli::write_stdout("");  // what a command wrote without write_stdout, flushed and checked
    return status;
  } catch (const gmcc::InputError& e) {
    std::cerr << "gmcc: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "gmcc: internal error: " << e.what() << "\n";
    return 1;
  }
}
