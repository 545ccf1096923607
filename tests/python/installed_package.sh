#!/usr/bin/env bash
# `pip install .` as a user does it, offline (Debian's setuptools, --no-build-isolation), reusing the build
# folder BUILD so that nothing compiles twice: `pip wheel .` makes the wheel; it installs into a venv with the
# system's packages, where the whole pytest suite runs against the installed copy (not the build tree), and into a
# bare venv without numpy, where the package imports, answers exactly and says that float views need numpy.
# Usage: installed_package.sh SOURCE BUILD WORK
set -euo pipefail
src=$1 build=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
python=/usr/bin/python3
"$python" -m venv --system-site-packages "$work/venv"
(cd "$src" && CONTACTCERT_BUILD_DIR="$build" "$work/venv/bin/pip" wheel -q --no-build-isolation --no-deps --no-index \
  -w "$work/wheel" .)
wheel=$(ls "$work"/wheel/contactcert-*.whl)
"$work/venv/bin/pip" install -q --no-index --no-deps "$wheel"

# The suite against the installed copy: run from the work folder, without PYTHONPATH.
(cd "$work" && env -u PYTHONPATH CONTACTCERT_CLI="$build/cli/contactcert" "$work/venv/bin/python" -m pytest -q \
  -p no:cacheprovider --rootdir "$src" "$src/tests/python")
"$work/venv/bin/python" - <<'PY'
import contactcert, pathlib
assert "site-packages" in contactcert.__file__, contactcert.__file__
assert (pathlib.Path(contactcert.__file__).parent / "bin" / "contactcert").exists()
PY
"$work/venv/bin/python" -m contactcert --version

# A bare venv: no numpy, no system packages.
"$python" -m venv --without-pip "$work/bare"
"$work/venv/bin/pip" install -q --no-index --no-deps --target "$work/bare-site" "$wheel"
PYTHONPATH="$work/bare-site" SCENE="$src/scenes/bt2002_fig4a_lla.json" "$work/bare/bin/python" - <<'PY'
import os, sys
import contactcert as cc
assert "numpy" not in sys.modules
try:
    import numpy  # noqa: F401
    raise SystemExit("numpy is importable in the bare venv")
except ModuleNotFoundError:
    pass
scene = cc.Scene.from_file(os.environ["SCENE"])
verdict = scene.stability("0,-1,0").verdict
cone = scene.cone("lla")
assert cone.rays, "the exact generators"
try:
    cone.rays_approx
    raise SystemExit("a float view worked without numpy")
except ModuleNotFoundError as e:
    assert "need numpy" in str(e), e
print("bare venv:", cc.__version__, verdict, len(cone.rays), "rays")
PY
echo "installed_package: passed"
