"""ede: event-driven simulation of two-dimensional hard disks -- from Python.

    import ede
    summary = ede.run("examples/gas.toml", log="gas.ede", set={"physics.restitution": 0.9})
    with ede.open("gas.ede") as log:
        s = log.state(0.5)                   # numpy arrays, bit-identical to ede-replay --at 0.5
        ev = log.events(0.0, 0.1)            # a numpy structured array, one row per event
        h = ede.distribution(log)            # speed histogram, 2D Maxwell-Boltzmann, KS test
        ede.export_xyz(log, "gas.xyz", frames=50)   # for ASE and OVITO
    t = ede.sweep("study.sweep.toml", workers=4)   # ede-sweep's tables as numpy structured arrays

Errors are ede.Error subclasses carrying the library's messages (the same text as the tools print).
ede.__version__ is the project's version (CMakeLists.txt); the import fails with ede.Error if the compiled
part was linked with a library of another version. See docs/python.md.
"""
from ._errors import CorruptLogError, Error, InvalidError, IoError, UnsupportedError
from . import _ede

if _ede.__version__ != _ede.version():
    raise Error("ede's Python module was built for ede %s but is linked with ede's library %s: build both from one "
                "tree (`pip install --no-build-isolation .` from the repository, or rebuild the CMake build; "
                "docs/python.md)" % (_ede.__version__, _ede.version()))
from .analysis import Report, collision_series, crater, distribution, energy_series, impacts, pressure, species_stats
from .export import export_gsd, export_xyz, frame_times
from .log import EVENT_KINDS, Log, open
from .run import Simulation, load_scene, resume, run
from .state import State
from .sweeps import sweep, sweep_program, sweep_tables
from .structure import (bond_order, contact_values, enskog_diffusion, henderson_contact, kolafa_rottner_contact,
                        kolafa_rottner_z, msd, pair_correlation,
                        structure_factor, vacf, viscosity, sheared_viscosity, zero_shear_viscosity,
                        enskog_viscosity)

__version__ = _ede.__version__

__all__ = ["CorruptLogError", "Error", "InvalidError", "IoError", "UnsupportedError", "Report",
           "collision_series", "crater", "distribution", "energy_series", "impacts", "pressure", "species_stats",
           "export_gsd", "export_xyz", "frame_times", "EVENT_KINDS", "Log", "open", "Simulation",
           "load_scene", "resume", "run", "State", "sweep", "sweep_program", "sweep_tables", "bond_order",
           "contact_values", "enskog_diffusion", "henderson_contact", "kolafa_rottner_contact", "kolafa_rottner_z",
           "msd", "pair_correlation", "structure_factor", "vacf", "viscosity", "sheared_viscosity",
           "zero_shear_viscosity", "enskog_viscosity"]
