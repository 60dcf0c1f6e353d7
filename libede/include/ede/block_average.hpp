// Block averaging: the mean of a time series and its standard error when successive values are correlated.
//
// A series of equal-length time bins is cut into B blocks; the block means are close to independent when a
// block is much longer than the correlation time, and the standard error of the mean is then the sample
// standard deviation of the block means over sqrt(B). Two checks come with it: the lag-1 autocorrelation
// of the block means (near 0 when blocks are independent; its noise is ~1/sqrt(B)), and the blocking
// analysis of Flyvbjerg and Petersen (J. Chem. Phys. 91, 461 (1989)) on the fine bins: the series is
// halved again and again by averaging neighbours, the naive error estimate grows while blocks are shorter
// than the correlation time and levels off once they are longer; the plateau is the error.
// Rejected: estimating the integrated autocorrelation time from the fine series directly (windowing and
// cut-off choices, and it needs the whole autocorrelation function) for a quantity as short-correlated as
// a hard-disk gas's pressure, where blocking is simpler and says plainly when it has not converged.
// (One part of ede/analysis.hpp, which includes them all.)
#pragma once

#include <cstddef>
#include <vector>

namespace ede {

struct BlockStats {
  std::size_t blocks = 0;
  double mean = 0;
  double error = 0;  // standard error of the mean: sample standard deviation (n - 1) / sqrt(B)
  double lag1 = 0;   // lag-1 autocorrelation of the block means (0 when they are all equal)
};

// Mean, standard error and lag-1 autocorrelation of a series of block means (at least 2).
BlockStats block_stats(const std::vector<double>& block_means);

// The means of consecutive groups of `per_block` values (a shorter last group is dropped).
std::vector<double> coarse_grain(const std::vector<double>& fine, std::size_t per_block);

struct BlockingLevel {
  std::size_t blocks = 0;       // values in the series at this level
  double error = 0;             // sqrt(c0 / (n - 1)): the standard error if the values were independent
  double error_of_error = 0;    // error / sqrt(2 (n - 1))
};

// Without a plateau the estimates either keep rising (correlations longer than the coarsest blocks: the
// error is underestimated) or keep falling (anticorrelated values, e.g. wall hits more regular than a
// Poisson process: the coarsest estimate is an upper bound).
enum class BlockingTrend { Plateau, Rising, Falling };

struct BlockingAnalysis {
  std::vector<BlockingLevel> levels;  // level 0 is the series itself; each next level halves it
  // The plateau: the first level with whose error every coarser level with at least min_blocks values
  // agrees within two of that level's error bars. converged: at least two coarser levels confirm it (one
  // is not enough: with few blocks a change by sqrt(2) per level, the signature of blocks shorter than
  // the correlation time, hides in the noise of the coarsest level).
  std::size_t plateau = 0;
  bool converged = false;
  BlockingTrend trend = BlockingTrend::Rising;  // Plateau when converged
  double error = 0;                             // levels[plateau].error
};

// Flyvbjerg-Petersen blocking of a series of equal-length bins.
BlockingAnalysis blocking_analysis(const std::vector<double>& series, std::size_t min_blocks = 16);

}  // namespace ede
