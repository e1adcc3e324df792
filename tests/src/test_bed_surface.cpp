// Bed surface: column maxima and their mean, against hand-built beds.
#include "bed_surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace granpen;

TEST(BedSurface, ColumnsSpanTheBox)
{
  SurfaceGrid g{0.0, 8.0, 0.0, 8.0, 4};
  EXPECT_EQ(column_of(g, 0.1, 0.1), 0);
  EXPECT_EQ(column_of(g, 2.1, 0.1), 1);
  EXPECT_EQ(column_of(g, 0.1, 2.1), 4);
  EXPECT_EQ(column_of(g, 7.9, 7.9), 15);
  EXPECT_EQ(column_of(g, 8.0, 8.0), 15);     // on the upper edge
  EXPECT_EQ(column_of(g, -0.01, 3.0), 4);    // just outside goes to the edge column
}

TEST(BedSurface, MeanOfHighestTopPerColumn)
{
  // a tilted surface: column (ix, iy) tops out at 5 + 0.1 ix; a low grain in each column too
  SurfaceGrid g{0.0, 8.0, 0.0, 8.0, 4};
  std::vector<double> x, y, top;
  double expect = 0.0;
  for (int iy = 0; iy < 4; ++iy)
    for (int ix = 0; ix < 4; ++ix) {
      double h = 5.0 + 0.1 * ix;
      x.insert(x.end(), {2.0 * ix + 1.0, 2.0 * ix + 0.5});
      y.insert(y.end(), {2.0 * iy + 1.0, 2.0 * iy + 1.5});
      top.insert(top.end(), {h, 1.0});
      expect += h / 16.0;
    }
  std::vector<double> col(16, EMPTY_COLUMN);
  column_max_tops(g, x.data(), y.data(), top.data(), x.size(), col);
  int nempty = -1;
  EXPECT_NEAR(surface_from_columns(col, nempty), expect, 1e-12);
  EXPECT_EQ(nempty, 0);
}

TEST(BedSurface, SplitAcrossRanksGivesTheSameAnswer)
{
  // two "ranks" each see half the grains; MAX-combining their columns equals one pass
  SurfaceGrid g{0.0, 4.0, 0.0, 4.0, 2};
  std::vector<double> x = {0.5, 1.5, 2.5, 3.5, 0.5, 3.5};
  std::vector<double> y = {0.5, 1.5, 0.5, 3.5, 3.5, 0.5};
  std::vector<double> t = {2.0, 3.0, 4.0, 1.0, 6.0, 7.0};
  std::vector<double> all(4, EMPTY_COLUMN), a(4, EMPTY_COLUMN), b(4, EMPTY_COLUMN);
  column_max_tops(g, x.data(), y.data(), t.data(), 6, all);
  column_max_tops(g, x.data(), y.data(), t.data(), 3, a);
  column_max_tops(g, x.data() + 3, y.data() + 3, t.data() + 3, 3, b);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(std::max(a[c], b[c]), all[c]);
  int n;
  EXPECT_NEAR(surface_from_columns(all, n), (3.0 + 7.0 + 6.0 + 1.0) / 4.0, 1e-12);
}

TEST(BedSurface, EmptyColumnsAreSkippedAndAllEmptyIsNaN)
{
  std::vector<double> col(16, EMPTY_COLUMN);
  int nempty = 0;
  EXPECT_TRUE(std::isnan(surface_from_columns(col, nempty)));
  EXPECT_EQ(nempty, 16);
  col[3] = 4.0;
  col[7] = 6.0;
  EXPECT_NEAR(surface_from_columns(col, nempty), 5.0, 1e-12);
  EXPECT_EQ(nempty, 14);
}
