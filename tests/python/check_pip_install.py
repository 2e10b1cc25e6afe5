#!/usr/bin/env python3
"""`pip install .` as a Python user does it (README, docs/python.md "Installing"), offline: a
virtual environment with the system's site packages (Debian's numpy, setuptools, wheel), then
`pip install --no-build-isolation --no-index SOURCE`; `import gmcc` from another folder with a
clean environment gives the installed package (its version, its commit, its data), and runs a
selection; `python3 -m build --no-isolation --wheel` makes a wheel holding the extension, the stub
and the data; `pip uninstall gmcc` removes every installed file.

    check_pip_install.py SOURCE_DIR CMAKE_BUILD_DIR WORK_DIR

CMAKE_BUILD_DIR is an already configured build (the test build), so the extension is not compiled
a second time; setup.py's own configure step is what a fresh clone runs (docs/python.md).
"""

import json
import os
import shutil
import subprocess
import sys
import zipfile


def run(*args, env=None, cwd=None):
    p = subprocess.run(args, env=env, cwd=cwd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"FAIL: {' '.join(args)} exited {p.returncode}\n{p.stdout[-4000:]}\n{p.stderr[-4000:]}")
    return p.stdout


def main():
    source, build, work = (os.path.abspath(x) for x in sys.argv[1:4])
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    venv = os.path.join(work, "venv")
    run(sys.executable, "-m", "venv", "--system-site-packages", venv)
    python = os.path.join(venv, "bin", "python")
    env = {"PATH": os.path.join(venv, "bin") + ":/usr/bin:/bin", "HOME": work,
           "GMCC_CMAKE_BUILD_DIR": build, "PIP_DISABLE_PIP_VERSION_CHECK": "1", "PYTHONDONTWRITEBYTECODE": "1"}
    run(python, "-m", "pip", "install", "--no-build-isolation", "--no-index", source, env=env, cwd=work)

    site = run(python, "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])", env=env).strip()
    probe = (
        "import gmcc, json, os\n"
        "fs = gmcc.select([[1,1,1],[2,1,1],[1,2,1]], [[1,1,1]])\n"
        "print(json.dumps({'file': os.path.realpath(gmcc.__file__), 'data': os.path.realpath(gmcc.data_dir()),"
        " 'version': gmcc.__version__, 'commit': gmcc.__commit__, 'kind': fs.kind}))\n")
    clean = {"PATH": "/usr/bin:/bin", "HOME": work, "PYTHONDONTWRITEBYTECODE": "1"}
    got = json.loads(run(python, "-c", probe, env=clean, cwd=work))
    real_site = os.path.realpath(site)
    failures = []
    if not got["file"].startswith(os.path.join(real_site, "gmcc") + os.sep):
        failures.append(f"imported {got['file']}, not from {real_site}")
    if got["data"] != os.path.join(real_site, "gmcc", "data"):
        failures.append(f"data_dir() is {got['data']}")
    with open(os.path.join(source, "CMakeLists.txt")) as f:
        if f"project(gmcc VERSION {got['version']}" not in f.read():
            failures.append(f"version {got['version']} is not CMakeLists.txt's")
    if got["kind"] != "polygon":
        failures.append(f"select gave {got['kind']}")
    if not got["commit"]:
        failures.append("no commit recorded")

    # The wheel.
    dist = os.path.join(work, "dist")
    run(python, "-m", "build", "--no-isolation", "--wheel", "--outdir", dist, source, env=env, cwd=work)
    wheels = [f for f in os.listdir(dist) if f.endswith(".whl")]
    if len(wheels) != 1 or not wheels[0].startswith(f"gmcc-{got['version']}-"):
        failures.append(f"wheels made: {wheels}")
    else:
        names = zipfile.ZipFile(os.path.join(dist, wheels[0])).namelist()
        for want in ("gmcc/__init__.py", "gmcc/__init__.pyi", "gmcc/py.typed", "gmcc/_records.py",
                     "gmcc/data/munsell_matt_1269_joensuu_5nm.csv", "gmcc/data/SOURCES.md"):
            if want not in names:
                failures.append(f"the wheel lacks {want}")
        if not any(n.startswith("gmcc/_core") and n.endswith(".so") for n in names):
            failures.append("the wheel lacks the extension gmcc/_core*.so")

    # Uninstall: every file gone, import fails.
    run(python, "-m", "pip", "uninstall", "-y", "gmcc", env=env, cwd=work)
    if os.path.exists(os.path.join(site, "gmcc")) and any(
            f for _, _, files in os.walk(os.path.join(site, "gmcc")) for f in files):
        failures.append("pip uninstall left files in site-packages/gmcc")
    p = subprocess.run([python, "-c", "import gmcc"], env=clean, cwd=work, capture_output=True, text=True)
    if p.returncode == 0 or "No module named 'gmcc'" not in p.stderr:
        failures.append(f"import gmcc after uninstall: {p.returncode} {p.stderr[-300:]}")
    for f in failures:
        print("FAIL:", f)
    print("pip install, import, wheel and uninstall: ok" if not failures else f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
