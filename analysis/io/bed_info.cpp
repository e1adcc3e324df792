/* ----------------------------------------------------------------------
   granpen analysis: reader of in.pour's bed .info files (see bed_info.h).
------------------------------------------------------------------------- */

#include "bed_info.h"

#include "text_util.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace granpen {

namespace {

bool is_numeric_key(const std::string &k)
{
  for (const char *n : {"seed", "mu", "grains", "z_s", "phi_0", "wall_seconds", "steps"})
    if (k == n) return true;
  return false;
}

}    // namespace

std::string bed_name(const std::string &text)
{
  std::string s = trim(text);
  auto slash = s.find_last_of('/');
  if (slash != std::string::npos) s = s.substr(slash + 1);
  for (const std::string ext : {".restart", ".info"})
    if (s.size() > ext.size() && s.compare(s.size() - ext.size(), ext.size(), ext) == 0)
      s.resize(s.size() - ext.size());
  return s;
}

BedInfo parse_bed_info(const std::string &text, const std::string &name)
{
  BedInfo b;
  b.path = name;
  b.name = bed_name(name);
  std::map<std::string, double> num;
  std::istringstream in(text);
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    const std::string s = trim(line);
    if (s.empty() || s[0] == '#') continue;
    const auto eq = s.find('=');
    if (eq == std::string::npos) fail_at(name, lineno, "expected 'key = value', found '" + s + "'");
    const std::string key = trim(s.substr(0, eq)), val = trim(s.substr(eq + 1));
    if (key.empty()) fail_at(name, lineno, "empty key in '" + s + "'");
    if (key.find_first_of(" \t") != std::string::npos)
      fail_at(name, lineno, "key '" + key + "' contains white space");
    if (b.keys.count(key)) fail_at(name, lineno, "key '" + key + "' given twice");
    b.keys[key] = val;
    if (is_numeric_key(key)) {
      char *end = nullptr;
      errno = 0;
      const double v = std::strtod(val.c_str(), &end);
      if (val.empty() || end != val.c_str() + val.size() || errno == ERANGE || !std::isfinite(v))
        fail_at(name, lineno, key + " '" + val + "' is not a finite number");
      num[key] = v;
    }
  }
  for (const char *req : {"mu", "phi_0"})
    if (!num.count(req)) throw InputError(name + ": missing key '" + req + "'");
  auto get = [&](const char *k) { return num.count(k) ? num[k] : 0.0; };
  b.mu = get("mu");
  b.phi_0 = get("phi_0");
  b.seed = get("seed");
  b.grains = get("grains");
  b.z_s = get("z_s");
  b.wall_seconds = get("wall_seconds");
  b.steps = get("steps");
  b.has_seed = num.count("seed") > 0;
  b.has_z_s = num.count("z_s") > 0;
  if (b.keys.count("preset")) b.preset = b.keys["preset"];
  return b;
}

BedInfo read_bed_info(const std::string &path)
{
  std::string text;
  if (!read_text_file(path, text)) throw InputError(path + ": cannot open bed info file");
  return parse_bed_info(text, path);
}

}    // namespace granpen
