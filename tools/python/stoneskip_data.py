"""Read stoneskip's HDF5 files from Python: reports (DIR/data.h5), sweeps (sweep --out FILE.h5),
throws (run --out FILE.h5) and scenes (scene --out FILE.h5, with the water at chosen frames).

Every table is a 2-D dataset of float64 with two attributes, ``columns`` and ``units``, each an
array of strings with one entry per column (files written before the units hold one
comma-separated ``columns`` string; their units are read from the names' suffixes, the rule
stoneskip itself uses: ``t_s`` is in s, ``entry_speed_m_s`` in m/s, a name without a suffix is
dimensionless, "1"). Needs h5py and numpy; pandas only for :func:`read_frame`.

    import stoneskip_data as sd
    sd.tables("out/waves/data.h5")                       # every table's path in the file
    t = sd.read_table("out/waves/data.h5", "sections/convergence/five_point/both/points")
    t["l2_error_m"], t.units["l2_error_m"]               # a numpy array and "m"
    df = sd.read_frame("out/throws/paper_8ms_spin.h5", "realtime/contacts")   # pandas
"""

import h5py
import numpy as np

__all__ = ["Table", "tables", "read_table", "read_frame", "read_water", "unit_of_name"]

# Suffix -> unit, longest first (the same list as tools/io/column_units.cpp).
_SUFFIXES = [
    ("_time_m3_s", "m^3 s"), ("_kg_m_s", "kg m/s"), ("_kg_m2", "kg m^2"), ("_kg_m3", "kg/m^3"),
    ("_rev_s", "rev/s"), ("_rad_s", "rad/s"), ("_deg_s", "deg/s"), ("_m_s", "m/s"), ("_m2", "m^2"),
    ("_m3", "m^3"), ("_deg", "deg"), ("_rad", "rad"), ("_ms", "ms"), ("_kg", "kg"), ("_J", "J"),
    ("_W", "W"), ("_N", "N"), ("_g", "g_n"), ("_s", "s"), ("_m", "m"),
]
# Names whose unit only their table knows (the writer stores it).
_CONTEXTUAL = {"value", "error", "x", "low", "high", "lo", "hi", "h"}


def unit_of_name(name):
    """The unit a column name states by its suffix ("" for value, error, x, ...)."""
    if name in _CONTEXTUAL:
        return ""
    for suffix, unit in _SUFFIXES:
        if len(name) > len(suffix) and name.endswith(suffix):
            return unit
    return "1"


def _strings(attr):
    if isinstance(attr, (bytes, str)):
        return [attr.decode() if isinstance(attr, bytes) else attr]
    return [a.decode() if isinstance(a, bytes) else str(a) for a in attr]


class Table:
    """One stored table: ``columns`` (names), ``units`` (name -> unit), ``values`` (2-D numpy
    array, rows x columns); ``t["t_s"]`` is one column as a 1-D numpy array."""

    def __init__(self, path, columns, units, values):
        self.path = path
        self.columns = list(columns)
        self.units = dict(zip(self.columns, units))
        self.values = values

    def __getitem__(self, name):
        return self.values[:, self.columns.index(name)]

    def __len__(self):
        return self.values.shape[0]

    def __repr__(self):
        cols = ", ".join(f"{c} [{self.units[c]}]" for c in self.columns)
        return f"Table({self.path}: {len(self)} rows; {cols})"


def _is_table(obj):
    return isinstance(obj, h5py.Dataset) and obj.ndim == 2 and "columns" in obj.attrs


def tables(filename):
    """The paths of every table in a stoneskip HDF5 file, in the file's order."""
    found = []
    with h5py.File(filename, "r") as f:
        f.visititems(lambda name, obj: found.append(name) if _is_table(obj) else None)
    return found


def read_table(filename, path):
    """The table at ``path`` (as :func:`tables` lists it) as a :class:`Table` of numpy arrays."""
    with h5py.File(filename, "r") as f:
        ds = f[path]
        if not _is_table(ds):
            raise KeyError(f"{filename}: {path} is not a table (a 2-D dataset with a 'columns' attribute)")
        raw = ds.attrs["columns"]
        columns = _strings(raw)
        if len(columns) == 1 and ds.shape[1] != 1:  # the older layout: one comma-separated string
            columns = columns[0].split(",")
        if "units" in ds.attrs:
            units = _strings(ds.attrs["units"])
        else:
            units = [unit_of_name(c) for c in columns]
        if len(columns) != ds.shape[1] or len(units) != len(columns):
            raise ValueError(f"{filename}: {path} has {ds.shape[1]} columns, {len(columns)} names, {len(units)} units")
        return Table(path, columns, units, np.asarray(ds[()], dtype=np.float64))


def read_frame(filename, path):
    """The table as a pandas DataFrame; its units in ``df.attrs["units"]`` (name -> unit)."""
    import pandas as pd  # optional: only this function needs it

    t = read_table(filename, path)
    df = pd.DataFrame(t.values, columns=t.columns)
    df.attrs["units"] = dict(t.units)
    return df


def read_water(filename):
    """A scene file's stored water (``stoneskip scene CASE --out F.h5 --water-frames ...``):
    a dict with ``t_s`` (frames' times, s), ``height_m`` (frames x ny x nx, m, float32),
    ``x_m`` and ``y_m`` (the cell centres, m)."""
    with h5py.File(filename, "r") as f:
        w = f["water"]
        height = np.asarray(w["height_m"][()])
        nx, ny = int(w.attrs["nx"]), int(w.attrs["ny"])
        d = float(w.attrs["cell_m"])
        return {
            "t_s": np.asarray(w["t_s"][()]),
            "height_m": height,
            "x_m": float(w.attrs["origin_x_m"]) + d * np.arange(nx),
            "y_m": float(w.attrs["origin_y_m"]) + d * np.arange(ny),
        }
