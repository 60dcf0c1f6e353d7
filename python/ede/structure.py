"""Structure and transport of a log, as ede-stats gr, sk, psi6, msd and vacf compute them (the same
library functions; docs/analysis.md has every formula): g(r) per species pair, g(sigma) three ways, S(k),
psi6 and g6(r), the exactly unwrapped MSD with D, the exact VACF, and the shear viscosity from the exact
stress integral."""
from . import _ede
from .analysis import _log, _report

__all__ = ["pair_correlation", "contact_values", "structure_factor", "bond_order", "msd", "vacf",
           "viscosity", "sheared_viscosity", "zero_shear_viscosity", "enskog_viscosity", "enskog_diffusion", "henderson_contact", "kolafa_rottner_z", "kolafa_rottner_contact"]


def _species(log, name):
    if name is None:
        return -1
    names = [n for n, _ in log.species]
    if name not in names:
        raise ValueError("no species %r (the log has: %s)" % (name, ", ".join(names)))
    return names.index(name)


def pair_correlation(log, r_max, *, bins=200, r_min=0.0, species=None, with_species=None, t0=None, t1=None, frames=1):
    """g(r) at t0 (default: the end), or summed over `frames` times from t0 to t1 (default: the end)."""
    a = _species(log, species)
    b = _species(log, with_species if with_species is not None else species)
    return _report(_ede.pair_correlation(_log(log), float(r_max), int(bins), float(r_min), a, b, t0, t1, int(frames)))


def contact_values(log, t0, t1=None, *, frames=20):
    """g(sigma) from a fit of g(r), from the collision rate (Enskog) and from the virial pressure."""
    return _report(_ede.contact_values(_log(log), t0, t1, int(frames)))


def structure_factor(log, k_max, *, shells=100, species=None, t0=None, t1=None, frames=1):
    """S(k) on the box's wave vectors (kx, ky, s) and averaged over shells of |k| (k_lo, k_hi, s_shell)."""
    return _report(_ede.structure_factor(_log(log), float(k_max), int(shells), _species(log, species), t0, t1,
                                         int(frames)))


def bond_order(log, r_max, *, bins=200, t0=None, t1=None, frames=1):
    """psi6 per disk (complex, nearest six neighbours), global |<psi6>|, mean |psi6|, g(r) and g6(r)."""
    return _report(_ede.bond_order(_log(log), float(r_max), int(bins), t0, t1, int(frames)))


def msd(log, max_lag, *, lag_step=None, t0=None, t1=None, origins=20, species=None, groups=10):
    """Mean-square displacement (exactly unwrapped) and D = slope / 4 with its error."""
    step = float(lag_step) if lag_step is not None else float(max_lag) / 100
    return _report(_ede.msd(_log(log), t0, t1, step, float(max_lag), int(origins), _species(log, species), int(groups)))


def vacf(log, max_lag, *, lag_step=None, t0=None, t1=None, species=None, groups=10):
    """Velocity autocorrelation, exact from the events, and its Green-Kubo integral."""
    step = float(lag_step) if lag_step is not None else float(max_lag) / 100
    return _report(_ede.vacf(_log(log), t0, t1, step, float(max_lag), _species(log, species), int(groups)))


def viscosity(log, max_lag, *, lag_step=None, t0=None, t1=None, blocks=10):
    """Shear viscosity of an equilibrium run (periodic, elastic, no thermostat) from the exact stress
    integral: eta(t) by the Helfand moment with its block error, the estimate `viscosity` (the moment's
    slope over the last half of the lags), the Green-Kubo running integral, and Enskog's eta_E."""
    step = float(lag_step) if lag_step is not None else float(max_lag) / 100
    return _report(_ede.viscosity(_log(log), t0, t1, step, float(max_lag), int(blocks)))


def sheared_viscosity(log, *, t0=None, t1=None, blocks=10):
    """Shear viscosity of a sheared run (Lees-Edwards, in its steady state: start the window after the
    start-up with t0): eta = -<P_xy> / rate from the exact stress integral relative to the flow, with the
    standard error over `blocks` blocks; kT relative to the flow; eta* = eta sigma / sqrt(m kT) at
    rate* = rate sigma sqrt(m / kT) (equal disks); Enskog's eta_E at the run's kT. Per-block values in
    block_time, block_shear_stress, block_kT, block_viscosity (to see the steady state)."""
    return _report(_ede.sheared_viscosity(_log(log), t0, t1, int(blocks)))


def zero_shear_viscosity(runs):
    """The zero-shear limit over sheared runs at several rates (the dicts sheared_viscosity returns): a
    weighted fit eta* = eta0* + b rate*^2, with eta0*'s error, b, chi2 and Enskog's eta_E* at the density."""
    return _report(_ede.zero_shear_viscosity(list(runs)))


def enskog_viscosity(phi, sigma, g_contact, kT, mass):
    """Enskog's 2D viscosity eta_0 [1.022 (1 + phi g)^2 / g + (8 / pi) phi^2 g], eta_0 = sqrt(m kT / pi) / (2 sigma)."""
    return _ede.enskog_viscosity(phi, sigma, g_contact, kT, mass)


def enskog_diffusion(n, sigma, g_contact, kT, mass):
    """D_E = (1 / (2 n sigma g(sigma))) sqrt(kT / (pi m)) (2D, Gass 1971)."""
    return _ede.enskog_diffusion(n, sigma, g_contact, kT, mass)


def henderson_contact(phi):
    """Henderson's g(sigma) = (1 - 7 phi / 16) / (1 - phi)^2."""
    return _ede.henderson_contact(phi)


def kolafa_rottner_z(phi):
    """Kolafa and Rottner's Z(phi) of the hard-disk fluid (Mol. Phys. 104, 3435 (2006)); NaN above 0.7069."""
    return _ede.kolafa_rottner_z(phi)


def kolafa_rottner_contact(phi):
    """g(sigma) = (Z - 1) / (2 phi) from Kolafa and Rottner's Z; NaN above phi = 0.7069."""
    return _ede.kolafa_rottner_contact(phi)
