// shear_viscosity (ede/viscosity.hpp): the Helfand moment and the Green-Kubo integral of the exact stress
// integral per bin (stress_walk.cpp). With W_k the integral of V P over bin k (width dt) and
// G_k = W_0 + ... + W_(k-1), the moment's increment over lag l dt from origin s is G_(s+l) - G_s, exact;
//   eta(l dt) = < (G_(s+l) - G_s)^2 >_s / (2 V kT l dt)
// over the origins s = 0 .. S - L - 1 (S bins, L the largest lag in bins; the same origins at every lag).
// eta(t) tends to eta only as 1/t (the moment is 2 V kT (eta t - integral of t C)), so the estimate is the
// moment's least-squares slope over the last half of the lags, / (2 V kT), like D from the MSD's slope.
// The Green-Kubo integral of the bin-averaged stress, C_m = <W_s W_(s+m)>_s:
//   eta_GK(l dt) = (C_0 / 2 + C_1 + ... + C_(l-1) + C_l / 2) / (V kT dt),
// which is the Helfand moment's slope ((H_(l+1) - H_(l-1)) / 2 = C_0 + 2 (C_1 + ... + C_(l-1)) + C_l for a
// stationary W), so the two agree where the moment grows linearly. The collisional stress has a delta at
// t = 0 (every impulse correlates with itself); here it sits in C_0, half of it in every eta_GK, as the
// integral from 0 of a delta at 0 takes. Errors: the origins are split into contiguous blocks, each
// block's eta (both components averaged) is an estimate, and the error is their standard error (blocks
// much longer than the lags and the stress's correlation time are nearly independent; the tool warns when
// a block is shorter than twice the largest lag).
// Cost: O(S L) for both; S = window / dt bins. Rejected: an FFT for the correlations (O(S log S), but
// S L stays below a few 10^8 for the grids the tool allows, and the sums need no library).
#include <algorithm>
#include <cmath>

#include "analysis/enskog_reference.hpp"
#include "analysis/stress_walk.hpp"
#include "analysis/transport_stream.hpp"
#include "ede/viscosity.hpp"

