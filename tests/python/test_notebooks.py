"""The notebooks of examples/notebooks run clean (Debian's nbclient and ipykernel), top to bottom, in a kernel of
this interpreter (so they use the contactcert this suite tests), and draw their pictures inline."""

import json
import os
import pathlib
import sys

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")
pytest.importorskip("ipykernel")

import contactcert  # noqa: E402
from conftest import ROOT  # noqa: E402

NOTEBOOKS = sorted((ROOT / "examples" / "notebooks").glob("*.ipynb"))
PICTURES = {"ladder_friction_threshold", "section7_region", "fixture_design_pawl"}  # with an inline SVG


@pytest.fixture(scope="module")
def kernel(tmp_path_factory):
    """A kernelspec running this interpreter with the contactcert under test first on its path (the kernel runs
    in the notebook's folder, where a relative PYTHONPATH would not reach it), found through JUPYTER_PATH."""
    spec = tmp_path_factory.mktemp("jupyter") / "kernels" / "contactcert-test"
    spec.mkdir(parents=True)
    (spec / "kernel.json").write_text(json.dumps({
        "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
        "display_name": "contactcert test", "language": "python",
        "env": {"PYTHONPATH": str(pathlib.Path(contactcert.__file__).resolve().parents[1])}}))
    old = os.environ.get("JUPYTER_PATH")
    os.environ["JUPYTER_PATH"] = str(spec.parents[1])
    yield "contactcert-test"
    if old is None:
        del os.environ["JUPYTER_PATH"]
    else:
        os.environ["JUPYTER_PATH"] = old


def test_there_are_notebooks():
    assert {p.stem for p in NOTEBOOKS} >= PICTURES | {"float_caught_by_exact", "dataset4_jamming"}


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebook_runs_clean(kernel, path):
    nb = nbformat.read(path, as_version=4)
    client = nbclient.NotebookClient(nb, kernel_name=kernel, timeout=300,
                                     resources={"metadata": {"path": str(path.parent)}})
    client.execute()  # raises CellExecutionError on the first failing cell
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])]
    assert not [o for o in outputs if o.get("output_type") == "error"]
    svgs = [o["data"]["image/svg+xml"] for o in outputs if "image/svg+xml" in o.get("data", {})]
    if path.stem in PICTURES:
        assert svgs and all(s.lstrip().startswith("<svg") or s.lstrip().startswith("<?xml") for s in svgs)
