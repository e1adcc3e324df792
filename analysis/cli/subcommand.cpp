// granpen subcommands: the option parser and the top-level handler (subcommand.h).
#include "subcommand.h"

#include "args.h"
#include "input_refused.h"

#include <cstdio>
#include <new>

namespace granpen {
namespace cli {

namespace {

// CLI11's default help without its own usage line: the prose starts with granpen's.
class Formatter : public CLI::Formatter {
 public:
  std::string make_usage(const CLI::App *, std::string) const override { return ""; }
  std::string make_description(const CLI::App *app) const override { return app->get_description(); }
  // the value's name alone ("--axis X Y"): ranges and defaults are in the description
  std::string make_option_opts(const CLI::Option *opt) const override
  {
    std::string out;
    if (opt->get_type_size() != 0 && !opt->get_type_name().empty()) out += " " + opt->get_type_name();
    if (opt->get_required()) out += " (required)";
    return out;
  }
  // no "Positionals:" list: the usage line names them
  std::string make_positionals(const CLI::App *) const override { return ""; }
};

// A text from the C++ library rather than from granpen: one word, no blank ("stod",
// "basic_string::_M_create", "map::at").
bool library_text(const std::string &what) { return what.find(' ') == std::string::npos; }

void report(const char *name, const std::string &what)
{
  std::fprintf(stderr, "granpen %s: error: %s\n", name, what.c_str());
}

}    // namespace

CLI::Validator finite_number(bool accept_underflow)
{
  return CLI::Validator(
      [accept_underflow](std::string &s) -> std::string {
        double v;
        return number_arg(s, v, accept_underflow) ? std::string() : "needs a number, got '" + s + "'";
      },
      "");
}

CLI::Validator positive_number()
{
  return CLI::Validator(
      [](std::string &s) -> std::string {
        double v;
        if (!number_arg(s, v)) return "needs a number, got '" + s + "'";
        return v > 0 ? std::string() : "must be > 0, got '" + s + "'";
      },
      "");
}

CLI::Validator non_negative_number()
{
  return CLI::Validator(
      [](std::string &s) -> std::string {
        double v;
        if (!number_arg(s, v)) return "needs a number, got '" + s + "'";
        return v >= 0 ? std::string() : "must be >= 0, got '" + s + "'";
      },
      "");
}

CLI::Validator whole_number(long long lo, long long hi)
{
  return CLI::Validator(
      [lo, hi](std::string &s) -> std::string {
        long long v;
        if (integer_arg(s, v) && v >= lo && v <= hi) return std::string();
        return "must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) + ", got '" + s + "'";
      },
      "");
}

CLI::Validator file_name()
{
  return CLI::Validator([](std::string &s) { return s.empty() ? std::string("needs a name") : std::string(); }, "");
}

Command::Command(const std::string &name, const std::string &prose) : app(prose, "granpen " + name), name_(name)
{
  auto formatter = std::make_shared<Formatter>();
  formatter->column_width(24);
  app.formatter(formatter);
  app.allow_extras();    // unknown words are named below, in granpen's wording
  app.set_help_flag("-h,--help", "this help");
}

CLI::Option *Command::number(const std::string &flag, double &v, const std::string &what, bool accept_underflow)
{
  return app.add_option(flag, v, what)->check(finite_number(accept_underflow));
}

bool Command::parse(int argc, char **argv, std::string &help)
{
  if (argc < 1) throw UsageError("", app.help());
  std::vector<std::string> words(argv, argv + argc);
  std::vector<std::string> reversed(words.rbegin(), words.rend());
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp &) {
    help = app.help();
    return false;
  } catch (const CLI::ValidationError &e) {
    refuse_unknown_words();
    // CLI11 writes "--band: needs a number, got 'wide'"; granpen has always written it
    // without the colon
    std::string what = e.what();
    const auto colon = what.find(": ");
    if (what.compare(0, 2, "--") == 0 && colon != std::string::npos) what.erase(colon, 1);
    throw UsageError(what);
  } catch (const CLI::ParseError &e) {
    refuse_unknown_words();    // an unknown option explains a missing one best
    throw UsageError(e.what());
  }
  refuse_unknown_words();
  return true;
}

void Command::refuse_unknown_words() const
{
  // "--", the end of the options (the words after it are positional), is what CLI11
  // leaves among the remaining words when extras are allowed: not an unknown option
  std::vector<std::string> rest;
  for (const auto &w : app.remaining())
    if (w != "--") rest.push_back(w);
  for (const auto &w : rest)
    if (w.size() > 1 && w[0] == '-') throw UsageError("unknown option '" + w.substr(0, w.find('=')) + "'");
  if (!rest.empty()) throw UsageError("unexpected argument '" + rest.front() + "'");
}

std::string user_text(const std::exception &e)
{
  const std::string what = e.what();
  if (dynamic_cast<const std::bad_alloc *>(&e))
    return "out of memory (an input or an option asks for more than this machine has)";
  if (!library_text(what)) return what;
  if (dynamic_cast<const std::invalid_argument *>(&e)) return "a value is not a number";
  if (dynamic_cast<const std::out_of_range *>(&e)) return "a value is out of range";
  return "internal failure; please report it with the command line";
}

int run_subcommand(const char *name, int (*fn)(int, char **), int argc, char **argv)
{
  try {
    return fn(argc, argv);
  } catch (const UsageError &e) {
    if (*e.what()) {
      report(name, e.what());
      std::fprintf(stderr, "(granpen %s --help for usage)\n", name);
    } else {
      std::fputs(e.usage.c_str(), stderr);
    }
    return EXIT_USAGE;
  } catch (const CLI::Error &e) {
    report(name, e.what());
    return EXIT_USAGE;
  } catch (const InputRefused &e) {
    report(name, e.what());
    return EXIT_USAGE;
  } catch (const std::exception &e) {
    report(name, user_text(e));
  } catch (...) {
    report(name, "internal failure; please report it with the command line");
  }
  return EXIT_FAILED;
}

}    // namespace cli
}    // namespace granpen
