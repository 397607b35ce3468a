"""hcbd from Python: the same kernel as the C library, the same bits.

Two worlds, named as in the C API (thing, then verb):

    World     GI-BD, classical BD and walls (Padding & Briels 2014, Ahuja et
              al. 2016): the walled build of the library
    HCWorld   the 2018 model: SPH fluid blobs coupled to RaPiD polymer blobs

A world takes the C parameters as keywords, with the C defaults (the 2014
star scene; Table I of 2018 in units of sigma, kT and 1 us).  A bad value
raises ValueError with the library's message, which names the parameter;
a failed step raises RuntimeError with the step, the particle and the
limit crossed, and leaves the world as the C API documents (the state of
the failed step).

    >>> import hcbd
    >>> w = hcbd.World(N=512, density=0.24, seed=1)
    >>> w.step(100)
    >>> w.temperature()        # about kT = 1
    >>> xyz = w.positions()    # a copy, (N, 3), in id order

The arrays of the world's own storage are read-only numpy views (no copy):
World.x, .y, .z, .vx, .vy, .vz and .id are in storage order, which the
GI-BD world re-sorts by cell at neighbour-list rebuilds (.id[s] is the id
at slot s); HCWorld's fluid (.fx ...) and polymer (.px ...) arrays are in
id order.  A view keeps its world alive; it shows the world as it is now.
Write through set_positions / set_velocities.

Requires numpy; matplotlib only for the notebooks' plots.  Build the
libraries with `make python` (docs/PYTHON.md).
"""
import ctypes
import math
import os

import numpy as np

__all__ = ["World", "HCWorld", "RDF", "MSD", "Profile", "carreau_fit", "blocking_error", "HcbdError",
           "library_path"]

_here = os.path.dirname(os.path.abspath(__file__))
_dbl_p = ctypes.POINTER(ctypes.c_double)
_MSG = 512


class HcbdError(RuntimeError):
    """A run-time error of the library (a step that crossed a limit, a file that could not be read)."""

    def __init__(self, code, message):
        super().__init__(message)
        self.code = code


def library_path(kind):
    """The shared library of a build: kind 'walled' (World) or 'hc' (HCWorld)."""
    return os.path.join(_here, "_hcbd_%s.so" % kind)


