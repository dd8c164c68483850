# Script tests, run with python3. Each gets the udec binary and the source tree.
set(UDEC_BIN $<TARGET_FILE:udec>)
function(udec_script_test name script label)
  add_test(NAME ${name}
           COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/scripts/${script}
                   ${UDEC_BIN} ${CMAKE_SOURCE_DIR} ${ARGN})
  set_tests_properties(${name} PROPERTIES LABELS "${label}" TIMEOUT 600)
endfunction()

udec_script_test(e2e.interactive e2e_interactive.py e2e)
# libedit at the prompt on a pseudo-terminal (skipped, 77, without libedit)
udec_script_test(e2e.prompt_lineedit prompt_lineedit.py e2e)
set_tests_properties(e2e.prompt_lineedit PROPERTIES SKIP_RETURN_CODE 77)
add_test(NAME unit.labels_cover
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/scripts/labels_cover.py
                 ${CMAKE_CTEST_COMMAND} ${CMAKE_BINARY_DIR})
set_tests_properties(unit.labels_cover PROPERTIES LABELS unit TIMEOUT 120)
udec_script_test(e2e.batch e2e_batch.py e2e)
udec_script_test(examples.check_decks check_decks.py "examples;e2e")
udec_script_test(robustness.fuzz_input fuzz_input.py stability)
udec_script_test(examples.geometry_decks geometry_decks.py "examples;e2e")
udec_script_test(commands.print print_command.py e2e)
udec_script_test(plot.files plot_files.py unit)
udec_script_test(plot.profiles plot_profiles.py e2e)
udec_script_test(commands.not_yet_walk not_yet_walk.py e2e)
# HISTORY SRAT against the statics of a block on a slope (JCONS 2 and 3)
udec_script_test(e2e.history_srat history_srat.py e2e)
udec_script_test(examples.tutorial_mechanics tutorial_mechanics.py "examples;e2e")
udec_script_test(restart.save_restart save_restart.py "restart;e2e")
udec_script_test(mechanics.excavation excavation.py unit)
udec_script_test(stability.zones stability_zones.py stability)
udec_script_test(stability.joint_ends joint_ends.py stability)
# CRACK / SPLIT ends typed to six decimals on an inclined edge or a joint
udec_script_test(e2e.crack_typed_ends crack_typed_ends.py e2e)
udec_script_test(e2e.block_on_plane block_on_plane.py e2e)
# a cut end moved onto a corner within EDGE of its line (no tooth; l3's set-up)
udec_script_test(e2e.cut_tooth cut_tooth.py e2e)
# a TUNNEL side across a block's tip bends through its corner (m5); the sweep tool
udec_script_test(e2e.tunnel_ring_tips tunnel_ring_tips.py e2e)
udec_script_test(e2e.tunnel_coarse_ring tunnel_coarse_ring.py e2e)
# a BOUNDARY STRESS pulling a jointed model: the first CYCLE and the overlap stop say so
udec_script_test(e2e.boundary_tension boundary_tension.py e2e)
udec_script_test(e2e.scan_skip scan_skip.py e2e)
udec_script_test(stability.insitu_junctions insitu_junctions.py stability)
udec_script_test(stability.facing_corners facing_corners.py stability)
udec_script_test(stability.insitu_wedge insitu_wedge.py stability)
udec_script_test(stability.insitu_rounded_vertex insitu_rounded_vertex.py stability)
udec_script_test(stability.insitu_mixed_rigid insitu_mixed_rigid.py stability)
udec_script_test(e2e.gen_rest gen_rest.py e2e)
udec_script_test(e2e.gen_quad_straight gen_quad_straight.py e2e)
udec_script_test(e2e.contact_normal_disp contact_normal_disp.py e2e)
udec_script_test(stability.auto_damping_held auto_damping_held.py stability)
udec_script_test(stability.stress_held_turn stress_held_turn.py stability)
# SDEF strain modes take FRACTION fz: a needle of SDEF blocks comes to rest
udec_script_test(stability.sdef_needle sdef_needle.py stability)
udec_script_test(stability.sdef_insitu_rest sdef_insitu_rest.py stability)
udec_script_test(stability.sdef_tower sdef_tower.py stability)
udec_script_test(e2e.fix_zoned fix_zoned.py e2e)
udec_script_test(stability.boundary_stress stability_boundary_stress.py stability)
# a zoned jointed model loaded from zero by BOUNDARY STRESS alone comes to rest (joint mouth)
udec_script_test(stability.bstress_joint_mouth bstress_joint_mouth.py stability)
udec_script_test(e2e.be_far_field be_far_field.py e2e)
udec_script_test(mechanics.viscous viscous_boundary.py unit)
udec_script_test(stability.viscous viscous_boundary.py stability stiff)
udec_script_test(verification.free_field free_field.py verification)
udec_script_test(verification.sdef_blocks sdef_blocks.py verification)
udec_script_test(verification.reinforcement reinforcement.py verification)
udec_script_test(verification.newmark_sliding newmark_sliding.py verification)
# blocks on joints against closed forms: sliding on a slope (friction,
# cohesion, JCONS 1, 2 and 5, rigid and zoned), tension cut-off, dilation ridden up and kept, an open
# dilatant joint carrying nothing
udec_script_test(verification.closed_forms closed_forms.py verification)
# zoned rock, waves, damping, joint flow and heat against closed forms: Kirsch
# (biaxial; stress boundary and BE far field), a P wave across an impedance
# contrast, Rayleigh damping, joint pressure diffusion (erfc), joints in
# series, a convective surface (erfc), thermal stress, joint stiffnesses,
# Salencon's wall displacement
udec_script_test(verification.closed_forms_fields closed_forms_fields.py verification)
# round 2: Kirsch under BOUNDARY STRESS alone, the cubic law with the
# mechanical aperture, a Bingham grout's penetration length, a heated block
# held on all sides, a column's free vibration
udec_script_test(verification.closed_forms_hm closed_forms_hm.py verification)
# Salencon's tunnel wall for phi = 40 degrees and with dilation (psi = 20)
udec_script_test(verification.closed_forms_salencon closed_forms_salencon.py verification)
# round 3: a column of rigid blocks (statics, the first mode of the spring-mass
# chain), Lame's thick cylinder, two parallel joints, a joint network with dead
# ends, a cantilever under its own weight (two zone sizes), cohesion and friction
# both sides of the limit under tilted gravity
udec_script_test(verification.closed_forms_r3 closed_forms_r3.py verification)
# round 4: uplift (water pressure in a joint, both sides of the effective-stress
# limit), a heated block between spring joints, an S wave across a joint of
# shear stiffness ks at 50 and 200 Hz, a single plane of weakness (Jaeger), a
# column of zoned blocks on joints under gravity, a block lifted by joint water
# pressure and held by a grouted cable, the Brazilian disk (Hondros)
udec_script_test(verification.closed_forms_r4 closed_forms_r4.py verification)
udec_script_test(examples.application_d application_d.py "examples;e2e;verification")
# the decks of the guide's physics pages (docs/guide/deformable.md .. structures.md)
foreach(deck deformable dynamics flow heat structures)
  udec_script_test(examples.guide_${deck} guide_decks.py "examples;e2e" ${deck})
