"""Exports of a log's states to the formats other programs read: extended XYZ (ASE, OVITO) and GSD
(HOOMD-blue's format; OVITO, python3-gsd).

Extended XYZ: one frame per time; z = 0; the comment line carries Lattice (the box, a 1.0-long third
axis), pbc, Time, and the properties species (a chemical symbol per ede species, H, He, Li, ..., because
ASE accepts only element names there), pos, vel, radius, masses and ede_species (the species' own name).
Numbers have the digits that read back to the identical value (float32 9, float64 17; long double logs
are written at 17 digits).
GSD (HOOMD schema): box [Lx, Ly, 0], dimensions 2, positions centred on the box (x - Lx/2), velocities,
masses, diameters (2 r), typeid and types (the species names) in float32 as the schema has them; the
exact float64 values are kept in the frame's log as ede/x, ede/y, ede/vx, ede/vy, ede/time.
Rejected: writing GSD's binary layout ourselves (python3-gsd is its reference implementation).
"""
import numpy as np

__all__ = ["export_xyz", "export_gsd", "frame_times"]

_ELEMENTS = ("H He Li Be B C N O F Ne Na Mg Al Si P S Cl Ar K Ca Sc Ti V Cr Mn Fe Co Ni Cu Zn Ga Ge As Se Br "
             "Kr Rb Sr Y Zr Nb Mo Tc Ru Rh Pd Ag Cd In Sn Sb Te I Xe").split()


def frame_times(log, times=None, *, t0=None, t1=None, frames=None, every=None):
    """The times to export: `times` as given; else from t0 (default the start) to t1 (default the end),
    `frames` evenly spaced (both ends included) or every `every`; default: the end alone."""
    if times is not None:
        return list(np.atleast_1d(times))
    a = log.info["start_time"] if t0 is None else t0
    b = log.info["end_time"] if t1 is None else t1
    if frames is not None:
        return list(np.linspace(a, b, int(frames))) if frames > 1 else [a]
    if every is not None:
        n = int(np.floor((b - a) / every + 1e-12))
        return [a + k * every for k in range(n + 1)]
    return [b]


def _digits(dtype):
    return 9 if dtype == np.float32 else 17


def _xyz_frame(state, out):
    n = len(state)
    if len(state.species_names) > len(_ELEMENTS):
        raise ValueError("export_xyz: more than %d species" % len(_ELEMENTS))
    symbols = np.asarray(_ELEMENTS[:len(state.species_names)], dtype=object)[state.species]
    names = np.asarray(state.species_names, dtype=object)[state.species]
    pbc = "T T F" if state.boundary == "periodic" else "F F F"
    d = _digits(state.x.dtype)
    r = "%%.%dg" % d
    out.write("%d\n" % n)
    out.write('Lattice="%s 0.0 0.0 0.0 %s 0.0 0.0 0.0 1.0" Properties=species:S:1:pos:R:3:vel:R:3:radius:R:1:'
              'masses:R:1:ede_species:S:1 Time=%s pbc="%s"\n' % (r % state.lx, r % state.ly, state.time_text, pbc))
    columns = [symbols, state.x.astype(np.float64), state.y.astype(np.float64), np.zeros(n),
               state.vx.astype(np.float64), state.vy.astype(np.float64), np.zeros(n),
               state.radius.astype(np.float64), state.mass.astype(np.float64), names]
    fmt = "%s " + " ".join([r] * 8) + " %s\n"
    rows = np.empty((n, 10), dtype=object)
    for k, c in enumerate(columns):
        rows[:, k] = c
    out.write("".join(fmt % tuple(row) for row in rows))


def export_xyz(log, path, times=None, **kw):
    """Writes the states at `times` (see frame_times for t0, t1, frames, every) as extended XYZ."""
    with open(path, "w") as out:
        for state in log.states(frame_times(log, times, **kw)):
            _xyz_frame(state, out)
    return path


def export_gsd(log, path, times=None, **kw):
    """Writes the states at `times` (see frame_times) as a GSD trajectory (HOOMD schema)."""
    try:
        import gsd.hoomd
    except ImportError:
        raise ImportError("export_gsd needs python3-gsd (apt-get install python3-gsd)") from None
    make = getattr(gsd.hoomd, "Frame", None) or gsd.hoomd.Snapshot
    f = gsd.hoomd.open(path, mode="wb" if gsd.__version__.startswith("2.") else "w")
    try:
        for step, state in enumerate(log.states(frame_times(log, times, **kw))):
            s = make()
            n = len(state)
            s.configuration.step = step
            s.configuration.dimensions = 2
            s.configuration.box = [float(state.lx), float(state.ly), 0.0, 0.0, 0.0, 0.0]
            s.particles.N = n
            s.particles.types = list(state.species_names)
            s.particles.typeid = state.species.astype(np.uint32)
            pos = np.zeros((n, 3), dtype=np.float32)
            pos[:, 0] = state.x - state.lx / 2
            pos[:, 1] = state.y - state.ly / 2
            vel = np.zeros((n, 3), dtype=np.float32)
            vel[:, 0], vel[:, 1] = state.vx, state.vy
            s.particles.position, s.particles.velocity = pos, vel
            s.particles.mass = state.mass.astype(np.float32)
            s.particles.diameter = (2 * state.radius).astype(np.float32)
            s.log["ede/time"] = np.array([float(state.time)], dtype=np.float64)
            for k in ("x", "y", "vx", "vy"):
                s.log["ede/" + k] = np.asarray(getattr(state, k), dtype=np.float64)
            f.append(s)
    finally:
        f.close()
    return path