def _load(kind):
    path = library_path(kind)
    if not os.path.exists(path):
        raise ImportError("hcbd: %s is missing; run `make python` in the hcbd tree" % path)
    lib = ctypes.CDLL(path)
    vp, cp, i, d = ctypes.c_void_p, ctypes.c_char_p, ctypes.c_int, ctypes.c_double
    sig = {
        "hpy_def_new": (vp, []), "hpy_def_free": (None, [vp]),
        "hpy_def_set": (i, [vp, cp, _dbl_p, i, cp, cp, i]), "hpy_def_set_seed": (i, [vp, ctypes.c_uint64]),
        "hpy_key_name": (cp, [i]), "hpy_seed": (ctypes.c_uint64, [vp]), "hpy_param_get": (i, [vp, cp, _dbl_p, ctypes.POINTER(cp), ctypes.POINTER(i)]),
        "hpy_world_new": (vp, [vp, cp, i]), "hpy_world_load": (vp, [cp, cp, i]), "hpy_world_free": (None, [vp]),
        "hpy_error": (cp, [vp]), "hpy_array": (vp, [vp, cp, ctypes.POINTER(i)]),
        "hpy_step_count": (ctypes.c_longlong, [vp]), "hpy_le_offset": (d, [vp]), "hpy_box": (None, [vp, _dbl_p]),
        "hpy_write_xyz": (i, [vp, cp, i, cp, i]), "hpy_real_size": (i, []), "hpy_free": (None, [vp]),
        "hpy_rdf_new": (vp, [d, i, i, cp, i]), "hpy_msd_new": (vp, [i, i, i, i, ctypes.c_longlong, cp, i]),
        "hcbd_result_name": (cp, [i]),
        "hcbd_msd_add": (None, [vp, _dbl_p]),
        "hcbd_msd_stats": (i, [vp, _dbl_p, _dbl_p, _dbl_p, i]),
        "hcbd_msd_diffusion": (i, [vp, d, d, _dbl_p, _dbl_p]),
        "hcbd_carreau_fit": (i, [_dbl_p, _dbl_p, _dbl_p, i, d, i, _dbl_p, _dbl_p, _dbl_p]),
        "hcbd_carreau_err_scale": (d, [d, i]),
        "hcbd_blocking_error": (i, [_dbl_p, i, _dbl_p, _dbl_p, _dbl_p, ctypes.POINTER(i)]),
    }
    if kind == "hc":
        sig.update({
            "hcbd_hc_world_step": (i, [vp, i]), "hcbd_hc_world_checksum": (ctypes.c_uint64, [vp]),
            "hcbd_hc_world_temperature": (d, [vp]), "hcbd_hc_world_momentum": (None, [vp, _dbl_p]),
            "hcbd_hc_world_place_fluid_lattice": (i, [vp, i]), "hcbd_hc_world_place_polymers_random": (i, [vp, i]),
            "hcbd_hc_world_set_fluid": (i, [vp, i, _dbl_p, _dbl_p]), "hcbd_hc_world_set_polymers": (i, [vp, i, _dbl_p]),
            "hcbd_hc_world_get_fluid": (i, [vp, _dbl_p, _dbl_p]), "hcbd_hc_world_get_polymers": (i, [vp, _dbl_p]),
            "hcbd_hc_world_stress_enable": (i, [vp, i]),
            "hcbd_hc_world_stress_read": (i, [vp, _dbl_p, ctypes.POINTER(ctypes.c_int64)]),
            "hcbd_hc_world_save": (i, [vp, cp]), "hcbd_hc_world_set_threads": (i, [vp, i]),
            "hcbd_hc_world_refresh": (i, [vp]), "hcbd_hc_world_density_range": (i, [vp, _dbl_p]),
            "hcbd_hc_world_polymer_energy": (d, [vp]),
            "hcbd_hc_world_transverse_current": (i, [vp, i, _dbl_p]),
        })
    else:
        sig.update({
            "hcbd_world_step": (i, [vp, i]), "hcbd_world_checksum": (ctypes.c_uint64, [vp]),
            "hcbd_world_temperature": (d, [vp]), "hcbd_world_momentum": (None, [vp, _dbl_p]),
            "hcbd_world_place_lattice": (i, [vp, i]), "hcbd_world_place_random": (i, [vp, i]),
            "hcbd_world_set_positions": (i, [vp, i, _dbl_p]), "hcbd_world_set_velocities": (i, [vp, _dbl_p]),
            "hcbd_world_get_positions": (i, [vp, _dbl_p, i]), "hcbd_world_get_velocities": (i, [vp, _dbl_p]),
            "hcbd_world_stress_enable": (i, [vp, i]),
            "hcbd_world_stress_read": (i, [vp, _dbl_p, ctypes.POINTER(ctypes.c_int64)]),
            "hcbd_world_save": (i, [vp, cp]), "hcbd_world_set_threads": (i, [vp, i]),
            "hcbd_world_config_temperature": (i, [vp, _dbl_p]),
            "hcbd_world_potential_energy": (d, [vp]),
            "hcbd_world_friction_average": (i, [vp, i, _dbl_p]),
            "hcbd_world_transverse_current": (i, [vp, i, _dbl_p]),
            "hcbd_world_forces": (i, [vp, _dbl_p]),
            "hcbd_rdf_sample": (i, [vp, vp]), "hcbd_rdf_result": (ctypes.c_int64, [vp, _dbl_p, _dbl_p, _dbl_p]),
            "hcbd_rdf_coordination": (i, [vp, d, _dbl_p, _dbl_p]),
            "hpy_profile_new": (vp, [vp, i, i, cp, i]), "hcbd_profile_sample": (None, [vp, vp]),
            "hcbd_profile_result": (ctypes.c_int64, [vp, _dbl_p]),
        })
    for name, (res, args) in sig.items():
        f = getattr(lib, name)
        f.restype = res
        f.argtypes = args
    if lib.hpy_real_size() != 8:
        raise ImportError("hcbd: %s is a float build; the package takes the double one" % path)
    return lib


