"""What a new user meets first: the version, an import without numpy, the type stubs, `python -m contactcert`."""

import ast
import os
import pathlib
import re
import shutil
import subprocess
import sys
import sysconfig
import textwrap

import numpy as np
import pytest

import contactcert as cc
from contactcert import _core
from conftest import CLI, ROOT, SCENES

PACKAGE = pathlib.Path(cc.__file__).parent


def python(*args, env=None, **kw):
    """This interpreter in a subprocess (the package found as in this process: PYTHONPATH)."""
    return subprocess.run([sys.executable, *args], capture_output=True, text=True, timeout=60,
                          env=dict(os.environ, **(env or {})), **kw)


# -- the version -----------------------------------------------------------------------------------------------


def test_version_is_the_projects():
    project = re.search(r"project\(contactcert VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text()).group(1)
    assert cc.__version__ == project
    cli = subprocess.run([CLI, "--version"], capture_output=True, text=True, check=True).stdout.strip()
    assert cli == f"contactcert {cc.__version__}"


# -- numpy only for the float views -----------------------------------------------------------------------------

WITHOUT_NUMPY = textwrap.dedent("""
    import sys
    sys.modules["numpy"] = None  # `import numpy` now raises ModuleNotFoundError
    import contactcert as cc
    ds4 = cc.Ucp.from_file(sys.argv[1])
    r = ds4.solve(certificate=sys.argv[2])
    print(r.status, bool(cc.check(sys.argv[2], problem=ds4)), r.certificate.check().valid)
    disk = cc.Scene.from_file(sys.argv[3])
    print(disk.stability([1, -2, 0], arith="float").verdict)  # float arithmetic is not a float view
    try:
        disk.cone("na").rays_approx
    except ImportError as e:
        print(type(e).__name__, e.name, e)
""")


def test_exact_results_without_numpy(tmp_path):
    p = python("-c", WITHOUT_NUMPY, SCENES / "pang1994_dataset4.json", tmp_path / "ds4.json",
               SCENES / "bt2002_section4_disk.json")
    assert p.returncode == 0, p.stderr
    jammed, verdict, error = p.stdout.splitlines()
    assert jammed == "jammed True True"
    assert verdict == "unstable"  # as `contactcert stability` says
    assert error.startswith("ModuleNotFoundError numpy contactcert: the float views (*_approx) need numpy")


def test_import_leaves_numpy_alone():
    p = python("-c", "import sys, contactcert; print('numpy' in sys.modules)")
    assert p.returncode == 0, p.stderr
    assert p.stdout.strip() == "False"


def test_numpy_floats_refused_and_views_are_arrays():
    disk = cc.Scene.from_file(SCENES / "bt2002_section7_disk.json")
    for x in (np.float32(0.5), np.float64(0.5), 0.5):
        with pytest.raises(ValueError, match="found the float"):
            disk.stability([x, -2, 0])
    assert disk.stability([np.int32(1), -2, 0]).wrench == (1, -2, 0)
    assert isinstance(disk.stability([-1, -1, 0]).acceleration_approx, np.ndarray)


# -- type hints ------------------------------------------------------------------------------------------------


def stub_names(body):
    """Names a stub body defines: classes, functions and annotated attributes."""
    names = {}
    for node in body:
        if isinstance(node, (ast.ClassDef, ast.FunctionDef)):
            names[node.name] = node
        elif isinstance(node, ast.AnnAssign):
            names[node.target.id] = node
    return names


def public(names):
    return {n for n in names if not n.startswith("_")}


def test_package_is_typed():
    assert (PACKAGE / "py.typed").is_file()
    assert (PACKAGE / "_core.pyi").is_file()


def test_stub_names_match_the_extension():
    stub = stub_names(ast.parse((PACKAGE / "_core.pyi").read_text()).body)
    assert public(stub) == public(vars(_core))
    assert "__version__" in stub and "__version__" in vars(_core)
    for name, node in stub.items():
        if isinstance(node, ast.ClassDef):
            core_class = getattr(_core, name)
            base = core_class.__mro__[1]  # pybind11's object, or RuntimeError for BudgetExceeded
            own = {n for n in dir(core_class) if n not in dir(base) or getattr(core_class, n) is not getattr(base, n)}
            assert public(stub_names(node.body)) == public(own), name


def core_signature(f):
    """A pybind11 function's parameters (name, or None for pybind11's unnamed argN; type) and return type, from
    its docstring's signature line, spelled as the stub spells them."""

    def spell(t):
        t = t.replace("contactcert._core.", "").replace("List[", "list[").replace("Tuple[", "tuple[")
        return re.sub(r"Optional\[(\w+)\]", r"\1 | None", t)

    params, ret = re.fullmatch(r"\w+\((.*)\) -> (.*)", f.__doc__.splitlines()[0]).groups()
    out = []
    for p in re.split(r", (?![^\[]*\])", params) if params else []:
        name, _, type_ = p.partition(": ")
        type_ = type_.partition(" = ")[0]  # a default value (the stub writes it beside the annotation)
        unnamed = re.fullmatch(r"arg\d+", name)
        out.append(("self", None) if name == "self" else (None if unnamed else name, spell(type_)))
    return out, spell(ret)


def stub_signature(node):
    """The same for a stub's function: positional-only parameters have no name (pybind11's argN)."""
    a = node.args
    out = [("self", None) if p.arg == "self" else (None if p in a.posonlyargs else p.arg, ast.unparse(p.annotation))
           for p in a.posonlyargs + a.args]
    return out, ast.unparse(node.returns)


def test_stub_signatures_match_the_extension():
    checked = 0
    for name, node in stub_names(ast.parse((PACKAGE / "_core.pyi").read_text()).body).items():
        members = stub_names(node.body).items() if isinstance(node, ast.ClassDef) else [(None, node)]
        for member, f in members:
            if isinstance(f, ast.FunctionDef) and not any(ast.unparse(d) == "property" for d in f.decorator_list):
                core = getattr(_core, name) if member is None else getattr(getattr(_core, name), member)
                assert stub_signature(f) == core_signature(core), (name, member)
                checked += 1
    assert checked == 46  # every function and method of the stub


def test_annotations_check_against_the_stub(tmp_path):
    """mypy (Debian: python3-mypy, optional) finds the package's annotations consistent with _core.pyi."""
    pytest.importorskip("mypy")
    p = python("-m", "mypy", "--strict", "--no-warn-return-any", "--cache-dir", tmp_path, "-p", "contactcert",
               cwd=PACKAGE.parent)
    assert p.returncode == 0, p.stdout


# -- python -m contactcert -------------------------------------------------------------------------------------


def scripts_cli():
    """The CLI in the package (`pip install .`) or in this interpreter's scripts directory, which `python -m
    contactcert` prefers to PATH's."""
    return (shutil.which("contactcert", path=str(PACKAGE / "bin"))
            or shutil.which("contactcert", path=sysconfig.get_path("scripts")))


def test_main_runs_the_cli(tmp_path):
    env = {"PATH": os.path.dirname(CLI)}
    cli = scripts_cli() or CLI
    p = python("-m", "contactcert", "--version", env=env)
    assert p.returncode == 0, p.stderr
    assert p.stdout == subprocess.run([cli, "--version"], capture_output=True, text=True).stdout
    bad = tmp_path / "bad.json"
    bad.write_text("{")
    p = python("-m", "contactcert", "stability", bad, "--wrench", "1,0,0", env=env)
    assert p.returncode == 2
    assert p.stderr.startswith(f"contactcert: {bad}")


def test_main_without_an_executable(tmp_path):
    if scripts_cli():
        pytest.skip("a contactcert executable is installed in the package or the scripts directory")
    p = python("-m", "contactcert", "--version", env={"PATH": str(tmp_path)})
    assert p.returncode == 127
    assert p.stdout == ""
    assert p.stderr.startswith("contactcert: no contactcert executable in ")
