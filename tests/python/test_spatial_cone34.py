"""SpatialScene.modes(svg=...) and SpatialScene.cone(mode, certificate=...) (issue 34): the picture and the
spatial_cone certificate are the bytes the CLI writes (`modes SPATIAL --svg F`, `cone SPATIAL --mode M
--certificate F`), the certificate checks, and to_dict() is the CLI's --json."""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path
from typing import Any

import contactcert

SCENES = Path(__file__).resolve().parents[2] / "scenes"
BOX = SCENES / "spatial_box_on_plane.json"


def same_as_cli(result: Any, key: str, written: Path, *args: str) -> None:
    """The CLI with args, writing `key`'s file beside `written`, wrote the same bytes and printed result's --json
    (but for the file's name); skipped without CONTACTCERT_CLI."""
    exe = os.environ.get("CONTACTCERT_CLI")
    if not exe:
        return
    mine = written.with_name("cli" + written.suffix)
    out = subprocess.run([exe, *args, f"--{key}", str(mine), "--json"], check=True, capture_output=True, text=True)
    assert mine.read_bytes() == written.read_bytes()
    want = json.loads(out.stdout)
    want[key] = str(written)
    assert result.to_dict() == want


def test_modes_svg_is_the_cli_picture(tmp_path: Path) -> None:
    modes = contactcert.SpatialScene.from_file(BOX).modes(svg=tmp_path / "py.svg")
    picture = (tmp_path / "py.svg").read_text()
    assert picture.startswith("<svg") or picture.startswith("<?xml")
    assert modes._repr_svg_() == picture
    assert modes.to_dict()["svg"] == str(tmp_path / "py.svg")
    same_as_cli(modes, "svg", tmp_path / "py.svg", "modes", str(BOX))


def test_modes_without_svg_draw_nothing() -> None:
    modes = contactcert.SpatialScene.from_file(BOX).modes()
    assert modes._repr_svg_() is None and "svg" not in modes.to_dict()


def test_cone_certificate_is_the_cli_certificate_and_checks(tmp_path: Path) -> None:
    cone = contactcert.SpatialScene.from_file(BOX).cone("ffss", certificate=tmp_path / "py.json")
    assert cone.certificate is not None and cone.certificate.kind == "spatial_cone"
    assert cone.certificate.check().valid
    assert contactcert.check(tmp_path / "py.json").valid
    assert cone.to_dict()["certificate"] == str(tmp_path / "py.json")
    same_as_cli(cone, "certificate", tmp_path / "py.json", "cone", str(BOX), "--mode", "ffss")


def test_empty_cone_certificate_checks(tmp_path: Path) -> None:
    cone = contactcert.SpatialScene.from_file(BOX).cone("sAsB", certificate=tmp_path / "e.json")
    assert cone["cone"]["empty"] is True
    assert cone.certificate is not None and cone.certificate.check().valid