_libs = {}


def _lib(kind):
    if kind not in _libs:
        _libs[kind] = _load(kind)
    return _libs[kind]


def _ptr(a):
    return a.ctypes.data_as(_dbl_p)


def _msgbuf():
    return ctypes.create_string_buffer(_MSG)


def _define(lib, params):
    """A C world definition from keyword parameters (the C field names)."""
    d = lib.hpy_def_new()
    if not d:
        raise MemoryError("hcbd: out of memory")
    msg = _msgbuf()
    try:
        for key, value in params.items():
            if key == "seed":
                if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not 0 <= int(value) < 2 ** 64:
                    raise ValueError("seed = %r is not an unsigned 64-bit integer" % (value,))
                lib.hpy_def_set_seed(d, int(value))
                continue
            if isinstance(value, str):
                r = lib.hpy_def_set(d, key.encode(), None, 0, value.encode(), msg, _MSG)
            else:
                try:
                    v = np.ascontiguousarray(np.atleast_1d(np.asarray(value, dtype=np.float64)).ravel())
                except (TypeError, ValueError):
                    raise ValueError("%s = %r is not a number or a list of numbers" % (key, value)) from None
                r = lib.hpy_def_set(d, key.encode(), _ptr(v), int(v.size), None, msg, _MSG)
            if r:
                raise ValueError(msg.value.decode(errors="replace"))
    except BaseException:
        lib.hpy_def_free(d)
        raise
    return d


def _create(lib, params):
    """A world of the C defaults and params, or ValueError with the library's message."""
    d = _define(lib, params)
    msg = _msgbuf()
    try:
        h = lib.hpy_world_new(d, msg, _MSG)
    finally:
        lib.hpy_def_free(d)
    if not h:
        raise ValueError(msg.value.decode(errors="replace"))
    return h


