// Structure and transport of a Log (ede/structure.hpp, ede/transport.hpp, ede/viscosity.hpp) for Python:
// the library functions ede-stats gr, sk, psi6, msd, vacf and viscosity (both routes) call, each report converted field
// by field into a dict of numpy arrays; nothing is computed here. Rejected: adding them to
// bind_analysis.cpp, which another part of the module grows too (one file per part of the API).
#include <complex>

#include "bindings.hpp"
#include "shared_log.hpp"

namespace ede::python {

namespace {

template <class T>
py::array_t<T> vec(const std::vector<T>& v) {
  return py::array_t<T>({v.size()}, {sizeof(T)}, v.data());
}

FrameTimes frames_of(const py::object& from, const py::object& to, std::size_t frames) {
  FrameTimes f;
  if (!from.is_none()) f.from = from.cast<double>();
  if (!to.is_none()) f.to = to.cast<double>();
  f.frames = frames;
  return f;
}

py::dict gr_dict(const PairCorrelation& p) {
  py::dict d;
  d["r_lo"] = vec(p.r_lo), d["r_hi"] = vec(p.r_hi), d["g"] = vec(p.g), d["count"] = vec(p.count);
  d["ideal"] = vec(p.ideal), d["frames"] = p.frames, d["n_a"] = p.n_a, d["n_b"] = p.n_b, d["area"] = p.area;
  if (!p.g6.empty()) d["g6"] = vec(p.g6);
  return d;
}

py::dict sheared_dict(const ShearedViscosity& r) {
  py::dict d;
  d["shear_rate"] = r.shear_rate, d["from"] = r.from, d["to"] = r.to, d["area"] = r.area, d["disks"] = r.disks;
  d["blocks"] = r.blocks, d["pair_events"] = r.pair_events, d["thermostat_events"] = r.thermostat_events;
  d["block_time"] = vec(r.block_time), d["block_shear_stress"] = vec(r.block_shear_stress);
  d["block_kT"] = vec(r.block_kT), d["block_viscosity"] = vec(r.block_viscosity);
  d["shear_stress"] = r.shear_stress, d["shear_stress_error"] = r.shear_stress_error;
  d["kinetic_shear_stress"] = r.kinetic_shear_stress, d["collisional_shear_stress"] = r.collisional_shear_stress;
  d["normal_stress_difference"] = r.normal_stress_difference;
  d["normal_stress_difference_error"] = r.normal_stress_difference_error, d["pressure"] = r.pressure;
  d["kT"] = r.kT, d["kT_error"] = r.kT_error, d["viscosity"] = r.viscosity, d["viscosity_error"] = r.viscosity_error;
  d["sigma"] = r.sigma, d["reduced_rate"] = r.reduced_rate, d["reduced_viscosity"] = r.reduced_viscosity;
  d["reduced_viscosity_error"] = r.reduced_viscosity_error, d["packing_fraction"] = r.packing_fraction;
  d["g_contact"] = r.g_contact, d["enskog"] = r.enskog, d["dilute"] = r.dilute, d["enskog_reduced"] = r.enskog_reduced;
  d["enskog_note"] = r.enskog_note;
  return d;
}

TransportOptions transport_of(const py::object& from, const py::object& to, double lag_step, double max_lag,
                              std::size_t origins, std::int32_t species, std::size_t groups) {
  TransportOptions o;
  if (!from.is_none()) o.from = from.cast<double>();
  if (!to.is_none()) o.to = to.cast<double>();
  o.lag_step = lag_step, o.max_lag = max_lag, o.origins = origins, o.species = species, o.groups = groups;
  return o;
}

}  // namespace

void bind_structure(py::module_& m) {
  m.def("pair_correlation", [](SharedLog& log, double r_max, std::size_t bins, double r_min, std::int32_t a,
                               std::int32_t b, py::object from, py::object to, std::size_t frames) {
    PairCorrelationOptions o;
    o.r_max = r_max, o.bins = bins, o.r_min = r_min, o.species_a = a, o.species_b = b;
    const FrameTimes f = frames_of(from, to, frames);
    return gr_dict(log.read("pair_correlation()", [&](const Log& l) { return pair_correlation(l, o, f); }));
  });
  m.def("contact_values", [](SharedLog& log, py::object from, py::object to, std::size_t frames) {
    const FrameTimes f = frames_of(from, to, frames);
    const ContactValues c = log.read("contact_values()", [&](const Log& l) { return contact_values(l, f); });
    py::dict d;
    const auto one = [](const ContactValue& v) {
      py::dict e;
      e["value"] = v.value, e["error"] = v.error, e["method"] = v.method;
      return e;
    };
    d["fit"] = one(c.from_gr), d["collisions"] = one(c.from_collisions), d["pressure"] = one(c.from_pressure);
    d["sigma"] = c.sigma, d["density"] = c.density, d["kT"] = c.kT, d["mass"] = c.mass;
    return d;
  });
  m.def("structure_factor", [](SharedLog& log, double k_max, std::size_t shells, std::int32_t species,
                               py::object from, py::object to, std::size_t frames) {
    StructureFactorOptions o;
    o.k_max = k_max, o.shells = shells, o.species = species;
    const FrameTimes f = frames_of(from, to, frames);
    const StructureFactor s = log.read("structure_factor()", [&](const Log& l) { return structure_factor(l, o, f); });
    py::dict d;
    d["kx"] = vec(s.kx), d["ky"] = vec(s.ky), d["s"] = vec(s.s);
    d["k_lo"] = vec(s.k_lo), d["k_hi"] = vec(s.k_hi), d["s_shell"] = vec(s.s_shell);
    d["frames"] = s.frames, d["n"] = s.n;
    return d;
  });
  m.def("bond_order", [](SharedLog& log, double r_max, std::size_t bins, py::object from, py::object to,
                         std::size_t frames) {
    PairCorrelationOptions o;
    o.r_max = r_max, o.bins = bins;
    const FrameTimes f = frames_of(from, to, frames);
    const BondOrder b = log.read("bond_order()", [&](const Log& l) { return bond_order(l, o, f); });
    py::dict d = gr_dict(b.g6);
    std::vector<std::complex<double>> p(b.psi6);
    d["psi6"] = vec(p), d["global"] = b.global, d["mean_local"] = b.mean_local;
    return d;
  });
  m.def("msd", [](SharedLog& log, py::object from, py::object to, double lag_step, double max_lag,
                  std::size_t origins, std::int32_t species, std::size_t groups) {
    const TransportOptions o = transport_of(from, to, lag_step, max_lag, origins, species, groups);
    const MeanSquareDisplacement r = log.read("msd()", [&](const Log& l) { return mean_square_displacement(l, o); });
    py::dict d;
    d["lag"] = vec(r.lag), d["msd"] = vec(r.msd), d["error"] = vec(r.error);
    d["disks"] = r.disks, d["origins"] = r.origins, d["diffusion"] = r.diffusion, d["diffusion_error"] = r.diffusion_error;
    return d;
  });
  m.def("vacf", [](SharedLog& log, py::object from, py::object to, double lag_step, double max_lag,
                   std::int32_t species, std::size_t groups) {
    const TransportOptions o = transport_of(from, to, lag_step, max_lag, 0, species, groups);
    const VelocityAutocorrelation r = log.read("vacf()", [&](const Log& l) { return velocity_autocorrelation(l, o); });
    py::dict d;
    d["lag"] = vec(r.lag), d["c"] = vec(r.c), d["error"] = vec(r.error), d["green_kubo"] = vec(r.green_kubo);
    d["disks"] = r.disks;
    return d;
  });
  m.def("viscosity", [](SharedLog& log, py::object from, py::object to, double lag_step, double max_lag,
                        std::size_t blocks) {
    ViscosityOptions o;
    if (!from.is_none()) o.from = from.cast<double>();
    if (!to.is_none()) o.to = to.cast<double>();
    o.lag_step = lag_step, o.max_lag = max_lag, o.blocks = blocks;
    const ShearViscosity r = log.read("viscosity()", [&](const Log& l) { return shear_viscosity(l, o); });
    py::dict d;
    d["lag"] = vec(r.lag), d["eta"] = vec(r.eta), d["error"] = vec(r.error), d["eta_xy"] = vec(r.eta_xy);
    d["eta_normal"] = vec(r.eta_normal), d["acf"] = vec(r.acf), d["green_kubo"] = vec(r.green_kubo);
    d["green_kubo_error"] = vec(r.green_kubo_error), d["viscosity"] = r.viscosity;
    d["viscosity_error"] = r.viscosity_error, d["disks"] = r.disks, d["bins"] = r.bins, d["origins"] = r.origins;
    d["blocks"] = r.blocks, d["bin_width"] = r.bin_width, d["area"] = r.area, d["kT"] = r.kT;
    d["pressure"] = r.pressure, d["mean_shear_stress"] = r.mean_shear_stress;
    d["mean_shear_stress_error"] = r.mean_shear_stress_error, d["mean_normal_stress"] = r.mean_normal_stress;
    d["mean_normal_stress_error"] = r.mean_normal_stress_error, d["packing_fraction"] = r.packing_fraction;
    d["g_contact"] = r.g_contact, d["enskog"] = r.enskog, d["dilute"] = r.dilute, d["enskog_note"] = r.enskog_note;
    return d;
  });
  m.def("sheared_viscosity", [](SharedLog& log, py::object from, py::object to, std::size_t blocks) {
    ShearedOptions o;
    if (!from.is_none()) o.from = from.cast<double>();
    if (!to.is_none()) o.to = to.cast<double>();
    o.blocks = blocks;
    const ShearedViscosity r = log.read("sheared_viscosity()", [&](const Log& l) { return sheared_viscosity(l, o); });
    return sheared_dict(r);
  });
  m.def("zero_shear_viscosity", [](const py::list& runs) {
    std::vector<ShearedViscosity> in;
    for (const py::handle& h : runs) {
      const py::dict d = h.cast<py::dict>();
      ShearedViscosity r;
      r.shear_rate = d["shear_rate"].cast<double>(), r.reduced_rate = d["reduced_rate"].cast<double>();
      r.reduced_viscosity = d["reduced_viscosity"].cast<double>();
      r.reduced_viscosity_error = d["reduced_viscosity_error"].cast<double>();
      r.packing_fraction = d["packing_fraction"].cast<double>(), r.enskog_reduced = d["enskog_reduced"].cast<double>();
      in.push_back(r);
    }
    auto fit = zero_shear_viscosity(in);
    if (!fit) throw std::runtime_error(fit.error().message);
    const ZeroShearFit& f = fit.value();
    py::dict d;
    d["points"] = f.points, d["reduced_viscosity"] = f.reduced_viscosity;
    d["reduced_viscosity_error"] = f.reduced_viscosity_error, d["slope"] = f.slope, d["slope_error"] = f.slope_error;
    d["chi2"] = f.chi2, d["packing_fraction"] = f.packing_fraction, d["enskog_reduced"] = f.enskog_reduced;
    return d;
  });
  m.def("enskog_viscosity", [](double phi, double sigma, double g, double kT, double mass) {
    return enskog_viscosity(phi, sigma, g, kT, mass);
  });
  m.def("enskog_diffusion", &enskog_diffusion);
  m.def("henderson_contact", &henderson_contact_value);
  m.def("kolafa_rottner_z", &kolafa_rottner_z);
  m.def("kolafa_rottner_contact", &kolafa_rottner_contact_value);
}

}  // namespace ede::python
