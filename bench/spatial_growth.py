#!/usr/bin/env python3
"""Growth of the spatial contact-mode tree in the contacts k (docs/bench.md, "Contact modes in space").

    bench/spatial_growth.py BUILD-BENCH/bench/spatial_bench BUILD/cli/contactcert [OTHER/contactcert] [--time-limit 60]

Runs bench/spatial_bench (box on a plane and peg in a hole, k = 4, 8, 16, 32: the walk and its certificate text in
process) and prints its counters as a Markdown table, then the exponent of each fitted over k (least squares of
log value on log k, over k = 8 to 32 where the tree is past its start). Then the command line end to end,
`contactcert modes SCENE --json --certificate FILE` on the same scenes (written by `spatial_bench --scenes DIR`),
as the child's CPU seconds (user + sys) and the certificate's size; with OTHER (an older build) its CPU seconds
and the ratio OTHER / ours side by side. A run past --time-limit prints "> LIMIT"; exit 3 with the covered nodes.
"""
import argparse
import json
import math
import os
import resource
import subprocess
import tempfile

KS = [4, 8, 16, 32]


def fit(ks, values):
    """The exponent b of value ~ a k^b, least squares of log value on log k."""
    xs, ys = [math.log(k) for k in ks], [math.log(v) for v in values]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def cli(binary, scene, cert, limit):
    """(child CPU seconds, certificate bytes or None, exit code) of one `modes` run."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = subprocess.run([binary, "modes", scene, "--json", "--certificate", cert, "--time-limit", str(limit)],
                       capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    size = os.path.getsize(cert) if p.returncode == 0 and os.path.exists(cert) else None
    if os.path.exists(cert):
        os.remove(cert)
    return cpu, size, p.returncode


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("bench")
    ap.add_argument("contactcert")
    ap.add_argument("other", nargs="?")
    ap.add_argument("--time-limit", type=float, default=60)
    a = ap.parse_args()
    out = subprocess.run([a.bench, "--benchmark_format=json"], capture_output=True, text=True, check=True).stdout
    rows = {}
    for b in json.loads(out)["benchmarks"]:
        shape, k = b["label"].split(" k=")
        rows[(shape, int(k))] = b
    print("| scene | k | modes | nodes | LPs | certificate bytes | CPU ms (walk + certificate text) |")
    print("|---|---|---|---|---|---|---|")
    for (shape, k), b in sorted(rows.items()):
        print(f"| {shape} | {k} | {b['modes']:.0f} | {b['nodes']:.0f} | {b['lps']:.0f} | {b['cert_bytes']:.0f} | "
              f"{b['cpu_time']:.0f} |")
    print("\nexponent b of value ~ k^b over k = 8, 16, 32:\n")
    print("| scene | modes | nodes | LPs | certificate bytes | CPU |")
    print("|---|---|---|---|---|---|")
    for shape in sorted({s for s, _ in rows}):
        ks = [k for k in KS[1:] if (shape, k) in rows]
        cells = [fit(ks, [rows[(shape, k)][c] for k in ks]) for c in ("modes", "nodes", "lps", "cert_bytes", "cpu_time")]
        print(f"| {shape} | " + " | ".join(f"{c:.2f}" for c in cells) + " |")
    with tempfile.TemporaryDirectory() as d:
        subprocess.run([a.bench, "--scenes", d], check=True)
        head = "| scene | k | CPU s | certificate bytes |" + (" OTHER CPU s | OTHER / ours |" if a.other else "")
        print("\n`contactcert modes SCENE --json --certificate FILE`, end to end:\n\n" + head)
        print("|---" * (head.count("|") - 1) + "|")
        for shape in ("box", "peg"):
            for k in KS:
                scene, cert = f"{d}/{shape}_{k}.json", f"{d}/cert.json"
                cpu, size, rc = cli(a.contactcert, scene, cert, a.time_limit)
                line = f"| {shape} | {k} | {cpu:.2f} | {size if size else 'exit %d' % rc} |"
                if a.other:
                    ocpu, _, orc = cli(a.other, scene, cert, a.time_limit)
                    shown = f"{ocpu:.2f}" if orc == 0 else f"exit {orc} after {ocpu:.2f}"
                    line += f" {shown} | {ocpu / cpu:.1f} |" if orc == 0 else f" {shown} | |"
                print(line)


if __name__ == "__main__":
    main()