endforeach()
udec_script_test(stability.jcons3_long_shear jcons3_shear.py stability)
udec_script_test(stability.boundary_closure_random boundary_closure_random.py stability 150)
udec_script_test(e2e.boundary_openings boundary_openings.py e2e)
udec_script_test(e2e.property_units property_units.py e2e)
udec_script_test(e2e.units_weight units_weight.py e2e)
udec_script_test(stability.tunnel_key_cut tunnel_key_cut.py stability)
# a joint grazing the TUNNEL ring (the lead's random deck, seed 234): no refused cut, no needle zone
udec_script_test(e2e.tunnel_grazing tunnel_grazing.py e2e)
# openings drawn by ARC: two half turns, a CRACK square, a ring across or grazed by a joint
udec_script_test(e2e.arc_openings arc_openings.py e2e)
# campaign round 4 (tools/physics_campaign.py): glued joints = Kirsch, a roof wedge's friction limit
udec_script_test(verification.tunnel_glued_kirsch tunnel_glued_kirsch.py verification)
udec_script_test(verification.roof_wedge_friction roof_wedge_friction.py verification)
# campaign round 5 (tools/support_campaign.py): a roof wedge on bolts (statics, F = k d, yield)
udec_script_test(verification.bolted_wedge bolted_wedge.py verification)
# ... and a tunnel under gravity, water and overburden, bolted in stages, saved and restarted
udec_script_test(stability.staged_gravity_tunnel staged_gravity_tunnel.py stability)
udec_script_test(stability.needle_round needle_round.py stability)
# the needle's root under a rounded corner while a tunnel is excavated below
udec_script_test(stability.needle_excavation needle_excavation.py stability)
udec_script_test(stability.open_joint_shear open_joint_shear.py stability)
# the mixed discretization's stiffness is symmetric (one-way leftovers made
# the guide tunnel's corner gridpoint rattle; Maxwell-Betti reciprocity)
udec_script_test(stability.mixed_zones_reciprocal mixed_zones_reciprocal.py stability)
# Application C's zones, undamped from rest, do no work (the one-way leftovers
# pumped a 54 Hz motion there that DAMP AUTO held only by overdamping the rock)
udec_script_test(stability.mixed_zones_undamped mixed_zones_undamped.py stability)
# a TUNNEL ring with its plug starts in equilibrium under INSITU + BOUND STRESS
udec_script_test(stability.tunnel_ring_insitu tunnel_ring_insitu.py stability)
# rigid blocks cut by crossing joint sets stay at rest under INSITU + the same
# BOUND STRESS (the contact forces of each joint on its chord)
udec_script_test(stability.insitu_rigid_rest insitu_rigid_rest.py stability)
# random jointed tunnels as new users write them (tools/jointed_tunnel_fuzz.py, quick
# seeds): at rest before the excavation, balanced after, reactions, no stop
udec_script_test(stability.jointed_tunnel_fuzz jointed_tunnel_fuzz.py stability)
# ... and its unbalanced class split (round 4): still settling (checked with SOLVE's
# default limit), a loose wedge, a field beyond a joint set's friction
udec_script_test(stability.jointed_tunnel_fuzz_classes jointed_tunnel_fuzz_classes.py stability)
# ... and round 5: a joint bent at a corner keeps its contact lengths at the first CYCLE,
# INSITU's field written to round-off, rollers without a shear, openings near the edge and
# a horseshoe of CRACK lines
udec_script_test(stability.jointed_tunnel_fuzz5 jointed_tunnel_fuzz5.py stability)
# a static load given at once under DAMP AUTO (LOAD, BOUND YLOAD) reaches its static
# answer without the overshoot breaking a joint below its tensile strength
udec_script_test(stability.sudden_load sudden_load.py stability)
# ... and on zoned models (a column, a quarter tunnel, a zoned jointed tunnel): the probe of
# the driven mode's frequency after a load change keeps the overshoot below its bound
udec_script_test(stability.zoned_sudden_load zoned_sudden_load.py stability)
# INSITU notes the contacts whose shear the joints cannot hold
udec_script_test(e2e.insitu_strength_note insitu_strength_note.py e2e)
udec_script_test(e2e.fluid_closed_note fluid_closed_note.py e2e)
udec_script_test(e2e.fluid_fixed_step fluid_fixed_step.py e2e)
udec_script_test(e2e.boundary_stress_corner boundary_stress_corner.py e2e)
udec_script_test(e2e.boundary_range_short boundary_range_short.py e2e)
udec_script_test(e2e.file_case_prompt file_case_prompt.py e2e)
# a fractured JCONS 5 joint stays fractured when its blocks part and touch again
udec_script_test(e2e.fracture_recontact fracture_recontact.py e2e)
# the tunnel scenes whose wall loads leaked before the boundary-walk fixes
# (a notch narrowing to a closed tip; a wall along a joint between T-junctions)
udec_script_test(stability.boundary_closure_tunnels boundary_closure_random.py stability 200 1
                 46,83,107,134,171,193)

