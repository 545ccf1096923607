"""to_dict() == --json (issue 30): for every bundled file (scenes/, examples/) and every question it can be asked,
the Python call and the CLI give the same object, write the same certificate bytes and refuse bad input with the
same message. Planar scenes: stability under (0, -1, 0) in every arithmetic (with its margin, its certificate),
the region, the finger pushes, modes (with its certificate), the cones of the first mode `modes` lists, insert;
quasistatic problems and quasistatic scenes: ucp for every method and arithmetic (with its certificate); every
certificate written: check, alone, against its own problem file and against the same problem spelled otherwise;
assemblies (files with `bodies`): `assembly` (stability, or `--ucp` for a quasistatic scene) against Assembly;
motion scenes (files with `motion`, one body or several): `simulate` against Motion."""

import json
import subprocess
from decimal import Decimal, localcontext
from fractions import Fraction

import pytest

import contactcert as cc
from conftest import CLI, ROOT, without_seconds

FILES = sorted(p for d in ("scenes", "examples") for p in (ROOT / d).glob("*.json"))
WRENCH = "0,-1,0"
TIMINGS = ("seconds", "phases")  # a UCP report's CPU times: measured, never equal between two runs


def kind(path):
    """The file's kind, "motion" for a motion scene, "assembly" for one with several bodies."""
    data = json.loads(path.read_text())
    if "motion" in data:
        return "motion"
    return "assembly" if "bodies" in data else data.get("kind")


PLANAR = [p for p in FILES if kind(p) == "planar"]
UCP = [p for p in FILES if kind(p) in ("quasistatic", "quasistatic_scene", "ucp")]
ASSEMBLY = [p for p in FILES if kind(p) == "assembly"]
MOTION = [p for p in FILES if kind(p) == "motion"]
SPATIAL = [p for p in FILES if kind(p) == "spatial"]

# Planar questions: name -> (the Python call on a Scene, the CLI's arguments after FILE).
PLANAR_QUESTIONS = {
    "stability": (lambda s: s.stability(WRENCH), ["--wrench", WRENCH]),
    "stability-exact": (lambda s: s.stability(WRENCH, arith="exact"), ["--wrench", WRENCH, "--arith", "exact"]),
    "stability-float": (lambda s: s.stability(WRENCH, arith="float"), ["--wrench", WRENCH, "--arith", "float"]),
    "stability-adaptive": (lambda s: s.stability(WRENCH, arith="adaptive"),
                           ["--wrench", WRENCH, "--arith", "adaptive"]),
    "margin": (lambda s: s.stability(WRENCH, margin=True), ["--wrench", WRENCH, "--margin"]),
    "region": (lambda s: s.region(), ["--region"]),
    "finger": (lambda s: s.finger(), ["--finger"]),
}
MODES_QUESTIONS = {
    "modes": (lambda s: s.modes(), []),
    "modes-kinematic": (lambda s: s.modes(kinematic=True), ["--kinematic"]),
    "modes-printed-unions": (lambda s: s.modes(table2="printed", unions=True), ["--table2", "printed", "--unions"]),
    "modes-exact": (lambda s: s.modes(arith="exact"), ["--arith", "exact"]),
}
INSERT_QUESTIONS = {
    "insert": (lambda s: s.insertion(), []),
    "insert-sweep": (lambda s: s.insertion(sweep_mu="1/10,1/2"), ["--sweep-mu", "1/10,1/2"]),
}
CONE_VARIANTS = {
    "paper-verified": ({}, []),
    "project-verified": ({"route": "project"}, ["--route", "project"]),
    "paper-exact": ({"arith": "exact"}, ["--arith", "exact"]),
    "paper-float": ({"arith": "float"}, ["--arith", "float"]),
}
UCP_VARIANTS = ["complete-verified", "complete-exact", "complete-float", "complete-adaptive", "paper-verified",
                "modified-verified", "enumerate-exact"]


def cases(paths, questions):
    """pytest params (file, question)."""
    return [pytest.param(p, q, id=f"{p.name}-{q}") for p in paths for q in questions]


def cli(*args):
    """(exit code, stdout, stderr) of `contactcert ARGS --json`."""
    p = subprocess.run([CLI, *map(str, args), "--json"], capture_output=True, text=True, timeout=60)
    return p.returncode, p.stdout, p.stderr


