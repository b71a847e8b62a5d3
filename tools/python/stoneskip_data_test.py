"""The Python reader and the documents' Python snippets, on a report made for the test.

Oracles: h5py's own read of each dataset (the reader must return the same numbers), the naming
convention (a column's stored unit is its name's suffix unit, for every name that has one), and
the documents: every ```python block of tools/README.md runs as written from a folder where
`stoneskip report waves --quick --out out/waves` has just run (outside the source tree, with a
link to tools/ as the snippet expects).

Usage (ctest runs it): python3 stoneskip_data_test.py STONESKIP SOURCE_DIR
Exit 77 (skipped, with the reason) where h5py or numpy cannot be imported.
"""

import os
import re
import subprocess
import sys
import tempfile

try:
    import h5py
    import numpy as np
except ImportError as e:
    print(f"skipped: {sys.executable} cannot import h5py and numpy ({e}); "
          "install python3-h5py python3-numpy (tools/setup/install-deps.sh)")
    sys.exit(77)

STONESKIP, SOURCE = sys.argv[1], os.path.abspath(sys.argv[2])
sys.path.insert(0, os.path.join(SOURCE, "tools", "python"))
import stoneskip_data as sd  # noqa: E402

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what)


def python_blocks(doc):
    text = open(doc, encoding="utf-8").read()
    return re.findall(r"^```python\n(.*?)^```", text, flags=re.S | re.M)


with tempfile.TemporaryDirectory(prefix="stoneskip_python_") as work:
    os.symlink(os.path.join(SOURCE, "tools"), os.path.join(work, "tools"))
    os.makedirs(os.path.join(work, "out"))
    subprocess.run([STONESKIP, "report", "waves", "--quick", "--out", "out/waves"], cwd=work, check=True,
                   stdout=subprocess.DEVNULL)
    subprocess.run([STONESKIP, "run", "cases/paper_8ms_spin.toml", "--out", "out/throw.h5"], cwd=work, check=True,
                   stdout=subprocess.DEVNULL)
    report = os.path.join(work, "out", "waves", "data.h5")
    throw = os.path.join(work, "out", "throw.h5")

    # 1. Every table: one unit per column, none empty, each as its name says; numbers as h5py reads them.
    for filename in (report, throw):
        names = sd.tables(filename)
        check(len(names) > 0, f"{filename}: no tables listed")
        with h5py.File(filename, "r") as f:
            for name in names:
                t = sd.read_table(filename, name)
                raw = f[name]
                check(list(raw.attrs["columns"]) == t.columns, f"{name}: columns are a string array")
                check(len(raw.attrs["units"]) == len(t.columns), f"{name}: one unit per column")
                check(np.array_equal(raw[()], t.values, equal_nan=True), f"{name}: values as h5py reads them (NaN: no value)")
                for c in t.columns:
                    check(t.units[c] != "", f"{name}: column {c} has no unit")
                    by_name = sd.unit_of_name(c)
                    check(by_name == "" or t.units[c] == by_name,
                          f"{name}: column {c} stored as [{t.units[c]}], its name says [{by_name}]")

    # 2. A throw's trajectory: the units a reader expects, and a column as numpy.
    traj = sd.read_table(throw, "realtime/trajectory")
    check(traj.units["t_s"] == "s" and traj.units["vx_m_s"] == "m/s" and traj.units["energy_J"] == "J",
          f"trajectory units {traj.units}")
    check(bool(np.all(np.diff(traj["t_s"]) > 0)), "trajectory times increase")

    # 3. pandas, where it is installed.
    try:
        import pandas  # noqa: F401
    except ImportError:
        print("pandas not importable: read_frame not tested")
    else:
        df = sd.read_frame(throw, "realtime/contacts")
        check(list(df.columns) == sd.read_table(throw, "realtime/contacts").columns, "read_frame keeps the columns")
        check(df.attrs["units"]["entry_speed_m_s"] == "m/s", "read_frame carries the units")

    # 4. The documents' snippets run as written.
    blocks = python_blocks(os.path.join(SOURCE, "tools", "README.md"))
    check(len(blocks) > 0, "tools/README.md has no ```python block")
    for i, code in enumerate(blocks):
        r = subprocess.run([sys.executable, "-c", code], cwd=work, capture_output=True, text=True)
        check(r.returncode == 0, f"tools/README.md python block {i + 1} failed:\n{r.stdout}\n{r.stderr}")
        if r.returncode == 0:
            print(f"tools/README.md python block {i + 1}:\n{r.stdout}")

if failures:
    print(f"{len(failures)} failure(s)")
    sys.exit(1)
print("ok")
