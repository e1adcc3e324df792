// The bed .info reader (io/bed_info.h): in.pour's format read back, and malformed lines
// rejected naming file:line.
#include "bed_info.h"
#include "errors.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <string>

using namespace granpen;

namespace {

const char *GOOD_INFO = "# granpen bed: preset bench, seed 4242, mu 0.3\n"
                        "preset = bench\nseed = 4242\nmu = 0.3\ngrains = 6300\n"
                        "z_s = 5.69832257381603\nphi_0 = 0.578884793470033\n"
                        "wall_seconds = 58.8\nsteps = 100000\n";

void expect_rejected(const std::string &text, const std::string &pattern)
{
  try {
    parse_bed_info(text, "beds/bad.info");
    FAIL() << "accepted; expected an error matching " << pattern;
  } catch (InputError &e) {
    EXPECT_TRUE(std::regex_search(e.what(), std::regex(pattern))) << e.what();
  }
}

}    // namespace

TEST(BedInfo, ReadsInPourFormat)
{
  const BedInfo b = parse_bed_info(GOOD_INFO, "sweep/beds/bed_mu0.3_s4242.info");
  EXPECT_EQ(b.name, "bed_mu0.3_s4242");
  EXPECT_EQ(b.preset, "bench");
  EXPECT_DOUBLE_EQ(b.mu, 0.3);
  EXPECT_DOUBLE_EQ(b.phi_0, 0.578884793470033);
  EXPECT_DOUBLE_EQ(b.z_s, 5.69832257381603);
  EXPECT_EQ(b.seed, 4242.0);
  EXPECT_EQ(b.grains, 6300.0);
  EXPECT_EQ(b.steps, 100000.0);
  EXPECT_DOUBLE_EQ(b.wall_seconds, 58.8);
  EXPECT_EQ(bed_name("runs/bed_3.restart"), "bed_3");
  EXPECT_EQ(bed_name(" bed_3 "), "bed_3");
}

TEST(BedInfo, RejectsMalformedLinesWithFileAndLine)
{
  expect_rejected("# granpen bed\nmu = 0.3\ngrains 6300\nphi_0 = 0.6\n",
                  "^beds/bad\\.info:3: expected 'key = value', found 'grains 6300'");
  expect_rejected("mu = 0.3\n= 4\nphi_0 = 0.6\n", "^beds/bad\\.info:2: empty key");
  expect_rejected("mu = 0.3\nphi_0 = 0.6\nmu = 0.4\n", "^beds/bad\\.info:3: key 'mu' given twice");
  expect_rejected("mu = 0.3x\nphi_0 = 0.6\n", "^beds/bad\\.info:1: mu '0\\.3x' is not a finite number");
  expect_rejected("mu = 0.3\nphi_0 = nan\n", "^beds/bad\\.info:2: phi_0 'nan' is not a finite number");
  expect_rejected("mu = 0.3\nz_s = 5.7\n", "^beds/bad\\.info: missing key 'phi_0'");
  expect_rejected("phi_0 = 0.6\n", "^beds/bad\\.info: missing key 'mu'");
}

TEST(BedInfo, ReadsFileAndNamesIt)
{
  const std::string path = testing::TempDir() + "granpen_bed_bad.info";
  {
    std::ofstream f(path);
    f << "# granpen bed\nmu = 0.3\nphi_0 = 0.6\nz_s 5.7\n";
  }
  try {
    read_bed_info(path);
    FAIL() << "accepted a malformed line";
  } catch (InputError &e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ":4: ", 0), 0u) << e.what();
  }
  std::remove(path.c_str());
  EXPECT_THROW(read_bed_info(path), InputError);
}
