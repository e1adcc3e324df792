// granpen subcommands: the one option parser (CLI11) and the one top-level error handler.
// A subcommand is a parse function (NAME_options.h: words -> a typed options struct, no
// I/O, usage errors thrown as UsageError) and a run function (NAME_cmd.cpp: calls the
// library and writes), joined by run_parsed into its entry point (subcommands.h); any
// exception either lets go is turned into "granpen NAME: error: ..." and an exit status
// by run_subcommand.
#ifndef GRANPEN_CLI_SUBCOMMAND_H
#define GRANPEN_CLI_SUBCOMMAND_H

#include <CLI/CLI.hpp>

#include <cstdio>

#include <stdexcept>
#include <string>
#include <vector>

namespace granpen {
namespace cli {

// Exit statuses of every subcommand.
enum Exit { EXIT_OK = 0, EXIT_FAILED = 1, EXIT_USAGE = 2 };

// What every parse returns besides its options: --help's text when --help was asked for
// (every other field is then its default).
struct ParsedCommand {
  std::string help;
  bool help_requested() const { return !help.empty(); }
};

// A usage error (an option's value against its meaning, options that contradict each
// other): exit 2. An empty message with a usage text: no words at all, the usage (the
// help) is printed on stderr instead of a message.
class UsageError : public std::runtime_error {
 public:
  explicit UsageError(const std::string &what, const std::string &usage = "") : std::runtime_error(what), usage(usage) {}
  std::string usage;
};

// A value check for CLI11: a whole finite number (args.h's number_arg), else
// "needs a number, got 'V'".
CLI::Validator finite_number(bool accept_underflow = false);
// a whole number > 0 / >= 0
CLI::Validator positive_number();
CLI::Validator non_negative_number();
// a whole number from lo to hi (a count, a run number), else "must be a whole number
// from LO to HI, got 'V'"
CLI::Validator whole_number(long long lo, long long hi);
// a file or folder name: not empty
CLI::Validator file_name();

// The parser of one subcommand. Its --help prints the prose (usage line, what it does,
// outputs, exit status) and then the options as CLI11 lists them.
class Command {
 public:
  Command(const std::string &name, const std::string &prose);
  CLI::App app;

  // A number option bound to v: checked as a finite number (with lo/hi bounds when given).
  CLI::Option *number(const std::string &flag, double &v, const std::string &what, bool accept_underflow = false);
  // argv[0] is the first word after the subcommand. false: --help was asked for, its text
  // in help. No words at all: UsageError("", the help). A parse error (unknown option,
  // missing or bad value) throws UsageError naming the option. Prints nothing.
  bool parse(int argc, char **argv, std::string &help);

  const std::string &name() const { return name_; }

 private:
  // UsageError for the first word no option took: an unknown option, else a stray argument
  void refuse_unknown_words() const;
  std::string name_;
};

// What an exception says to the user: its message, or for the C++ library's own terse
// texts ("stod", "basic_string::_M_create", std::bad_alloc) what they mean.
std::string user_text(const std::exception &e);

// Runs fn(argc, argv) for subcommand name, the top-level handler: UsageError, CLI11's
// errors and InputRefused (io/input_refused.h) -> "granpen NAME: error: ..." and 2; any other exception (InputError,
// OutputError, std::bad_alloc, std::invalid_argument, ...) -> "granpen NAME: error: ..."
// and 1, the C++ library's own terse texts ("stod", "basic_string::...") replaced by
// what they mean.
int run_subcommand(const char *name, int (*fn)(int, char **), int argc, char **argv);

// A subcommand's entry point (subcommands.h): parse, then --help's text on stdout (exit 0)
// or run.
template <class Options>
int run_parsed(Options (*parse)(int, char **), int (*run)(const Options &), int argc, char **argv)
{
  const Options o = parse(argc, argv);
  if (o.help_requested()) {
    std::fputs(o.help.c_str(), stdout);
    return EXIT_OK;
  }
  return run(o);
}

}    // namespace cli
}    // namespace granpen

#endif
