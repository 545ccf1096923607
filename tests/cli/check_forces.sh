#!/usr/bin/env bash
# `check`'s view of a stability or wrench cone certificate: the witness's contact forces as world vectors,
# recomputed from the checked raw forces, in --json and text. On four scenes (resting and moving witnesses): at rest
# sum f_i + (g_x, g_y) = 0 and sum torque_i + g_tau = 0 exactly, a moving witness's forces plus (g_x, g_y) give its linear acceleration
# (mass 1), f_i = c_n n_i + c_t t_i, and the certificate file's readable "contacts" are exactly check's. A
# certificate whose readable contacts were altered is INVALID (exit 2).
# Usage: check_forces.sh CONTACTCERT REPO_DIR WORK_DIR
set -u
cc=$1 repo=$2 work=$3
s=$repo/scenes
mkdir -p "$work"
failures=0
for spec in section7_disk:1,-2,0 section4_disk:0,-1,1/3 fig4c_peg_lra:1/2,-1,0 fig10_pentagon_insert:31/100,-1,0; do
  scene=$s/bt2002_${spec%%:*}.json g=${spec##*:}
  "$cc" stability "$scene" --wrench "$g" --certificate "$work/cert.json" > /dev/null || { echo "FAILED: stability $spec"; failures=$((failures + 1)); continue; }
  "$cc" check "$work/cert.json" --json > "$work/check.json"
  "$cc" check "$work/cert.json" > "$work/check.txt"
  python3 - "$work/cert.json" "$work/check.json" "$work/check.txt" "$spec" << 'PY' || failures=$((failures + 1))
import json, sys
from fractions import Fraction as F
cert, out, text, spec = json.load(open(sys.argv[1])), json.load(open(sys.argv[2])), open(sys.argv[3]).read(), sys.argv[4]
vec = lambda v: [F(x) for x in v]
g = vec(out['wrench'])
ok = out['valid'] and 'world coordinates' in text
def sums(contacts):
    global ok
    for c in contacts:
        n, t, f = vec(c['normal']), vec(c['tangent']), vec(c['force'])
        ok = ok and f == [F(c['c_n']) * n[k] + F(c['c_t']) * t[k] for k in range(2)]
    return [sum(F(c['force'][k]) for c in contacts) for k in range(2)] + [sum(F(c['torque']) for c in contacts)]
if 'resting_contacts' in out:
    s = sums(out['resting_contacts'])
    ok = ok and all(s[k] + g[k] == 0 for k in range(3)) and out['resting_contacts'] == cert['resting']['contacts']
if 'moving' in out:
    s, a = sums(out['moving']['contacts']), vec(out['moving']['acceleration'])
    ok = ok and all(s[k] + g[k] == a[k] for k in range(2)) and out['moving']['contacts'] == cert['moving']['contacts']
print(('ok: ' if ok else 'WRONG: ') + spec + ' ' + out.get('reason', ''))
sys.exit(0 if ok else 1)
PY
done
# A wrench cone witness (cone --certificate): the contact forces its z applies, as world vectors, with
# sum f_i + (g_x, g_y) = (a_x, a_y) and sum torque_i + g_tau = (I/m) a_theta exactly (eq. 4 per unit mass), the same in
# `cone --json`, the certificate file and `check --json` (on modes whose witness has a non-zero contact force).
for spec in section7_disk:sl section7_disk:sn fig4b_nnn:rsr fig10_pentagon_insert:rsr fig10_pentagon_insert:sll; do
  scene=$s/bt2002_${spec%%:*}.json mode=${spec##*:}
  "$cc" cone "$scene" --mode "$mode" --certificate "$work/cone.json" --json > "$work/cone_out.json" || { echo "FAILED: cone $spec"; failures=$((failures + 1)); continue; }
  "$cc" cone "$scene" --mode "$mode" --certificate "$work/cone.json" > "$work/cone_out.txt"
  "$cc" check "$work/cone.json" --json > "$work/check.json"
  "$cc" check "$work/cone.json" > "$work/check.txt"
  python3 - "$work/cone.json" "$work/cone_out.json" "$work/check.json" "$work/cone_out.txt" "$work/check.txt" "$spec" << 'PY' || failures=$((failures + 1))
import json, sys
from fractions import Fraction as F
cert, cone, out = (json.load(open(sys.argv[k])) for k in (1, 2, 3))
texts, spec = [open(sys.argv[k]).read() for k in (4, 5)], sys.argv[6]
vec = lambda v: [F(x) for x in v]
w = out['witness']
g, a, c = vec(w['wrench']), vec(w['acceleration']), w['contacts']
ok = out['valid'] and w == cone['witness'] and cert['contacts'] == c and cert['acceleration'] == w['acceleration']
ok = ok and vec(cert['wrench']) == g and all('world coordinates' in t and 'c_n = ' in t for t in texts)
for x in c:
    n, t, f = vec(x['normal']), vec(x['tangent']), vec(x['force'])
    ok = ok and f == [F(x['c_n']) * n[k] + F(x['c_t']) * t[k] for k in range(2)]
s = [sum(F(x['force'][k]) for x in c) for k in range(2)] + [sum(F(x['torque']) for x in c)]
m = [1, 1, F(w['inertia_per_mass'])]
ok = ok and all(s[k] + g[k] == m[k] * a[k] for k in range(3)) and any(F(x['c_n']) != 0 for x in c)
print(('ok: ' if ok else 'WRONG: ') + 'cone ' + spec + ' ' + out.get('reason', ''))
sys.exit(0 if ok else 1)
PY
done
# Altered readable contacts: INVALID.
"$cc" stability "$s/bt2002_section7_disk.json" --wrench 1,-2,0 --certificate "$work/forged.json" > /dev/null
python3 -c "import json,sys; c=json.load(open(sys.argv[1])); c['resting']['contacts'][0]['force'][0]='7'; json.dump(c,open(sys.argv[1],'w'))" "$work/forged.json"
"$cc" check "$work/forged.json" > "$work/forged.txt"
rc=$?
if [ $rc -eq 2 ] && grep -q "INVALID" "$work/forged.txt"; then echo "ok: altered contacts INVALID"; else echo "WRONG: altered contacts (exit $rc)"; failures=$((failures + 1)); fi
"$cc" cone "$s/bt2002_section4_disk.json" --mode na --certificate "$work/cone_forged.json" > /dev/null
python3 -c "import json,sys; c=json.load(open(sys.argv[1])); c['acceleration'][0]='7'; json.dump(c,open(sys.argv[1],'w'))" "$work/cone_forged.json"
"$cc" check "$work/cone_forged.json" > "$work/forged.txt"
rc=$?
if [ $rc -eq 2 ] && grep -q "acceleration is not the view" "$work/forged.txt"; then echo "ok: altered cone witness INVALID"; else echo "WRONG: altered cone witness (exit $rc)"; failures=$((failures + 1)); fi
echo "check forces: $failures failures"
exit $((failures > 0))
