// Block averages, their standard error, and the Flyvbjerg-Petersen blocking analysis; see block_average.hpp.
// Sums run in long double: the series are short (thousands of values), and the variance of values that
// differ in their last digits (a gas at equilibrium) must not drown in the rounding of the mean.
// Rejected: a one-pass (Welford) variance, which buys nothing for series that are already in memory.
#include "ede/analysis.hpp"

#include <cmath>

namespace ede {

namespace {

long double mean_of(const std::vector<double>& v) {
  long double s = 0;
  for (const double x : v) s += x;
  return s / (long double)v.size();
}

// Sum of squared deviations from the mean.
long double squared_deviations(const std::vector<double>& v, long double mean) {
  long double s = 0;
  for (const double x : v) s += (x - mean) * (x - mean);
  return s;
}

}  // namespace

BlockStats block_stats(const std::vector<double>& b) {
  BlockStats out;
  out.blocks = b.size();
  if (b.empty()) return out;
  const long double mean = mean_of(b);
  out.mean = double(mean);
  if (b.size() < 2) return out;
  const long double ss = squared_deviations(b, mean);
  const long double n = (long double)b.size();
  out.error = double(std::sqrt(ss / (n - 1) / n));
  long double cross = 0;
  for (std::size_t k = 1; k < b.size(); ++k) cross += (b[k - 1] - mean) * (b[k] - mean);
  out.lag1 = ss > 0 ? double(cross / ss) : 0.0;
  return out;
}

std::vector<double> coarse_grain(const std::vector<double>& fine, std::size_t per_block) {
  std::vector<double> out;
  if (per_block == 0) return out;
  for (std::size_t k = 0; k + per_block <= fine.size(); k += per_block) {
    long double s = 0;
    for (std::size_t m = 0; m < per_block; ++m) s += fine[k + m];
    out.push_back(double(s / (long double)per_block));
  }
  return out;
}

BlockingAnalysis blocking_analysis(const std::vector<double>& series, std::size_t min_blocks) {
  BlockingAnalysis out;
  std::vector<double> x = series;
  while (x.size() >= 2) {
    const long double n = (long double)x.size();
    const long double c0 = squared_deviations(x, mean_of(x)) / n;
    BlockingLevel level;
    level.blocks = x.size();
    level.error = double(std::sqrt(c0 / (n - 1)));
    level.error_of_error = double((long double)level.error / std::sqrt(2 * (n - 1)));
    out.levels.push_back(level);
    x = coarse_grain(x, 2);
  }
  std::size_t eligible = 0;  // levels with at least min_blocks values: 0 .. eligible - 1
  while (eligible < out.levels.size() && out.levels[eligible].blocks >= min_blocks) ++eligible;
  if (eligible == 0) {
    out.plateau = out.levels.empty() ? 0 : out.levels.size() - 1;
    out.error = out.levels.empty() ? 0 : out.levels[out.plateau].error;
    return out;
  }
  const auto confirmed = [&](std::size_t l) {
    for (std::size_t c = l + 1; c < eligible; ++c)
      if (std::fabs(out.levels[c].error - out.levels[l].error) > 2 * out.levels[c].error_of_error) return false;
    return true;
  };
  std::size_t l = 0;
  while (!confirmed(l)) ++l;  // the last eligible level is always confirmed (nothing coarser to check)
  out.plateau = l;
  out.converged = l + 2 < eligible;
  out.error = out.levels[l].error;
  if (out.converged)
    out.trend = BlockingTrend::Plateau;
  else
    out.trend = out.levels[eligible - 1].error >= out.levels[0].error ? BlockingTrend::Rising : BlockingTrend::Falling;
  return out;
}

}  // namespace ede
