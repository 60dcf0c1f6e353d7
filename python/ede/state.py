"""State: every disk at one time, as numpy arrays in the run's own precision."""
import numpy as np

__all__ = ["State"]


class State:
    """Every disk at one time.

    x, y, vx, vy, radius, mass: numpy arrays in the run's scalar type (float32, float64 or longdouble),
    bit-identical to the engine's state (and to ``ede-replay --at``); species: int32 index into
    species_names; id: the disks' ids (0..N-1, the arrays' order). Positions are those at ``time``.
    shear_offset: in a Lees-Edwards (sheared) box, the x-shift of the periodic image above at ``time`` (the one
    below: minus it), as the run had it; 0 otherwise.
    omega, inertia: angular velocity and moment of inertia per disk for rough (rotating) disks, else None.
    The arrays are views of the library's own buffers: read-only unless copied.
    """

    __slots__ = ("time", "time_text", "events", "scalar", "lx", "ly", "boundary", "shear_offset", "x", "y", "vx", "vy",
                 "radius", "mass", "species", "species_names", "omega", "inertia")

    def __init__(self, d):
        for k in self.__slots__:
            setattr(self, k, d.get(k))  # omega and inertia only for rough disks
        for k in ("x", "y", "vx", "vy", "radius", "mass", "species", "omega", "inertia"):
            if getattr(self, k) is not None:
                getattr(self, k).flags.writeable = False

    def __len__(self):
        return len(self.species)

    @property
    def id(self):
        return np.arange(len(self.species), dtype=np.int64)

    @property
    def speed(self):
        return np.hypot(self.vx, self.vy)

    @property
    def kinetic_energy(self):
        return 0.5 * self.mass * (self.vx * self.vx + self.vy * self.vy)

    @property
    def rotational_energy(self):
        """I w^2 / 2 per disk (zeros for smooth disks)."""
        if self.omega is None:
            return np.zeros(len(self))
        return 0.5 * self.inertia * self.omega * self.omega

    def species_mask(self, name):
        """A boolean mask of the disks of species `name`."""
        try:
            k = self.species_names.index(name)
        except ValueError:
            raise KeyError("no species %r (this state has: %s)" % (name, ", ".join(self.species_names))) from None
        return self.species == k

    def to_dict(self):
        """The columns as a dict (for pandas.DataFrame(state.to_dict()))."""
        d = {"id": self.id, "species": np.asarray(self.species_names, dtype=object)[self.species],
             "x": self.x, "y": self.y, "vx": self.vx, "vy": self.vy, "radius": self.radius, "mass": self.mass}
        if self.omega is not None:
            d["omega"], d["inertia"] = self.omega, self.inertia
        return d

    def __repr__(self):
        return "<ede.State %d disks at t=%s (%s, %d events)>" % (len(self), self.time_text, self.scalar, self.events)
