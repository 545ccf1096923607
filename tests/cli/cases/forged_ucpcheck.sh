# Sourced by forged_certificates.sh: the checker module's views (queries/check_views.h) make a valid certificate
# INVALID when its readable copy of the evidence is not the checked one; the kind table's refusal; a UCP certificate
# of a quasistatic_scene checked against its scene file. The files stay in $work: the Python parity test
# (tests/python/test_ucp_check_parity.py) checks each with both checkers.
forge uc_cone_accel 's/"acceleration": \[\n  "1"/"acceleration": [\n  "2"/' "$cn"
check 2 'acceleration is not the view of the checked witness' check "$work/uc_cone_accel.json"
forge uc_cone_contacts 's/"c_t": "0"/"c_t": "1"/' "$cn"
check 2 'contacts is not the view of the checked witness' check "$work/uc_cone_contacts.json"
forge uc_st_resting 's/"c_n": "1"/"c_n": "2"/' "$work/st.json"
check 2 'resting.contacts are not the world forces of the checked resting.forces' check "$work/uc_st_resting.json"
forge uc_kind 's/"kind": "stability"/"kind": "stable"/' "$work/st.json"
check 2 'expected a certificate kind: ucp_jammed, ucp_solvable, stability, modes, cone_empty, cone_nonempty, goal_nonempty, assembly_stability, assembly_modes, spatial_modes, spatial_stability, spatial_cone or motion_uniqueness, found "stable"' \
  check "$work/uc_kind.json"
"$cc" ucp "$s/pang1994_dataset3_geometry.json" --certificate "$work/uc_geometry.json" > /dev/null
check 0 'certificate is VALID for' check "$work/uc_geometry.json" --problem "$s/pang1994_dataset3_geometry.json"
check 0 'certificate is VALID for' check "$work/uc_geometry.json" --problem "$s/pang1994_dataset3.json"
check 2 'is about another problem than' check "$work/uc_geometry.json" --problem "$s/pang1994_dataset4_geometry.json"
