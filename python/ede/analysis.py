"""The analyses of a log, as the command-line tools compute them (the same library functions), returning
numpy arrays: speed/energy distributions with the 2D Maxwell-Boltzmann law and the KS test, energy
series per species with Haff's law, collision statistics, species tables, pressure, crater metrics."""
from . import _ede

__all__ = ["Report", "distribution", "energy_series", "collision_series", "impacts", "species_stats", "pressure", "crater"]


class Report(dict):
    """A dict whose keys are also attributes (report.kT == report["kT"])."""

    def __getattr__(self, name):
        try:
            return self[name]
        except KeyError:
            raise AttributeError(name) from None

    def __dir__(self):
        return list(self.keys())


def _log(log):
    from .log import Log
    if isinstance(log, Log):
        return log._log
    raise TypeError("expected an ede.Log (ede.open(path)), got %s" % type(log).__name__)


def _report(d):
    return Report({k: (_report(v) if isinstance(v, dict) and k != "species_energy" else v) for k, v in d.items()})


def distribution(log, t=None, *, times=None, species=None, quantity="speed", bins=40):
    """The histogram of speeds (or kinetic energies) at time t (default: the end of the log), or pooled
    over `times`, with the 2D Maxwell-Boltzmann law at the sample's kT and the KS test of the energies
    (as ede-stats hist): edges, count, density, law_density, curve_x, curve_density, kT, ks, initial_*."""
    if t is not None and times is not None:
        raise TypeError("distribution: give t or times, not both")
    if times is None:
        times = [log.info["end_time"] if t is None else t]
    return _report(_ede.distribution(_log(log), times, species, quantity, int(bins)))


def energy_series(log, *, t0=None, t1=None, every=None, points=None):
    """Kinetic energy, total and per species, on a time grid (as ede-stats energy): time, kinetic_energy,
    species_energy[name], pair/wall collisions, with Haff's law for inelastic runs: haff_ratio uses
    enskog_tau (Enskog's rate at t = 0, +- enskog_tau_error), or haff_tau (calibrated on the collision count)
    where Enskog does not apply."""
    return _report(_ede.energy_curve(_log(log), t0, t1, every, points))


def collision_series(log, times):
    """Collision counts, the pair collision rate per disk, the mean free time and the GasLab speed classes
    at the given times (as ede-stats collisions)."""
    return _report(_ede.collision_series(_log(log), times))


def impacts(log, *, t0=None, t1=None, bins=20):
    """Pair collisions in [t0, t1] (as ede-stats impacts): histograms of |b|/(r_i + r_j) (impact_edges,
    impact_count, impact_density; the law is 1) and of the relative speed g (speed_edges, speed_count,
    speed_density, speed_law: the flux-weighted Maxwellian), KS tests (impact_ks against U(0, 1), speed_ks of
    mu g^2/2kT against Gamma(3/2)), kT at t0, mean |b|/sigma, g and impulses (docs/analysis.md)."""
    return _report(_ede.impacts(_log(log), t0, t1, int(bins)))


def species_stats(log, times):
    """Per-species mean speed, mean kinetic energy and kT (with standard errors) at each time (as
    ede-stats species): a list of dicts, each species then "all" at each time."""
    return [Report(d) for d in _ede.species_stats(_log(log), times)]


def pressure(log, *, t0=None, t1=None, blocks=20):
    """Pressure from wall impulses and the virial, with block errors and the ideal-gas and Henderson
    references (as ede-stats pressure)."""
    return _report(_ede.pressure(_log(log), t0, t1, int(blocks)))


def crater(log, *, at=None, energy_fraction=0.1, bed=""):
    """Crater metrics (count, depth, width, area, ...) when `energy_fraction` of the energy is left, or at
    time `at` (as ede-crater measure), with the surface profiles before and after."""
    return _report(_ede.crater(_log(log), at, float(energy_fraction), bed))