class _Base:
    _kind = None
    _prefix = None

    def __init__(self, handle, lib):
        self._h = handle
        self._lib = lib

    def _fn(self, name):
        return getattr(self._lib, self._prefix + name)

    def _check(self, r, what=""):
        if r:
            name = self._lib.hcbd_result_name(r).decode()
            text = self._lib.hpy_error(self._h).decode(errors="replace")
            if r in (1, 2, 4, 13):  # NULL, PARAM, BOX, OVERLAP: a bad input
                raise ValueError("%s%s" % (what, text))
            raise HcbdError(r, "%s%s (%s)" % (what, text, name))

    def __del__(self):
        h, self._h = getattr(self, "_h", None), None
        if h:
            self._lib.hpy_world_free(h)

    def _view(self, name, dtype=np.float64):
        n = ctypes.c_int(0)
        p = self._lib.hpy_array(self._h, name.encode(), ctypes.byref(n))
        if not p or n.value == 0:
            return np.empty(0, dtype=dtype)
        ct = ctypes.c_double if dtype == np.float64 else ctypes.c_int32
        buf = (ct * n.value).from_address(p)
        buf._world = self  # the view keeps its world (and so its memory) alive
        a = np.frombuffer(buf, dtype=dtype)
        a.flags.writeable = False
        return a

    def step(self, n=1):
        """Advances n steps in C."""
        n = int(n)
        if n < 0:
            raise ValueError("step: n = %d is negative" % n)
        while True:  # the C API takes an int
            k = min(n, 1 << 30)
            self._check(self._fn("step")(self._h, k), "step: ")
            n -= k
            if n <= 0:
                break

    @property
    def params(self):
        """The world's parameters as created (after the library's defaults and checks): a dict by
        the C field names, the keywords the constructor takes; choices by their names."""
        out, names, k = {}, [], 0
        while True:
            nm = self._lib.hpy_key_name(k)
            if nm is None:
                break
            names.append(nm.decode())
            k += 1
        v, ch, integer = np.zeros(3), ctypes.c_char_p(), ctypes.c_int(0)
        for nm in names:
            ch.value = None
            n = self._lib.hpy_param_get(self._h, nm.encode(), _ptr(v), ctypes.byref(ch), ctypes.byref(integer))
            if n < 0:
                continue
            if ch.value is not None:
                out[nm] = ch.value.decode()
            elif nm == "seed":
                out[nm] = int(self._lib.hpy_seed(self._h))  # whole: a double holds 53 bits
            elif integer.value:
                out[nm] = int(v[0])
            else:
                out[nm] = float(v[0]) if n == 1 else v[:n].copy()
        return out

    @property
    def step_count(self):
        """Steps taken since the particles were set."""
        return int(self._lib.hpy_step_count(self._h))

    @property
    def box(self):
        b = np.zeros(3)
        self._lib.hpy_box(self._h, _ptr(b))
        return b

    @property
    def le_offset(self):
        """The Lees-Edwards offset of the images above the box."""
        return float(self._lib.hpy_le_offset(self._h))

    def checksum(self):
        """64-bit hash of the state: equal for bit-identical states (as the C API's)."""
        return int(self._fn("checksum")(self._h))

    def temperature(self):
        return float(self._fn("temperature")(self._h))

    def momentum(self):
        p = np.zeros(3)
        self._fn("momentum")(self._h, _ptr(p))
        return p

    def transverse_current(self, nk=1):
        """The transverse current at k = 2 pi nk / L_d along each axis d, (3, 2) complex:
        [d, c] = sum_i v_i,a exp(-i k x_i,d), a = (d + 1 + c) mod 3 (the two components transverse
        to d).
        C_t(k, t) = <Re(j(t) conj(j(0)))> / n, averaged over d and c."""
        out = np.zeros(12)
        self._check(self._fn("transverse_current")(self._h, int(nk), _ptr(out)), "transverse_current: ")
        return (out[0::2] + 1j * out[1::2]).reshape(3, 2)

    def set_threads(self, n):
        """OpenMP threads; the bits do not depend on them."""
        self._check(self._fn("set_threads")(self._h, int(n)), "set_threads: ")

    def stress_enable(self, on=True):
        """Starts (clearing the sums) or stops the stress accumulation."""
        self._check(self._fn("stress_enable")(self._h, 1 if on else 0), "stress_enable: ")

    def save(self, path):
        """A checkpoint: a later load and n steps give the same bits as n steps now."""
        self._check(self._fn("save")(self._h, os.fsencode(path)), "save: ")

    @classmethod
    def load(cls, path):
        """The world of a checkpoint file."""
        lib = _lib(cls._kind)
        msg = _msgbuf()
        h = lib.hpy_world_load(os.fsencode(path), msg, _MSG)
        if not h:
            raise HcbdError(0, "load: " + msg.value.decode(errors="replace"))
        return cls._wrap(h, lib)

    @classmethod
    def _wrap(cls, h, lib):
        w = cls.__new__(cls)
        _Base.__init__(w, h, lib)
        return w

    def write_xyz(self, path, append=True):
        """One extended XYZ frame (OVITO, ASE), appended to path by default."""
        msg = _msgbuf()
        r = self._lib.hpy_write_xyz(self._h, os.fsencode(path), 1 if append else 0, msg, _MSG)
        if r:
            raise HcbdError(r, "write_xyz: " + msg.value.decode(errors="replace"))


