// core/rate_interval.h: the binomial CDF and the Clopper-Pearson interval against closed
// forms and published values.
#include "rate_interval.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using granpen::binomial_cdf;
using granpen::clopper_pearson;

// the bisection reaches double precision; the closed forms agree to rounding
constexpr double EXACT = 1e-12;
// published values are quoted to 4 significant digits or more (R's binom.test)
constexpr double PUBLISHED = 5e-5;

TEST(BinomialCdf, SumsToOneAndMatchesHandCounts)
{
  // n = 3, p = 0.5: P(X <= 1) = (1 + 3) / 8
  EXPECT_NEAR(binomial_cdf(1, 3, 0.5), 0.5, EXACT);
  // n = 4, p = 0.2: P(X = 0) = 0.8^4
  EXPECT_NEAR(binomial_cdf(0, 4, 0.2), std::pow(0.8, 4), EXACT);
  EXPECT_DOUBLE_EQ(binomial_cdf(4, 4, 0.3), 1.0);
  EXPECT_DOUBLE_EQ(binomial_cdf(-1, 4, 0.3), 0.0);
}

TEST(ClopperPearson, NoEventsHasTheClosedFormUpperEnd)
{
  // k = 0: P(X <= 0) = (1 - p)^n = 0.025 -> p = 1 - 0.025^(1/n); 0 of 20 -> [0, 0.168]
  const auto r = clopper_pearson(0, 20);
  EXPECT_EQ(r.rate, 0.0);
  EXPECT_EQ(r.low, 0.0);
  EXPECT_NEAR(r.high, 1 - std::pow(0.025, 1.0 / 20), EXACT);
  EXPECT_NEAR(r.high, 0.1684, PUBLISHED);
  EXPECT_NEAR(clopper_pearson(0, 46).high, 1 - std::pow(0.025, 1.0 / 46), EXACT);
}

TEST(ClopperPearson, OneEventHasTheClosedFormLowerEnd)
{
  // k = 1: P(X >= 1) = 1 - (1 - p)^n = 0.025 -> p = 1 - 0.975^(1/n)
  EXPECT_NEAR(clopper_pearson(1, 20).low, 1 - std::pow(0.975, 1.0 / 20), EXACT);
}

TEST(ClopperPearson, AgreesWithPublishedValues)
{
  // R: binom.test(1, 20)$conf.int = 0.001265 0.248733; binom.test(3, 10) = 0.066740 0.652453
  auto r = clopper_pearson(1, 20);
  EXPECT_NEAR(r.low, 0.001265, PUBLISHED);
  EXPECT_NEAR(r.high, 0.248733, PUBLISHED);
  r = clopper_pearson(3, 10);
  EXPECT_NEAR(r.rate, 0.3, EXACT);
  EXPECT_NEAR(r.low, 0.066740, PUBLISHED);
  EXPECT_NEAR(r.high, 0.652453, PUBLISHED);
}

TEST(ClopperPearson, IsSymmetricInEventsAndNonEvents)
{
  // the interval of k in n mirrors that of n - k: low(k) = 1 - high(n - k)
  for (int k = 0; k <= 12; ++k) {
    const auto a = clopper_pearson(k, 12), b = clopper_pearson(12 - k, 12);
    EXPECT_NEAR(a.low, 1 - b.high, EXACT) << k;
  }
  EXPECT_EQ(clopper_pearson(10, 10).high, 1.0);
  EXPECT_NEAR(clopper_pearson(10, 10).low, std::pow(0.025, 1.0 / 10), EXACT);
}

TEST(ClopperPearson, RefusesWhatIsNotARate)
{
  EXPECT_THROW(clopper_pearson(0, 0), std::invalid_argument);
  EXPECT_THROW(clopper_pearson(3, 2), std::invalid_argument);
  EXPECT_THROW(clopper_pearson(-1, 2), std::invalid_argument);
  EXPECT_THROW(clopper_pearson(1, 2, 1.0), std::invalid_argument);
}
