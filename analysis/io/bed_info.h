/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: reader of the NAME.info file that inputs/in.pour writes
   beside each bed (NAME.restart):

     # granpen bed: preset bench, seed 4242, mu 0.3
     preset = bench
     seed = 4242
     mu = 0.3
     grains = 6300
     z_s = 5.69832257381603
     phi_0 = 0.578884793470033
     wall_seconds = 58.8
     steps = 100000

   Lines starting with '#' and blank lines are comments. Every other line must be
   'key = value' with a non-empty key, each key at most once; the numeric keys
   (seed, mu, grains, z_s, phi_0, wall_seconds, steps) must hold finite numbers.
   mu and phi_0 are required. Rejections throw InputError naming file:line (or
   the file, for a missing key).
------------------------------------------------------------------------- */

#ifndef GRANPEN_BED_INFO_H
#define GRANPEN_BED_INFO_H

#include "errors.h"

#include <map>
#include <string>

namespace granpen {

struct BedInfo {
  std::string path;
  std::string name;                           // file name without directory and .info
  std::map<std::string, std::string> keys;    // every key, as text
  std::string preset;                         // "" when absent
  double mu = 0.0, phi_0 = 0.0;               // required
  double seed = 0.0, grains = 0.0, z_s = 0.0, wall_seconds = 0.0, steps = 0.0;    // 0 when absent
  bool has_seed = false, has_z_s = false;
};

BedInfo read_bed_info(const std::string &path);
BedInfo parse_bed_info(const std::string &text, const std::string &name);

// The bed name a trace's 'bed' header may give: directory and a .restart or .info
// suffix dropped ("runs/bed_3.restart" -> "bed_3").
std::string bed_name(const std::string &text);

}    // namespace granpen

#endif