# Verification problems of the manual (verification/<case>/check.py): each
# runs the manual's deck(s) and compares with the published numbers.
function(udec_verification name folder)
  add_test(NAME verification.${name}
           COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/verification/${folder}/check.py
                   ${UDEC_BIN} ${CMAKE_SOURCE_DIR} ${ARGN})
  set_tests_properties(verification.${name} PROPERTIES LABELS "verification" TIMEOUT 1500)
endfunction()
udec_verification(A A)
udec_verification(B B)
udec_verification(E E)
udec_verification(D D)
udec_verification(C C)
# verification C's refinement study (crack tips fixed, quasi-static drop): converges
add_test(NAME verification.C_refinement
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/verification/C/refine.py ${UDEC_BIN})
set_tests_properties(verification.C_refinement PROPERTIES LABELS "verification" TIMEOUT 1500)
udec_verification(F F)
udec_verification(thermal1 thermal1)
udec_verification(thermal2 thermal2)
udec_verification(thermal3 thermal3)
udec_verification(thermal4 thermal4)
udec_verification(thermal5 thermal5)
add_test(NAME verification.appF
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/examples/application/F/check.py ${UDEC_BIN})
set_tests_properties(verification.appF PROPERTIES LABELS "verification" TIMEOUT 1500)
add_test(NAME verification.appA
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/examples/application/A/check.py ${UDEC_BIN})
set_tests_properties(verification.appA PROPERTIES LABELS "verification" TIMEOUT 1500)
add_test(NAME verification.appE
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/examples/application/E/check.py ${UDEC_BIN})
set_tests_properties(verification.appE PROPERTIES LABELS "verification" TIMEOUT 1500)
add_test(NAME verification.appC
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/examples/application/C/check.py ${UDEC_BIN})
set_tests_properties(verification.appC PROPERTIES LABELS "verification" TIMEOUT 1500)
udec_script_test(restart.zoned_output zoned_output_restart.py "restart;e2e")
udec_script_test(e2e.output_probe output_probe.py e2e)
udec_script_test(e2e.probe_zone_decks probe_zone_decks.py e2e)
udec_script_test(e2e.probe_boundary_decks probe_boundary_decks.py e2e)
# new-user decks for fluid, free field, structures, SDEF (session 34's defects)
udec_script_test(e2e.probe_physics_decks probe_physics_decks.py e2e)
udec_script_test(commands.debts command_debts.py e2e)
udec_script_test(e2e.probe_rigid_decks probe_rigid_decks.py e2e)
udec_script_test(e2e.boundary_held_loads boundary_held_loads.py e2e)
udec_script_test(e2e.boundary_rigid_reactions boundary_rigid_reactions.py e2e)
udec_script_test(verification.probe_plastic_decks probe_plastic_decks.py verification)
udec_script_test(fluid.closed_forms fluid_flow.py unit)
udec_script_test(fluid.grouting_G fluid_grouting.py verification)
udec_script_test(e2e.addresses_1989 addresses_1989.py e2e)
foreach(n 2 3)
  foreach(order sets-first tunnel-first)
    udec_script_test(stability.tunnel_${n}_sets_${order} stability_tunnel_jointed.py stability ${n} ${order})
  endforeach()
