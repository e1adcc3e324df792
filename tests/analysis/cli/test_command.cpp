// The top-level handler of granpen-cli (cli/command.h): every exception a subcommand lets
// go becomes "granpen NAME: error: ..." and an exit status; the C++ library's own texts
// never reach the user.
#include "subcommand.h"
#include "trace_reader.h"

#include <gtest/gtest.h>

#include <new>
#include <stdexcept>
#include <string>

namespace {

struct Outcome {
  int status = 0;
  std::string err;
};

Outcome run(int (*fn)(int, char **))
{
  testing::internal::CaptureStderr();
  Outcome o;
  o.status = granpen::cli::run_subcommand("demo", fn, 0, nullptr);
  o.err = testing::internal::GetCapturedStderr();
  return o;
}

int ok(int, char **) { return 0; }
int stod_failure(int, char **) { return (int) std::stod("x"); }
int out_of_memory(int, char **) { throw std::bad_alloc(); }
int input_error(int, char **) { throw granpen::InputError("trace.csv:3: row has 2 fields, expected 3"); }
int usage_error(int, char **) { throw granpen::cli::UsageError("--band must be > 0, got '0'"); }
int library_length(int, char **) { throw std::length_error("basic_string::_M_create"); }
int unknown(int, char **) { throw 42; }

}    // namespace

TEST(TopLevelHandler, ExitStatusAndNamedErrors)
{
  EXPECT_EQ(run(ok).status, 0);
  Outcome o = run(input_error);
  EXPECT_EQ(o.status, 1);
  EXPECT_EQ(o.err, "granpen demo: error: trace.csv:3: row has 2 fields, expected 3\n");
  o = run(usage_error);
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.err, "granpen demo: error: --band must be > 0, got '0'\n(granpen demo --help for usage)\n");
}

TEST(TopLevelHandler, NoRawLibraryText)
{
  Outcome o = run(stod_failure);
  EXPECT_EQ(o.status, 1);
  EXPECT_EQ(o.err, "granpen demo: error: a value is not a number\n");
  o = run(out_of_memory);
  EXPECT_EQ(o.status, 1);
  EXPECT_EQ(o.err.find("bad_alloc"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("granpen demo: error: out of memory"), std::string::npos) << o.err;
  o = run(library_length);
  EXPECT_EQ(o.status, 1);
  EXPECT_EQ(o.err.find("basic_string"), std::string::npos) << o.err;
  o = run(unknown);
  EXPECT_EQ(o.status, 1);
  EXPECT_EQ(o.err, "granpen demo: error: internal failure; please report it with the command line\n");
}
