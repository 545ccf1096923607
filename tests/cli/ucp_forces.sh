#!/usr/bin/env bash
# `ucp` on a quasistatic_scene prints each contact's force as a world vector (exact) beside c_n, c_t and its frame:
# on the bundled Data Set scenes and a box with an obstacle, a force- and a velocity-controlled finger (com off the
# origin), a solvable verdict's forces satisfy, exactly: n_i and r_i are the file's as written, t_i = (-n_iy, n_ix),
# f_i = c_n n_i + c_t t_i, torque = r_i x f_i, c_n, c_t are physical.c_n, c_t, the workpiece's equilibrium
# sum_i (f_i, r_i x f_i) + (gravity, com x gravity) = 0 (Pang, Trinkle, Lo, eq. 1), and the text prints the same.
# A problem given by its matrices prints no world vectors and says its frames are its own.
# Usage: ucp_forces.sh CONTACTCERT REPO_DIR WORK_DIR
set -u
cc=$1 repo=$2 work=$3
mkdir -p "$work"
cat > "$work/box.json" << 'JSON'
{ "kind": "quasistatic_scene",
  "workpiece": { "shape": {"type": "polygon", "vertices": [[0, 0], [1, 0], [1, 1], [0, 1]]}, "com": ["1/2", "1/2"] },
  "gravity": [0, -1],
  "contacts": [
    {"point": ["1/2", 0], "normal": [0, 1], "mu": "0.3"},
    {"position": [0, "1/2"], "mu": "1/5", "finger": {"axes": "world", "force": ["3/10", 0]}},
    {"point": [1, "1/2"], "normal": [-2, 0], "mu": "0.5", "finger": {"velocity": ["-0.1", 0]}} ] }
JSON
failures=0 solvable=0
for scene in "$repo"/scenes/pang1994_dataset{1,2,3,4}_geometry.json "$work/box.json"; do
  "$cc" ucp "$scene" --json > "$work/out.json"
  "$cc" ucp "$scene" > "$work/out.txt"
  python3 - "$scene" "$work/out.json" "$work/out.txt" << 'PY' || failures=$((failures + 1))
import json, sys
from fractions import Fraction as F
scene, out, text = json.load(open(sys.argv[1])), json.load(open(sys.argv[2])), open(sys.argv[3]).read()
name = sys.argv[1].split('/')[-1]
if out['status'] != 'solvable':
    ok = 'physical' not in out
    print(('ok: ' if ok else 'WRONG: ') + name + ' ' + out['status'])
    sys.exit(0 if ok else 2)
vec = lambda v: [F(x) for x in v]
cross = lambda a, b: a[0] * b[1] - a[1] * b[0]
p, cs = out['physical'], out['physical']['contacts']
ok = len(cs) == len(scene['contacts']) and 'world coordinates' in text
total = [F(0)] * 3
for i, (c, s) in enumerate(zip(cs, scene['contacts'])):
    r, n, t, f = vec(c['point']), vec(c['normal']), vec(c['tangent']), vec(c['force'])
    cn, ct = F(c['c_n']), F(c['c_t'])
    ok = ok and c['contact'] == i and t == [-n[1], n[0]] and cn == F(p['c_n'][i]) and ct == F(p['c_t'][i])
    if 'normal' in s: ok = ok and n == vec(s['normal']) and r == vec(s['point'])
    ok = ok and f == [cn * n[k] + ct * t[k] for k in range(2)] and F(c['torque']) == cross(r, f)
    total = [total[0] + f[0], total[1] + f[1], total[2] + F(c['torque'])]
    line = 'contact %d at (%s): force (%s), torque %s' % (i, ', '.join(c['point']), ', '.join(c['force']), c['torque'])
    ok = ok and line in text
g = vec(scene.get('gravity', [0, 0]))
com = vec(scene['workpiece']['com'])
ok = ok and total == [-g[0], -g[1], -cross(com, g)]
print(('ok: ' if ok else 'WRONG: ') + name + ' solvable, balance ' + str([str(x) for x in total]))
sys.exit(0 if ok else 1)
PY
  [ $? -eq 0 ] && solvable=$((solvable + 1))
done
# At least one solvable scene: the equilibrium was checked.
[ $solvable -ge 1 ] || { echo "WRONG: no solvable scene"; failures=$((failures + 1)); }
# A problem given by its matrices: no world vectors; the text states the frames are its own.
"$cc" ucp "$repo/scenes/pang1994_dataset1.json" --json > "$work/raw.json"
"$cc" ucp "$repo/scenes/pang1994_dataset1.json" > "$work/raw.txt"
if grep -q '"c_n"' "$work/raw.json" && ! grep -q '"contacts"' "$work/raw.json" && grep -q "own contact frames" "$work/raw.txt" &&
  ! grep -q "world coordinates" "$work/raw.txt"; then
  echo "ok: raw problem states its own frames"
else
  echo "WRONG: raw problem"
  failures=$((failures + 1))
fi
echo "ucp forces: $failures failures"
exit $((failures > 0))