endforeach()
udec_script_test(examples.geometry_scenes geometry_scenes.py "examples;e2e")
add_test(NAME examples.tunnel_jointed
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/examples/tunnel_jointed/check.py ${UDEC_BIN})
set_tests_properties(examples.tunnel_jointed PROPERTIES LABELS "examples;e2e" TIMEOUT 900)
# Issue 20: faults found by fuzzing (each deck crashed, hung or lost a file),
# and Ctrl-C / SIGTERM ending a CYCLE instead of the program.
udec_script_test(robustness.faults faults.py stability ${CMAKE_BUILD_TYPE})
udec_script_test(e2e.interrupt interrupt.py e2e)
udec_script_test(e2e.interrupt_commands interrupt_commands.py e2e)
# The deck fuzzer's short run (tests/fuzz/fuzz.py, 2,000 variants): no crash
# and no hang. In the Debug build (-fcheck=all, FP traps, the sanitizers of
# UDEC_SANITIZE) the first 400 variants of the same run: all 2,000 would take
# about 15 minutes there. AddressSanitizer reserves terabytes of address space,
# so no address-space limit under it (--memory 0).
if(CMAKE_BUILD_TYPE STREQUAL "Release")
  add_test(NAME robustness.fuzz_decks
           COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/tests/fuzz/fuzz.py --udec ${UDEC_BIN}
                   --source ${CMAKE_SOURCE_DIR} --count 2000 --seed 20 --jobs 2)
  set_tests_properties(robustness.fuzz_decks PROPERTIES LABELS "stability;fuzz" TIMEOUT 900)
