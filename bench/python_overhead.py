#!/usr/bin/env python3
"""Per-call cost of the Python module against a CLI subprocess on the same queries (docs/bench.md), and the
batch stability form against single calls. Run by hand, not in CI:

    PYTHONPATH=build/python /usr/bin/python3 bench/python_overhead.py [--cli build/cli/contactcert]
"""

import argparse
import json
import pathlib
import subprocess
import time

import contactcert as cc

ROOT = pathlib.Path(__file__).resolve().parents[1]
SCENES = ROOT / "scenes"


def per_call(f, min_seconds=0.5):
    """Median over 5 rounds of the mean seconds per call of f()."""
    n, rounds = 1, []
    while True:
        t = time.perf_counter()
        for _ in range(n):
            f()
        if time.perf_counter() - t > min_seconds / 5:
            break
        n *= 2
    for _ in range(5):
        t = time.perf_counter()
        for _ in range(n):
            f()
        rounds.append((time.perf_counter() - t) / n)
    return sorted(rounds)[2]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cli", default=str(ROOT / "build" / "cli" / "contactcert"))
    args = ap.parse_args()

    def cli(*a):
        return lambda: subprocess.run([args.cli, *map(str, a), "--json"], capture_output=True, check=True)

    disk7 = cc.Scene.from_file(SCENES / "bt2002_section7_disk.json")
    disk4 = cc.Scene.from_file(SCENES / "bt2002_section4_disk.json")
    ds1 = cc.Ucp.from_file(SCENES / "pang1994_dataset1.json")
    text = disk7._core.stability("1,-2,0", "verified", False, "")[0]
    queries = [
        ("section 7 stability g = (1, -2, 0)", lambda: disk7.stability("1,-2,0"),
         cli("stability", SCENES / "bt2002_section7_disk.json", "--wrench", "1,-2,0")),
        ("section 4 cone, mode na", lambda: disk4.cone("na"),
         cli("cone", SCENES / "bt2002_section4_disk.json", "--mode", "na")),
        ("Data Set 1, ucp complete verified", lambda: ds1.solve(),
         cli("ucp", SCENES / "pang1994_dataset1.json")),
    ]
    print(f"{'query':40s} {'python us':>10s} {'CLI us':>10s} {'ratio':>7s}")
    for name, py, sub in queries:
        p, c = per_call(py), per_call(sub)
        print(f"{name:40s} {p * 1e6:10.1f} {c * 1e6:10.1f} {c / p:7.1f}")
    raw = per_call(lambda: disk7._core.stability("1,-2,0", "verified", False, ""))
    wrap = per_call(lambda: json.loads(text))
    print(f"section 7 stability: _core call {raw * 1e6:.1f} us, json.loads of its result {wrap * 1e6:.1f} us")

    wrenches = [[i % 7 - 3, -5 + i % 3, i % 5 - 2] for i in range(1000)]
    single = per_call(lambda: [disk7.stability(w) for w in wrenches[:100]]) / 100
    disk7.stability_many(wrenches[:1])  # prepares the oracle once
    batch = per_call(lambda: disk7.stability_many(wrenches)) / len(wrenches)
    print(f"stability per wrench on the section 7 disk: single {single * 1e6:.1f} us, batch {batch * 1e6:.1f} us, "
          f"ratio {single / batch:.1f}")


if __name__ == "__main__":
    main()