class World(_Base):
    """A GI-BD (or classical BD, or walled) world, keyword parameters as hcbd_params and
    hcbd_world_def (C defaults: the 2014 star scene).  N particles at number
    density `density` fill a box sized for them (or give L) and are placed on a
    lattice (place='lattice'), at random ('random'), or at positions (N, 3)."""
    _kind = "walled"
    _prefix = "hcbd_world_"

    def __init__(self, N=512, positions=None, place="lattice", **params):
        lib = _lib(self._kind)
        N = int(N)
        if N < 1:
            raise ValueError("N = %d: a world needs at least one particle" % N)
        params.setdefault("capacity", N)
        if "L" not in params:  # a cube of open volume N / density, as the examples size it
            dens = params.get("density", 0.24)
            if isinstance(dens, bool) or not isinstance(dens, (int, float, np.floating)) or not dens > 0:
                raise ValueError("density = %r is not a positive number" % (dens,))
            wall = params.get("wall_thickness", 0.0)
            if isinstance(wall, bool) or not isinstance(wall, (int, float, np.floating)):
                raise ValueError("wall_thickness = %r is not a number" % (wall,))
            edge = math.cbrt(N / float(dens))
            params["L"] = [edge, edge + 2.0 * float(wall) if wall else edge, edge]
        h = _create(lib, params)
        _Base.__init__(self, h, lib)
        if positions is not None:
            self.set_positions(positions)
        elif place == "lattice":
            self._check(lib.hcbd_world_place_lattice(h, N), "place_lattice: ")
        elif place == "random":
            self._check(lib.hcbd_world_place_random(h, N), "place_random: ")
        else:
            raise ValueError("place = %r is not 'lattice' or 'random'" % (place,))

    @property
    def n(self):
        return self._view("id", np.int32).size

    x = property(lambda s: s._view("x"), doc="positions along x, storage order (read-only view)")
    y = property(lambda s: s._view("y"), doc="positions along y, storage order (read-only view)")
    z = property(lambda s: s._view("z"), doc="positions along z, storage order (read-only view)")
    vx = property(lambda s: s._view("vx"), doc="background velocity x, storage order (read-only view)")
    vy = property(lambda s: s._view("vy"), doc="background velocity y, storage order (read-only view)")
    vz = property(lambda s: s._view("vz"), doc="background velocity z, storage order (read-only view)")
    id = property(lambda s: s._view("id", np.int32), doc="the id at each storage slot (read-only view)")

    def positions(self, unwrapped=False):
        """A copy (n, 3) in id order; unwrapped adds the periodic images crossed."""
        a = np.empty((self.n, 3))
        self._check(self._lib.hcbd_world_get_positions(self._h, _ptr(a), 1 if unwrapped else 0))
        return a

    def velocities(self):
        """A copy (n, 3) of the background velocities in id order."""
        a = np.empty((self.n, 3))
        self._check(self._lib.hcbd_world_get_velocities(self._h, _ptr(a)))
        return a

    def set_positions(self, xyz):
        """Particles with ids 0..n-1 at xyz (n, 3); Maxwell velocities, the step counter reset."""
        a = np.ascontiguousarray(np.asarray(xyz, dtype=np.float64).reshape(-1, 3))
        self._check(self._lib.hcbd_world_set_positions(self._h, a.shape[0], _ptr(a)), "set_positions: ")

    def set_velocities(self, v):
        a = np.ascontiguousarray(np.asarray(v, dtype=np.float64).reshape(-1, 3))
        if a.shape[0] != self.n:
            raise ValueError("set_velocities: %d rows for %d particles" % (a.shape[0], self.n))
        self._check(self._lib.hcbd_world_set_velocities(self._h, _ptr(a)), "set_velocities: ")

    def stress_read(self):
        """Averages since stress_enable: dict of pair, background, boundary, total (S_yx)."""
        out, ns = np.zeros(4), ctypes.c_int64(0)
        self._check(self._lib.hcbd_world_stress_read(self._h, _ptr(out), ctypes.byref(ns)))
        return {"pair": out[0], "background": out[1], "boundary": out[2], "total": out[3], "steps": ns.value}

    def config_temperature(self):
        """(sum |grad U|^2, sum lap U) now: average each over samples and divide for kT_conf."""
        out = np.zeros(2)
        self._check(self._lib.hcbd_world_config_temperature(self._h, _ptr(out)), "config_temperature: ")
        return out[0], out[1]

    def potential_energy(self):
        return float(self._lib.hcbd_world_potential_energy(self._h))

    def forces(self):
        """The conservative force on each particle now (n, 3), id order: the one a step's drift uses."""
        f = np.empty((self.n, 3))
        self._check(self._lib.hcbd_world_forces(self._h, _ptr(f)), "forces: ")
        return f

    def friction_average(self, nk=1):
        """Friction averages of the configuration (GI-BD, MODEL 10): a dict of sum_f = <sum_j f_ij>,
        sum_f_r2 = <sum_j f_ij r_ij^2> and sum_f_k = <sum_j f_ij (1 - cos k.x_ij)> at
        |k| = 2 pi nk / L (averaged over the axes).  nu_meanfield = sum_f_k / (tau k^2)."""
        out = np.zeros(3)
        self._check(self._lib.hcbd_world_friction_average(self._h, int(nk), _ptr(out)), "friction_average: ")
        return {"sum_f": out[0], "sum_f_r2": out[1], "sum_f_k": out[2]}