elseif(CMAKE_BUILD_TYPE STREQUAL "Debug")
  if(UDEC_SANITIZE)
    set(fuzz_memory 0)
  else()
    set(fuzz_memory 2048)
  endif()
  add_test(NAME robustness.fuzz_decks
           COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/tests/fuzz/fuzz.py --udec ${UDEC_BIN}
                   --source ${CMAKE_SOURCE_DIR} --count 400 --seed 20 --jobs 2 --timeout 60
                   --memory ${fuzz_memory})
  set_tests_properties(robustness.fuzz_decks PROPERTIES LABELS "stability;fuzz" TIMEOUT 900)
endif()
# udec under valgrind memcheck (issue 20): the tutorial, verification B and
# application A1 with no invalid access and no definite leak of ours. Release
# only (the Debug build carries AddressSanitizer, which valgrind cannot run);
# skipped with a message when valgrind is missing.
if(CMAKE_BUILD_TYPE STREQUAL "Release")
  udec_script_test(robustness.valgrind valgrind_decks.py "stability;valgrind")
  set_tests_properties(robustness.valgrind PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 1500)
endif()
udec_script_test(e2e.gen_needle_warning gen_needle_warning.py e2e)
udec_script_test(stability.still_joints_not_slipping still_joints_not_slipping.py stability)
udec_script_test(plot.temperature plot_temperature.py unit)
# Packaging (issue 24): cmake --install into a temporary prefix puts the program,
# the manual page, the command reference and the licence in place.
add_test(NAME e2e.install
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/scripts/install_prefix.py
                 ${UDEC_BIN} ${CMAKE_SOURCE_DIR} ${CMAKE_COMMAND} ${CMAKE_BINARY_DIR})
set_tests_properties(e2e.install PROPERTIES LABELS e2e TIMEOUT 120)
# SOLVE (issue 24, an extension): balances, reports the CYCLES limit, stops on Ctrl-C.
udec_script_test(e2e.solve solve.py e2e)
udec_script_test(e2e.solve_mscale_note solve_mscale_note.py e2e)
# The progress line on a terminal (a pseudo-terminal) and unchanged batch output (issue 24).
udec_script_test(e2e.progress_tty progress_tty.py e2e)
# EXPORT name.vtu and EXPORT HISTORY name.csv (issue 24), read back with xml.etree and csv.
udec_script_test(e2e.export export_files.py e2e)
# The user's guide names files, tests and pages that exist; no absolute path of
# a build machine in the repository (issue 24).
add_test(NAME unit.guide_current
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/scripts/guide_current.py
                 ${CMAKE_CTEST_COMMAND} ${CMAKE_BINARY_DIR} ${CMAKE_SOURCE_DIR})