namespace ede {

namespace {

// Per block of origins and per lag 1..L: sum over the block's origins of (G_(s+l) - G_s)^2 and of
// W_s W_(s+l) (lag 0 as well), for one stress component w.
struct ComponentSums {
  std::vector<std::vector<long double>> helfand, correlation;  // [block][lag]
};

ComponentSums component_sums(const std::vector<double>& w, std::size_t lags, std::size_t origins,
                             std::size_t blocks) {
  std::vector<long double> g(w.size() + 1, 0);
  for (std::size_t k = 0; k < w.size(); ++k) g[k + 1] = g[k] + w[k];
  ComponentSums c;
  c.helfand.assign(blocks, std::vector<long double>(lags + 1, 0));
  c.correlation.assign(blocks, std::vector<long double>(lags + 1, 0));
  for (std::size_t s = 0; s < origins; ++s) {
    const std::size_t b = s * blocks / origins;
    std::vector<long double>& h = c.helfand[b];
    std::vector<long double>& r = c.correlation[b];
    const long double ws = w[s];
    for (std::size_t l = 0; l <= lags; ++l) {
      const long double d = g[s + l] - g[s];
      h[l] += d * d;
      r[l] += ws * w[s + l];
    }
  }
  return c;
}

struct BlockStatistic {
  double mean = 0, error = 0;
};
// The pooled mean of per-block sums (each over `count[b]` origins) and the standard error of the block means.
BlockStatistic pooled(const std::vector<long double>& sums, const std::vector<std::size_t>& count) {
  long double total = 0;
  std::size_t n = 0;
  std::vector<double> means(sums.size());
  for (std::size_t b = 0; b < sums.size(); ++b) {
    total += sums[b], n += count[b];
    means[b] = double(sums[b] / (long double)count[b]);
  }
  return {double(total / (long double)n), transport::standard_error(means)};
}

// The least-squares slope of y against x over the points k0 .. end (through the origin when one point).
double slope(const std::vector<double>& x, const std::vector<double>& y, std::size_t k0) {
  const std::size_t n = x.size() - k0;
  if (n == 1) return y[k0] / x[k0];
  double mx = 0, my = 0;
  for (std::size_t k = k0; k < x.size(); ++k) mx += x[k], my += y[k];
  mx /= double(n), my /= double(n);
  double sxy = 0, sxx = 0;
  for (std::size_t k = k0; k < x.size(); ++k) sxy += (x[k] - mx) * (y[k] - my), sxx += (x[k] - mx) * (x[k] - mx);
  return sxy / sxx;
}

}  // namespace

Result<StressIntegral> stress_integral(const Log& log, double from, double bin_width, std::size_t bins) {
  const std::string where = log.info().path + ": stress integral: ";
  // A sheared log's integral is taken relative to the flow (its thermostat, if any, drawing about it); any
  // other log must be one the equilibrium analysis takes.
  const std::string why = log.info().lees_edwards ? stress::sheared_stress_refusal(log) : stress::refusal(log);
  if (!why.empty()) return Error{where + why};
  const double end = double(log.info().end_time);
  // The last edge may pass the log's end by the rounding of bins * bin_width; the walk stops at the end.
  if (!(bin_width > 0) || bins == 0 || !(from >= log.info().start_time) ||
      !(from + bin_width * double(bins) <= end + 1e-9 * bin_width))
    return Error{where + "the bins must lie within the log's " + std::to_string(log.info().start_time) + " to " +
                 std::to_string(end) + "; got " + std::to_string(bins) + " bins of " + std::to_string(bin_width) +
                 " from " + std::to_string(from)};
  return stress::integrate(log, from, bin_width, bins);
}

Result<ShearViscosity> shear_viscosity(const Log& log, const ViscosityOptions& o) {
  const LogInfo& info = log.info();
  const std::string where = info.path + ": viscosity: ";
  if (const std::string why = stress::refusal(log); !why.empty()) return Error{where + why};
  const double from = o.from.value_or(info.start_time), to = o.to.value_or(double(info.end_time));
  if (!(from >= info.start_time && to <= double(info.end_time) && from < to))
    return Error{where + "the window " + std::to_string(from) + " to " + std::to_string(to) +
                 " is not a non-empty part of the log's " + std::to_string(info.start_time) + " to " +
                 std::to_string(double(info.end_time))};
  if (!(o.lag_step > 0) || !(o.max_lag >= o.lag_step) || !(o.max_lag < to - from))
    return Error{where + "need 0 < lag step <= max lag < window length (" + std::to_string(to - from) +
                 "); got lag step " + std::to_string(o.lag_step) + ", max lag " + std::to_string(o.max_lag)};
  if (o.blocks < 2) return Error{where + "at least 2 blocks are needed for an error"};
  const double bins_real = std::floor((to - from) / o.lag_step + 1e-9);
  if (bins_real > 1e7) return Error{where + "more than 10^7 bins of the lag step in the window: raise the lag step"};
  const auto bins = std::size_t(bins_real);
  const auto lags = std::size_t(std::floor(o.max_lag / o.lag_step + 1e-9));
  if (bins <= lags || bins - lags < o.blocks)
    return Error{where + "the window holds " + std::to_string(bins) + " lag steps: too few for the largest lag (" +
                 std::to_string(lags) + " steps) and " + std::to_string(o.blocks) + " blocks of origins"};
  auto integral = stress::integrate(log, from, o.lag_step, bins);
  if (!integral) return integral.error();
  const StressIntegral& w = integral.value();
  if (w.disks < 2) return Error{where + "needs at least 2 disks"};

  ShearViscosity out;
  out.disks = w.disks, out.bins = bins, out.bin_width = o.lag_step, out.area = w.area;
  const double span = o.lag_step * double(bins);
  out.kT = double((w.kinetic_xx + w.kinetic_yy) / 2 / (long double)(double(w.disks - 1) * span));
  if (!(out.kT > 0)) return Error{where + "the disks do not move relative to their centre of mass (kT = 0)"};

  std::vector<double> shear(bins), normal(bins);
  long double trace = 0;
  for (std::size_t k = 0; k < bins; ++k) {
    shear[k] = 0.5 * (w.xy[k] + w.yx[k]), normal[k] = 0.5 * (w.xx[k] - w.yy[k]);
    trace += 0.5L * ((long double)w.xx[k] + w.yy[k]);
  }
  out.pressure = double(trace / (long double)(w.area * span));
  {  // the mean stresses, with errors from contiguous blocks of bins
    std::vector<long double> s_sum(o.blocks, 0), n_sum(o.blocks, 0);
    std::vector<std::size_t> count(o.blocks, 0);
    for (std::size_t k = 0; k < bins; ++k) {
      const std::size_t b = k * o.blocks / bins;
      s_sum[b] += shear[k], n_sum[b] += normal[k], ++count[b];
    }
    const double to_stress = 1 / (w.area * o.lag_step);
    const BlockStatistic s = pooled(s_sum, count), n = pooled(n_sum, count);
    out.mean_shear_stress = s.mean * to_stress, out.mean_shear_stress_error = s.error * to_stress;
    out.mean_normal_stress = n.mean * to_stress, out.mean_normal_stress_error = n.error * to_stress;
  }

  const std::size_t origins = bins - lags, blocks = o.blocks;
  out.origins = origins, out.blocks = blocks;
  std::vector<std::size_t> count(blocks, 0);
  for (std::size_t s = 0; s < origins; ++s) ++count[s * blocks / origins];
  const ComponentSums a = component_sums(shear, lags, origins, blocks);
  const ComponentSums b = component_sums(normal, lags, origins, blocks);
  const double scale = 1 / (w.area * out.kT);  // eta = scale * H / (2 l dt), eta_GK = scale * sum C / dt
  out.lag.resize(lags), out.eta.resize(lags), out.error.resize(lags), out.eta_xy.resize(lags);
  out.eta_normal.resize(lags), out.acf.resize(lags), out.green_kubo.resize(lags), out.green_kubo_error.resize(lags);
  std::vector<long double> both(blocks), gk_block(blocks, 0);
  // <dG^2> (both components averaged) per block and pooled, for the slope.
  std::vector<std::vector<double>> moment_block(blocks, std::vector<double>(lags));
  std::vector<double> moment(lags);
  // Block b's running Green-Kubo sum; its C_0 / 2 first.
  const auto correlation = [&](std::size_t q, std::size_t l) {
    return (a.correlation[q][l] + b.correlation[q][l]) / 2 / (long double)count[q];
  };
  for (std::size_t q = 0; q < blocks; ++q) gk_block[q] = correlation(q, 0) / 2;
  for (std::size_t l = 1; l <= lags; ++l) {
    const std::size_t k = l - 1;
    const double lag = o.lag_step * double(l), helfand_scale = scale / (2 * lag);
    out.lag[k] = lag;
    std::vector<long double> ha(blocks), hb(blocks);
    for (std::size_t q = 0; q < blocks; ++q) {
      ha[q] = a.helfand[q][l], hb[q] = b.helfand[q][l];
      both[q] = (ha[q] + hb[q]) / 2;
    }
    out.eta_xy[k] = pooled(ha, count).mean * helfand_scale;
    out.eta_normal[k] = pooled(hb, count).mean * helfand_scale;
    const BlockStatistic e = pooled(both, count);
    out.eta[k] = e.mean * helfand_scale, out.error[k] = e.error * helfand_scale;
    moment[k] = e.mean;
    for (std::size_t q = 0; q < blocks; ++q) moment_block[q][k] = double(both[q] / (long double)count[q]);

    std::vector<double> gk(blocks);
    long double acf = 0;
    for (std::size_t q = 0; q < blocks; ++q) {
      const long double c = correlation(q, l);
      acf += c * (long double)count[q];
      gk[q] = double((gk_block[q] + c / 2) * scale / o.lag_step);
      gk_block[q] += c;
    }
    out.acf[k] = double(acf / (long double)origins) * scale / (o.lag_step * o.lag_step);
    double mean = 0;
    for (std::size_t q = 0; q < blocks; ++q) mean += gk[q] * double(count[q]);
    out.green_kubo[k] = mean / double(origins);
    out.green_kubo_error[k] = transport::standard_error(gk);
  }
  const std::size_t half = (lags - 1) / 2;
  out.viscosity = slope(out.lag, moment, half) * scale / 2;
  std::vector<double> slopes(blocks);
  for (std::size_t q = 0; q < blocks; ++q) slopes[q] = slope(out.lag, moment_block[q], half) * scale / 2;
  out.viscosity_error = transport::standard_error(slopes);
  auto start = log.state_at(from);
  if (!start) return start.error();
  const stress::EnskogReference e = stress::enskog_reference(log, start.value(), out.area, out.kT);
  out.packing_fraction = e.packing_fraction, out.g_contact = e.g_contact;
  out.enskog = e.enskog, out.dilute = e.dilute, out.enskog_note = e.note;
  return out;
}

}  // namespace ede
