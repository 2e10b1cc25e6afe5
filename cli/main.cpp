// gmcc: gamut-mapping colour constancy with exact geometry. The command line's one edge where
// errors become messages and exit statuses: 0 success, 2 bad input or usage, 1 internal error,
// 3 a resource limit reached (--time-limit, --memory-limit, memory exhausted); a signal ends
// the run with its default action, temporary files removed (docs/cli.md).
#include "accuracy.h"
#include "benchmark_command.h"
#include "canonical.h"
#include "dataset.h"
#include "estimate.h"
#include "exit_cleanup.h"
#include "integer_option.h"
#include "limit_exit.h"
#include "memory_limit.h"
#include "merge.h"
#include "provenance.h"
#include "reproduce.h"
#include "select.h"
#include "time_limit.h"
#include "write_stdout.h"

#include <gmcc/input/colour_csv.h>

#include <CLI/CLI.hpp>

#include <exception>
#include <functional>
#include <iostream>
#include <memory>
#include <new>
#include <optional>
#include <sstream>
#include <system_error>
#include <vector>

namespace {

// The command named on the command line, as far as it goes: "gmcc", "gmcc select",
// "gmcc reproduce synthetic" (for the usage hint and the limits' messages).
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

// stderr for an error message, on a line of its own (an open progress line ended first).
std::ostream& error_out() {
  gmcc::cli::end_progress_line();
  return std::cerr;
}

// A subcommand: what CLI11 parsed into, and what runs it then (its options live as long as it).
struct Command {
  CLI::App* app;
  std::function<int()> run;
};
template <class Options, class Run>
Command command(CLI::App& app, CLI::App* (*add)(CLI::App&, Options&), Run run) {
  auto options = std::make_shared<Options>();
  CLI::App* cmd = add(app, *options);
  return {cmd, [options, cmd, run] { return run(*cmd, *options); }};
}

}  // namespace

int main(int argc, char** argv) {
  gmcc::cli::install_exit_cleanup();
  gmcc::cli::keep_freed_memory();
  gmcc::cli::install_gmp_allocation_failure_exit();
  CLI::App app{"gmcc — gamut-mapping colour constancy with exact geometry "
               "(Finlayson & Hordley 1999, \"Selection for gamut mapping colour constancy\")"};
  app.require_subcommand(1);
  app.fallthrough();  // the global options below are also read after a command's name
  app.set_version_flag("--version", gmcc::cli::version_line());
  std::string time_limit, memory_limit;
  app.add_option("--time-limit", time_limit,
                 "end the run after this many seconds, with a message and exit status 3 "
                 "(temporary files removed); default: no limit")
      ->type_name("SECONDS");
  app.add_option("--memory-limit", memory_limit,
                 "limit the address space to this many MiB (setrlimit RLIMIT_AS); reaching it "
                 "ends the run with a message and exit status 3; default: no limit")
      ->type_name("MIB");
  // The subcommands in --help's order (cite last), each with its options and what runs it.
  using namespace gmcc::cli;
  const auto plain = [](auto run) { return [run](const CLI::App&, const auto& o) { return run(o); }; };
  const std::vector<Command> commands{
      command(app, add_select_command, plain(run_select)), command(app, add_accuracy_command, plain(run_accuracy)),
      command(app, add_reproduce_command, run_reproduce), command(app, add_estimate_command, plain(run_estimate)),
      command(app, add_merge_command, plain(run_merge)), command(app, add_canonical_command, plain(run_canonical)),
      command(app, add_benchmark_command, plain(run_benchmark_command)),
      command(app, add_dataset_command, plain(run_dataset))};
  CLI::App* cite = app.add_subcommand(
      "cite", "print a BibTeX entry for this build of gmcc (version, git commit, commit date) "
              "and the paper it implements (docs/cli.md \"Provenance\")");
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
    std::optional<gmcc::cli::TimeLimit> watchdog;
    if (!time_limit.empty())
      watchdog.emplace(gmcc::cli::integer_option("--time-limit", time_limit, 1, 10000000));
    if (!memory_limit.empty())
      gmcc::cli::limit_memory(
          gmcc::cli::integer_option("--memory-limit", memory_limit, 1, std::uint64_t(1) << 40));
    gmcc::cli::set_activity("running " + command_of(app, argc, argv));
    gmcc::cli::record_command(app);
    int status = 0;
    if (cite->parsed()) gmcc::cli::write_stdout(gmcc::cli::bibtex_of_this_build());
    for (const Command& c : commands)
      if (c.app->parsed()) status = c.run();
    gmcc::cli::write_stdout("");  // what a command wrote without write_stdout, flushed and checked
    return status;
  } catch (const gmcc::InputError& e) {
    error_out() << "gmcc: error: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    gmcc::cli::exit_out_of_memory();
  } catch (const std::system_error& e) {
    // A thread that could not be made within --memory-limit (its stack is address space).
    if (gmcc::cli::memory_limit_mib() && (e.code() == std::errc::resource_unavailable_try_again ||
                                          e.code() == std::errc::not_enough_memory))
      gmcc::cli::exit_out_of_memory();
    error_out() << "gmcc: internal error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    error_out() << "gmcc: internal error: " << e.what() << "\n";
    return 1;
  }
}