set_tests_properties(unit.guide_current PROPERTIES LABELS unit TIMEOUT 120)
# A decaying source plus a TADD pulse (TABLE) against the superposition closed form
# (verification/thermal6/check.py states the reference and the 2 % tolerance).
udec_verification(thermal6 thermal6)
# Same bits at 1 and 2 OpenMP threads: histories, .vtu and saved model (issue 23)
udec_script_test(stability.threads_identical threads_identical.py stability)
# BOUNDARY STRESS given on points that carry one adds, and the note says so
udec_script_test(e2e.boundary_stress_twice boundary_stress_twice.py e2e)
# ARC of a full turn inside one block is keyed as TUNNEL's ring and cuts the opening
udec_script_test(e2e.arc_ring arc_ring.py e2e)
# Contact Overlap Too Great names the contact's closure, stress and JKN x OVTOL
udec_script_test(e2e.overlap_cause overlap_cause.py e2e)
# BOUNDARY STRESS alone on unloaded soft joints: the stop names the step load, INSITU and its bound
udec_script_test(e2e.overlap_step_load overlap_step_load.py e2e)
# a joint crossing's blunt corners overlap by the closure of two joints: each contact's tolerance
# from its rounded corners (up to 2 ROUND); the joints and real interpenetration still stop
udec_script_test(stability.xcrossing_overlap xcrossing_overlap.py stability)
# joints closing elastically past OVTOL run on within their contacts' tolerance (statics hold);
# SET OVTOL is the user's limit; soft joints still stop (the new user's tunnel of session 39)
udec_script_test(stability.overlap_tolerance overlap_tolerance.py stability)
# a model held in one direction only (XVEL rollers, no base) gets the net-force note for the other
udec_script_test(e2e.held_one_direction held_one_direction.py e2e)
# DELETE of a block spanning the whole model notes that the rest is cut in two
udec_script_test(e2e.delete_through delete_through.py e2e)
# reversed range limits and coincident cut points refused (manual Section 4.1)
udec_script_test(e2e.range_limits range_limits.py e2e)
udec_script_test(verification.local_damping local_damping.py verification)
# Campaign round 7's decks (zoned blocks, structures, water, heat) against
# closed forms (tests/scripts/camp7_decks.py states each reference).
udec_script_test(e2e.camp7_decks camp7_decks.py e2e)
# a liner round a circular tunnel, hydrostatic field: uniform thrust and the
# lined tunnel's closed form (tests/scripts/liner_hydrostatic.py states both)
udec_script_test(verification.liner_hydrostatic liner_hydrostatic.py verification)
# Campaign round 8's decks (a second BLOCK's remedy, a direct shear test under
# a boundary stress; tests/scripts/camp8_decks.py states each reference).
udec_script_test(e2e.camp8_decks camp8_decks.py e2e)
# cuts that would take away an earlier BOUNDARY's conditions are refused
udec_script_test(e2e.cut_after_boundary cut_after_boundary.py e2e)
# Campaign round 9's decks (dynamic, thermal, joint flow, structures; the
# free-field base note, the TFIX-everywhere RUN message, the RUN AGE note;
# tests/scripts/camp9_decks.py states each reference).
udec_script_test(e2e.camp9_decks camp9_decks.py e2e)
# Campaign round 10's decks (a tunnel study: BOUND STRESS 0 0 0 on a loaded
# boundary, CRACK inside a TUNNEL ring, GEN AU; tests/scripts/camp10_decks.py
# states each reference).
udec_script_test(e2e.camp10_decks camp10_decks.py e2e)
# BLOCK / JREGION corners given anticlockwise are taken in reverse order
# with a note (tests/scripts/corner_order.py)
udec_script_test(e2e.corner_order corner_order.py e2e)
# Campaign round 11's decks (one tunnel study written many ways: INSITU's
# note on joints in tension, symmetry, weight, rest, XGRAD / YGRAD loads, a
# session with typos; tests/scripts/camp11_decks.py states each reference).
udec_script_test(e2e.camp11_decks camp11_decks.py e2e)
# Campaign round 12's decks (a tunnel in crossing joint sets held by boundary
# stresses, with new users' mistakes: INSITU unheld by any boundary, stiff
# joints on soft zones, a very fine GENERATE, mirror symmetry, abbreviations,
# a session with typos; tests/scripts/camp12_decks.py states each reference).
udec_script_test(e2e.camp12_decks camp12_decks.py e2e)
