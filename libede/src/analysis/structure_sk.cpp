// S(k) on the box's wave vectors (structure.hpp). Per disk, the phase factors exp(-i 2 pi p x / Lx) for
// every p needed and exp(-i 2 pi q y / Ly) for every q are made once (one std::polar each, so no error
// accumulates along a recurrence), then every wave vector's density mode takes one complex product per disk:
// O(N K) for K vectors, with K ~ k_max^2 Lx Ly / (4 pi). With walls the same vectors are used (they are not
// the box's eigenmodes there: the docs say so). Rejected: an FFT of the density on a grid, whose binning
// (the disks' positions rounded to cells) changes S(k) at the k that matter.
#include <cmath>
#include <complex>
#include <string>

#include "ede/structure.hpp"
#include "analysis/sheared_guard.hpp"

namespace ede {

Status add_structure_factor(const State& s, const StructureFactorOptions& o, StructureFactor& acc) {
  if (!(o.k_max > 0) || o.shells == 0) return Error{"S(k): need k_max > 0 and shells >= 1"};
  const int pmax = int(std::floor(o.k_max * s.lx / (2 * M_PI))), qmax = int(std::floor(o.k_max * s.ly / (2 * M_PI)));
  if (pmax < 1 && qmax < 1)
    return Error{"S(k): k_max " + std::to_string(o.k_max) + " is below the smallest wave vector of the box, 2 pi / " +
                 std::to_string(std::max(s.lx, s.ly)) + "; raise k_max"};
  if (double(2 * pmax + 1) * double(qmax + 1) > 2e7)
    return Error{"S(k): k_max " + std::to_string(o.k_max) + " gives more than 10^7 wave vectors; lower it"};
  std::vector<int> vp, vq;  // one of each +-k pair: q > 0, or q == 0 and p > 0
  for (int q = 0; q <= qmax; ++q)
    for (int p = -pmax; p <= pmax; ++p) {
      if (q == 0 && p <= 0) continue;
      const double kx = 2 * M_PI * p / s.lx, ky = 2 * M_PI * q / s.ly;
      if (kx * kx + ky * ky <= o.k_max * o.k_max) vp.push_back(p), vq.push_back(q);
    }
  if (acc.frames == 0) {
    acc.kx.resize(vp.size());
    acc.ky.resize(vp.size());
    for (std::size_t k = 0; k < vp.size(); ++k) acc.kx[k] = 2 * M_PI * vp[k] / s.lx, acc.ky[k] = 2 * M_PI * vq[k] / s.ly;
    acc.s.assign(vp.size(), 0);
    acc.k_lo.resize(o.shells);
    acc.k_hi.resize(o.shells);
    for (std::size_t b = 0; b < o.shells; ++b)
      acc.k_lo[b] = o.k_max * double(b) / double(o.shells), acc.k_hi[b] = o.k_max * double(b + 1) / double(o.shells);
  } else if (acc.s.size() != vp.size()) {
    return Error{"S(k): a frame's box differs from the first frame's"};
  }
  std::vector<std::complex<double>> rho(vp.size());
  std::vector<std::complex<double>> ex(2 * std::size_t(pmax) + 1), ey(std::size_t(qmax) + 1);
  std::size_t n = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (o.species >= 0 && s.species[i] != o.species) continue;
    ++n;
    const double x = s.x[i], y = s.y[i];
    for (int p = -pmax; p <= pmax; ++p) ex[std::size_t(p + pmax)] = std::polar(1.0, -2 * M_PI * p * x / s.lx);
    for (int q = 0; q <= qmax; ++q) ey[std::size_t(q)] = std::polar(1.0, -2 * M_PI * q * y / s.ly);
    for (std::size_t k = 0; k < vp.size(); ++k) rho[k] += ex[std::size_t(vp[k] + pmax)] * ey[std::size_t(vq[k])];
  }
  if (n == 0) return Error{"S(k): no disk of the species asked for"};
  for (std::size_t k = 0; k < vp.size(); ++k) acc.s[k] += std::norm(rho[k]) / double(n);
  acc.n = n;
  ++acc.frames;
  return Ok{};
}

void finish_structure_factor(StructureFactor& acc) {
  for (double& v : acc.s) v /= double(acc.frames ? acc.frames : 1);
  const std::size_t shells = acc.k_lo.size();
  acc.s_shell.assign(shells, 0);
  acc.shell_vectors.assign(shells, 0);
  const double k_max = shells ? acc.k_hi.back() : 0;
  for (std::size_t k = 0; k < acc.s.size(); ++k) {
    const double kk = std::hypot(acc.kx[k], acc.ky[k]);
    const auto b = std::min(shells - 1, std::size_t(kk / k_max * double(shells)));
    acc.s_shell[b] += acc.s[k];
    ++acc.shell_vectors[b];
  }
  for (std::size_t b = 0; b < shells; ++b)
    acc.s_shell[b] = acc.shell_vectors[b] ? acc.s_shell[b] / double(acc.shell_vectors[b]) : NAN;
}

Result<StructureFactor> structure_factor(const State& s, const StructureFactorOptions& o) {
  StructureFactor acc;
  if (Status a = add_structure_factor(s, o, acc); !a) return a.error();
  finish_structure_factor(acc);
  return acc;
}

Result<StructureFactor> structure_factor(const Log& log, const StructureFactorOptions& o, const FrameTimes& f) {
  if (std::string why = sheared_refusal(log, "S(k)"); !why.empty()) return Error{why};
  auto times = frame_times(log, f);
  if (!times) return times.error();
  StructureFactor acc;
  for (const double t : times.value()) {
    auto s = log.state_at(t);
    if (!s) return s.error();
    if (Status a = add_structure_factor(s.value(), o, acc); !a) return Error{log.info().path + ": " + a.error().message};
  }
  finish_structure_factor(acc);
  return acc;
}

}  // namespace ede