_HC_COLS = ("kinetic", "pressure", "viscous", "noise", "fluid", "conservative", "transient", "polymer",
            "interaction", "total")


class HCWorld(_Base):
    """The 2018 world: `fluid` SPH blobs (a lattice, or fluid_positions) and `polymers`
    RaPiD blobs (random, or polymer_positions), keyword parameters as hcbd_hc_params
    and hcbd_hc_world_def (C defaults: Table I in sigma, kT and 1 us)."""
    _kind = "hc"
    _prefix = "hcbd_hc_world_"

    def __init__(self, fluid=806, polymers=0, fluid_positions=None, fluid_velocities=None,
                 polymer_positions=None, **params):
        lib = _lib(self._kind)
        fluid, polymers = int(fluid), int(polymers)
        if fluid < 2 or polymers < 0:
            raise ValueError("fluid = %d, polymers = %d: at least 2 fluid blobs and no negative count" %
                             (fluid, polymers))
        params.setdefault("fluid_capacity", fluid)
        params.setdefault("polymer_capacity", polymers)
        h = _create(lib, params)
        _Base.__init__(self, h, lib)
        if fluid_positions is not None:
            self.set_fluid(fluid_positions, fluid_velocities)
        else:
            self._check(lib.hcbd_hc_world_place_fluid_lattice(h, fluid), "place_fluid_lattice: ")
        if polymer_positions is not None:
            self.set_polymers(polymer_positions)
        elif polymers:
            self._check(lib.hcbd_hc_world_place_polymers_random(h, polymers), "place_polymers_random: ")

    fx = property(lambda s: s._view("fx"), doc="fluid positions x, id order (read-only view)")
    fy = property(lambda s: s._view("fy"), doc="fluid positions y, id order (read-only view)")
    fz = property(lambda s: s._view("fz"), doc="fluid positions z, id order (read-only view)")
    fvx = property(lambda s: s._view("fvx"), doc="fluid velocity x, id order (read-only view)")
    fvy = property(lambda s: s._view("fvy"), doc="fluid velocity y, id order (read-only view)")
    fvz = property(lambda s: s._view("fvz"), doc="fluid velocity z, id order (read-only view)")
    px = property(lambda s: s._view("px"), doc="polymer positions x, id order (read-only view)")
    py = property(lambda s: s._view("py"), doc="polymer positions y, id order (read-only view)")
    pz = property(lambda s: s._view("pz"), doc="polymer positions z, id order (read-only view)")

    @property
    def n_fluid(self):
        return self._view("fx").size

    @property
    def n_polymers(self):
        return self._view("px").size

    def fluid(self):
        """Copies (nf, 3) of the fluid's positions and velocities, id order."""
        x, v = np.empty((self.n_fluid, 3)), np.empty((self.n_fluid, 3))
        self._check(self._lib.hcbd_hc_world_get_fluid(self._h, _ptr(x), _ptr(v)))
        return x, v

    def polymers(self):
        """A copy (np, 3) of the polymers' positions, id order."""
        x = np.empty((self.n_polymers, 3))
        if x.size:
            self._check(self._lib.hcbd_hc_world_get_polymers(self._h, _ptr(x)))
        return x

    def set_fluid(self, xyz, v=None):
        a = np.ascontiguousarray(np.asarray(xyz, dtype=np.float64).reshape(-1, 3))
        vv = None if v is None else np.ascontiguousarray(np.asarray(v, dtype=np.float64).reshape(-1, 3))
        if vv is not None and vv.shape != a.shape:
            raise ValueError("set_fluid: %d velocities for %d blobs" % (vv.shape[0], a.shape[0]))
        self._check(self._lib.hcbd_hc_world_set_fluid(self._h, a.shape[0], _ptr(a), None if vv is None else _ptr(vv)),
                    "set_fluid: ")

    def set_polymers(self, xyz):
        a = np.ascontiguousarray(np.asarray(xyz, dtype=np.float64).reshape(-1, 3))
        self._check(self._lib.hcbd_hc_world_set_polymers(self._h, a.shape[0], _ptr(a)), "set_polymers: ")

    def stress_read(self):
        """Averages since stress_enable: the split of 2018 Fig. 4 (S_yx per column) and 'steps'."""
        out, ns = np.zeros(10), ctypes.c_int64(0)
        self._check(self._lib.hcbd_hc_world_stress_read(self._h, _ptr(out), ctypes.byref(ns)))
        r = dict(zip(_HC_COLS, (float(x) for x in out)))
        r["steps"] = ns.value
        return r

    def polymer_energy(self):
        """The polymers' conservative energy (densities and pair variables) now."""
        return float(self._lib.hcbd_hc_world_polymer_energy(self._h))

    def density_range(self):
        """(min n_i/nbar, max n_i/nbar, min pressure)."""
        out = np.zeros(3)
        self._check(self._lib.hcbd_hc_world_density_range(self._h, _ptr(out)))
        return tuple(out)