def without(d, keys):
    return {k: v for k, v in d.items() if k not in keys}


def same_answer(python_call, args, drop=()):
    """The CLI's --json for ARGS equals python_call().to_dict() (members in `drop` aside); or both refuse the input
    with the same message (exit 2 / ValueError); or both run out of a budget (exit 3 / BudgetExceeded: the CLI
    prints the limit alone, or an `unknown` answer that is the exception's result). Returns the CLI's exit code."""
    code, out, err = cli(*args)
    if code == 2:
        with pytest.raises(ValueError) as e:
            python_call()
        assert err.strip() == f"contactcert: {e.value}"
    elif code == 3:
        with pytest.raises(cc.BudgetExceeded) as e:
            python_call()
        if out:  # an answer with status unknown (the bilinear methods cannot prove jamming)
            assert without(e.value.result.to_dict(), drop) == without(json.loads(out), drop)
        else:  # a budget or the time limit: the CLI reports the limit alone, in Python's words
            assert err == f"contactcert: {e.value}\n"
    else:
        assert code == 0, err
        assert without(python_call().to_dict(), drop) == without(json.loads(out), drop)
    return code


def same_certificate(path, python_call, args, drop=()):
    """same_answer with `--certificate PATH` / certificate=PATH: the CLI writes first, then Python to the same path
    (the path is part of the object); both files must hold the same bytes. The certificate's path, if written."""
    code, out, err = cli(*args, "--certificate", path)
    written = path.read_bytes() if path.exists() else None
    path.unlink(missing_ok=True)
    assert code in (0, 3), err
    if code == 3:
        with pytest.raises(cc.BudgetExceeded):
            python_call(path)
    else:
        assert without(python_call(path).to_dict(), drop) == without(json.loads(out), drop)
    assert (path.read_bytes() if path.exists() else None) == written
    return path if written is not None else None


def decimal(x):
    """The decimal text of a fraction text p/q whose expansion ends ("201/250" -> "0.804"), else None."""
    try:
        f = Fraction(x)
    except ValueError:
        return None
    q = f.denominator
    for p in (2, 5):
        while q % p == 0:
            q //= p
    if q != 1 or "/" not in x:
        return None
    with localcontext() as c:
        c.prec = 100
        return str(Decimal(f.numerator) / Decimal(f.denominator))


def respelled(path, tmp_path):
    """The same problem written otherwise: keys in reverse order, integers as JSON numbers, fractions with a
    finite decimal expansion as decimals, indented."""
    def spell(x):
        if isinstance(x, dict):
            return {k: spell(x[k]) for k in reversed(list(x))}
        if isinstance(x, list):
            return [spell(v) for v in x]
        if isinstance(x, str) and x.lstrip("-").isdigit():
            return int(x)
        if isinstance(x, str) and decimal(x):
            return decimal(x)
        return x
    out = tmp_path / f"respelled_{path.name}"
    out.write_text(json.dumps(spell(json.loads(path.read_text())), indent=3))
    return out


def same_check(certificate, problem_file, load, tmp_path):
    """`check CERT [--problem FILE] --json` (exit 0 VALID, 2 INVALID) equals cc.check(CERT, problem=...).to_dict():
    without a problem, with its own file, and with the same problem spelled otherwise."""
    for file in (None, problem_file, respelled(problem_file, tmp_path)):
        code, out, err = cli("check", certificate, *(["--problem", file] if file else []))
        assert code in (0, 2) and out, err
        assert cc.check(certificate, problem=load(file) if file else None).to_dict() == json.loads(out)


# --- planar scenes -------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("path,question", cases(PLANAR, PLANAR_QUESTIONS))
def test_stability(path, question):
    call, args = PLANAR_QUESTIONS[question]
    scene = cc.Scene.from_file(path)
    assert same_answer(lambda: call(scene), ["stability", path, *args]) == 0


@pytest.mark.parametrize("path,question", cases(PLANAR, MODES_QUESTIONS))
def test_modes(path, question):
    call, args = MODES_QUESTIONS[question]
    scene = cc.Scene.from_file(path)
    assert same_answer(lambda: call(scene), ["modes", path, *args]) == 0


