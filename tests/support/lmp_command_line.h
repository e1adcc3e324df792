// The command line the sweep runner gives lmp_granpen, as its stand-ins (fake_lmp,
// fault_lmp) read it: -in DECK, -log FILE, -screen X (ignored), -var NAME VALUE.
#ifndef GRANPEN_TESTS_LMP_COMMAND_LINE_H
#define GRANPEN_TESTS_LMP_COMMAND_LINE_H

#include <map>
#include <string>

struct LmpCommandLine {
  std::map<std::string, std::string> var;
  std::string in, log;
};

inline LmpCommandLine read_lmp_command_line(int argc, char **argv)
{
  LmpCommandLine c;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-in" && i + 1 < argc) c.in = argv[++i];
    else if (a == "-log" && i + 1 < argc) c.log = argv[++i];
    else if (a == "-screen" && i + 1 < argc) ++i;
    else if (a == "-var" && i + 2 < argc) c.var[argv[i + 1]] = argv[i + 2], i += 2;
  }
  return c;
}

#endif