class _Block:
    """An accumulator's C block (made by an hpy_*_new, freed with the object)."""

    def _own(self, lib, new, *args):
        msg = _msgbuf()
        self._lib = lib
        self._h = new(*args, msg, _MSG)
        if not self._h:
            raise ValueError(msg.value.decode(errors="replace"))

    def __del__(self):
        h, self._h = getattr(self, "_h", None), None
        if h:
            self._lib.hpy_free(h)


class RDF(_Block):
    """g(r) of a World in nbins shells up to rmax, block errors with `block` samples a block."""

    def __init__(self, rmax, nbins, block=0):
        lib = _lib("walled")
        self._own(lib, lib.hpy_rdf_new, float(rmax), int(nbins), int(block))
        self.nbins = int(nbins)

    def sample(self, world):
        world._check(self._lib.hcbd_rdf_sample(self._h, world._h), "rdf sample: ")

    def result(self):
        """(r, g, err): shell centres, g(r), its block error (NaN with fewer than two blocks)."""
        r, g, e = np.zeros(self.nbins), np.zeros(self.nbins), np.zeros(self.nbins)
        self._lib.hcbd_rdf_result(self._h, _ptr(r), _ptr(g), _ptr(e))
        return r, g, e

    def coordination(self, rc):
        nc, err = ctypes.c_double(0), ctypes.c_double(0)
        r = self._lib.hcbd_rdf_coordination(self._h, float(rc), ctypes.byref(nc), ctypes.byref(err))
        if r:
            raise ValueError("coordination: rc = %g refused" % rc)
        return nc.value, err.value


