# `check --problem` with an assembly (issue 30), sourced by forged_certificates.sh: each assembly certificate kind
# (assembly_stability, assembly_modes, and the ucp_solvable / ucp_jammed of `assembly --ucp`) is VALID against its
# own assembly and INVALID (exit 2) against another one; a UCP certificate that embeds no assembly is about none.

fq=$work/forged_q30
mkdir -p "$fq"
two=$s/assembly_two_boxes.json other=$s/assembly_corbel.json
"$cc" assembly "$two" --certificate "$fq/stability.json" > /dev/null
"$cc" modes "$two" --certificate "$fq/modes.json" > /dev/null
"$cc" assembly "$two" --ucp --certificate "$fq/ucp.json" > /dev/null
"$cc" assembly "$s/assembly_overhang.json" --ucp --certificate "$fq/ucp_jammed.json" > /dev/null
"$cc" ucp "$s/pang1994_dataset1.json" --certificate "$fq/plain_ucp.json" > /dev/null
for kind in stability modes ucp; do
  check 0 "certificate is VALID for $two" check "$fq/$kind.json" --problem "$two"
  check 2 "is about another problem than $other" check "$fq/$kind.json" --problem "$other"
done
check 0 "ucp_jammed certificate is VALID for" check "$fq/ucp_jammed.json" --problem "$s/assembly_overhang.json"
check 2 "its embedded assembly's sha256 is" check "$fq/ucp_jammed.json" --problem "$two"
check 2 '"valid":false' check "$fq/ucp.json" --problem "$other" --json
# a respelt copy of the assembly (reformatted JSON) is the same assembly
python3 -c "import json, sys; json.dump(json.load(open(sys.argv[1])), open(sys.argv[2], 'w'), indent=1)" "$two" "$fq/respelt.json"
check 0 'certificate is VALID for' check "$fq/ucp.json" --problem "$fq/respelt.json"
# a plain UCP certificate is about no assembly; an assembly certificate is not about a UCP problem
check 2 'it embeds no assembly' check "$fq/plain_ucp.json" --problem "$two"
check 2 'is about another problem than' check "$fq/stability.json" --problem "$s/pang1994_dataset1.json"
