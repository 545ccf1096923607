"""design's options are queries::DesignOptions itself: rank and arith texts are parsed by the query layer when set."""

import pytest

import contactcert as cc
from contactcert import _core
from conftest import SCENES, cli_json

PENTAGON = SCENES / "bt2002_fig10_pentagon_insert.json"


def test_rank_and_arith_are_parsed_when_set():
    o = _core.DesignOptions()
    assert o.rank is None and o.arith == "verified" and o.out == "contactcert-design"
    o.rank = "goal-fraction"
    o.arith = "exact"
    assert (o.rank, o.arith) == ("goal-fraction", "exact")
    o.rank = None
    assert o.rank is None
    with pytest.raises(ValueError, match="rank"):
        o.rank = "best"
    with pytest.raises(ValueError, match="arith"):
        o.arith = "fast"


def test_an_explicit_rank_equals_the_cli(tmp_path):
    out = tmp_path / "out"
    want = cli_json("design", PENTAGON, "--candidates", "10", "--stable-under", "0,-1,0", "--insertable", "--rank",
                    "goal-fraction", "--top", "1", "--out", out)
    got = cc.design(cc.Scene.from_file(PENTAGON), 10, stable_under="0,-1,0", insertable=True, rank="goal-fraction",
                    top=1, out=out)
    assert got.to_dict() == want
    assert want["rank"] == "goal-fraction"