class MSD(_Block):
    """Mean-squared displacement with multiple origins (order-n): feed unwrapped (n, 3) positions in
    id order every sample; lags j B^l, block errors with `block` samples a block."""

    def __init__(self, n, B=10, levels=4, dense=0, block=0, kind="walled"):
        lib = _lib(kind)
        self._own(lib, lib.hpy_msd_new, int(n), int(B), int(levels), int(dense), int(block))
        self.n, self._max = int(n), int(levels) * (int(B) - 1)

    def add(self, xyz):
        a = np.ascontiguousarray(np.asarray(xyz, dtype=np.float64).reshape(-1, 3))
        if a.shape[0] != self.n:
            raise ValueError("MSD.add: %d positions for n = %d" % (a.shape[0], self.n))
        self._lib.hcbd_msd_add(self._h, _ptr(a))

    def result(self):
        """(lag in samples, MSD, block error)."""
        lag, m, e = np.zeros(self._max), np.zeros(self._max), np.zeros(self._max)
        k = self._lib.hcbd_msd_stats(self._h, _ptr(lag), _ptr(m), _ptr(e), self._max)
        return lag[:k], m[:k], e[:k]

    def diffusion(self, lag_min, lag_max):
        """D per sample (slope / 6) and its block error from the lags in [lag_min, lag_max]."""
        D, e = ctypes.c_double(0), ctypes.c_double(0)
        r = self._lib.hcbd_msd_diffusion(self._h, float(lag_min), float(lag_max), ctypes.byref(D), ctypes.byref(e))
        if r:
            raise ValueError("MSD.diffusion: the window [%g, %g] holds fewer than two lags" % (lag_min, lag_max))
        return D.value, e.value


class Profile(_Block):
    """Slab profiles across y of a World (density, <v_x>, temperature) with block errors."""

    def __init__(self, world, nslab, block=10):
        self._own(world._lib, world._lib.hpy_profile_new, world._h, int(nslab), int(block))
        self.nslab = int(nslab)

    def sample(self, world):
        self._lib.hcbd_profile_sample(self._h, world._h)

    def result(self):
        """A dict of arrays: y, density, density_err, vx, vx_err, T, T_err, particles."""
        out = np.zeros(8 * self.nslab)
        self._lib.hcbd_profile_result(self._h, _ptr(out))
        o = out.reshape(self.nslab, 8)
        names = ("y", "density", "density_err", "vx", "vx_err", "T", "T_err", "particles")
        return {k: o[:, c].copy() for c, k in enumerate(names)}


def carreau_fit(gdot, eta, err, eta_inf, start=None):
    """Carreau fit eta_inf + (eta0 - eta_inf)[1 + (lambda gdot)^2]^((n-1)/2) with eta_inf fixed:
    (eta0, lambda, n), their errors, chi^2 and the error scale sqrt(chi^2/dof) where above 1."""
    lib = _lib("walled")
    g, e, s = (np.ascontiguousarray(np.asarray(a, dtype=np.float64)) for a in (gdot, eta, err))
    if not (g.shape == e.shape == s.shape) or g.ndim != 1:
        raise ValueError("carreau_fit: gdot, eta and err must be 1-d of one length")
    p, pe, chi2 = np.zeros(3), np.zeros(3), ctypes.c_double(0)
    if start is not None:
        p[:] = np.asarray(start, dtype=np.float64)
    r = lib.hcbd_carreau_fit(_ptr(g), _ptr(e), _ptr(s), g.size, float(eta_inf), 1 if start is not None else 0,
                             _ptr(p), _ptr(pe), ctypes.byref(chi2))
    if r:
        raise ValueError("carreau_fit: %s (needs 4 points or more, positive rates and errors)" %
                         lib.hcbd_result_name(r).decode())
    return {"eta0": p[0], "lambda": p[1], "n": p[2], "errors": pe, "chi2": chi2.value,
            "err_scale": lib.hcbd_carreau_err_scale(chi2.value, g.size)}


def blocking_error(x):
    """Mean of a correlated series and its standard error by blocking (Flyvbjerg and Petersen):
    (mean, err, neff, plateau)."""
    lib = _lib("walled")
    a = np.ascontiguousarray(np.asarray(x, dtype=np.float64).ravel())
    m, e, n, pl = ctypes.c_double(0), ctypes.c_double(0), ctypes.c_double(0), ctypes.c_int(0)
    r = lib.hcbd_blocking_error(_ptr(a), a.size, ctypes.byref(m), ctypes.byref(e), ctypes.byref(n), ctypes.byref(pl))
    if r:
        raise ValueError("blocking_error: needs 8 finite values or more")
    return m.value, e.value, n.value, bool(pl.value)