@pytest.mark.parametrize("path,question", cases(PLANAR, INSERT_QUESTIONS))
def test_insert(path, question):
    """Insertion takes the goal configuration (2 or 3 fixels, all touching): other scenes are refused by both."""
    call, args = INSERT_QUESTIONS[question]
    scene = cc.Scene.from_file(path)
    same_answer(lambda: call(scene), ["insert", path, *args])


@pytest.mark.parametrize("path,question", cases(PLANAR, CONE_VARIANTS))
def test_cone(path, question):
    """The cone of the first mode `modes` lists (every bundled scene has one)."""
    kwargs, args = CONE_VARIANTS[question]
    scene = cc.Scene.from_file(path)
    mode = scene.modes().modes[0]
    assert same_answer(lambda: scene.cone(mode, **kwargs), ["cone", path, "--mode", mode, *args]) == 0


@pytest.mark.parametrize("path,question", cases(PLANAR, ["certificate"]))
def test_planar_certificates(path, question, tmp_path):
    """The stability and modes certificates of both are the same bytes; they, and the CLI's cone certificate
    (Python writes none), check alike."""
    scene = cc.Scene.from_file(path)
    mode = scene.modes().modes[0]
    written = [
        same_certificate(tmp_path / "stability.json", lambda p: scene.stability(WRENCH, certificate=p),
                         ["stability", path, "--wrench", WRENCH]),
        same_certificate(tmp_path / "modes.json", lambda p: scene.modes(certificate=p), ["modes", path]),
    ]
    for cert in written:
        assert cert is not None
        same_check(cert, path, cc.Scene.from_file, tmp_path)
    cone = tmp_path / "cone.json"
    code, _, err = cli("cone", path, "--mode", mode, "--certificate", cone)
    assert code == 0, err
    same_check(cone, path, cc.Scene.from_file, tmp_path)


# --- quasistatic problems and scenes -------------------------------------------------------------------------------
@pytest.mark.parametrize("path,question", cases(UCP, UCP_VARIANTS))
def test_ucp(path, question):
    method, arith = question.split("-")
    args = ["ucp", path, "--method", method, "--arith", arith]
    same_answer(lambda: cc.Ucp.from_file(path).solve(method=method, arith=arith), args, drop=TIMINGS)


@pytest.mark.parametrize("path,question", cases(UCP, ["certificate"]))
def test_ucp_certificate(path, question, tmp_path):
    code, _, err = cli("ucp", path)
    if code == 2:  # not a problem `ucp` reads: refused by both (test_ucp)
        pytest.skip(err.strip())
    problem = cc.Ucp.from_file(path)
    cert = same_certificate(tmp_path / "ucp.json", lambda p: problem.solve(certificate=p), ["ucp", path],
                            drop=TIMINGS)
    assert cert is not None
    same_check(cert, path, cc.Ucp.from_file, tmp_path)


@pytest.mark.parametrize("path", ASSEMBLY, ids=lambda p: p.name)
def test_assembly(path):
    assembly = cc.Assembly.from_file(path)
    if json.loads(path.read_text()).get("kind") == "quasistatic_scene":
        same_answer(assembly.ucp, ["assembly", path, "--ucp"], drop=TIMINGS)
    else:
        same_answer(assembly.stability, ["assembly", path])


# --- motion scenes ---------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("path", MOTION, ids=lambda p: p.name)
def test_simulate(path):
    code, out, err = cli("simulate", path, "--uniqueness", "off", "--compare")
    assert code == 0, err
    got = cc.Motion.from_file(path).simulate(uniqueness=False, compare=True).to_dict()
    assert without_seconds(got) == without_seconds(json.loads(out))


@pytest.mark.parametrize("path", SPATIAL, ids=lambda p: p.name)
def test_spatial(path, tmp_path):
    scene = cc.SpatialScene.from_file(path)
    cert = same_certificate(tmp_path / "modes.json", lambda p: scene.modes(certificate=p), ["modes", path])
    assert cert is not None
    same_check(cert, path, cc.SpatialScene.from_file, tmp_path)


def test_every_bundled_file_is_covered():
    """A bundled file of a kind without questions here fails: add its questions."""
    covered = set(PLANAR) | set(UCP) | set(ASSEMBLY) | set(MOTION) | set(SPATIAL)
    assert PLANAR and UCP and ASSEMBLY and MOTION and SPATIAL and set(FILES) == covered, [
        p.name for p in set(FILES) - covered
    ]
