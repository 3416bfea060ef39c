"""Seed A's rows of the reproduction table (Liu, Liu & Hu, Sensors 2021, 21,
309): every result figure (6, 8, 10, 11, 13, 14, 15) and every table whose
parameters the model uses (1, 2, 3). Figs. 1-5, 7, 9 and 12 are drawings.
The numbers in ``ours`` are pinned by the test each row names."""

from __future__ import annotations

from .reproduction import Row

_T = "tests/test_reproduction_seed_a.py::"

ROWS: tuple[Row, ...] = (
    Row(
        seed="A",
        item="Table 1",
        paper="parameters of the 6208 deep-groove ball bearing",
        figure="seed_a_bearing/seed_a_table1_bearing",
        quoted="Z = 9, D = 12 mm, bore 40 mm, OD 80 mm, groove radii 6.24 / 6.36 mm, "
        "a0 = 14.8351 deg, Pd = 0.04 mm, dm = 60 mm, expansion 1.36e-7 1/K",
        ours="the same geometry; a0 = 14.8351 deg computed from Pd; expansion 1.36e-5 1/K in "
        "the seed A bearing model (the 6208 preset keeps AISI 52100's 1.25e-5 1/K)",
        status="differs",
        reason="typo in the paper: 1.36e-7 1/K is a hundred times too small for any bearing "
        "steel (about 1.2e-5 1/K). Its nearer reading, 1.36e-5 1/K, is taken as the paper's "
        "value: the fitted claims in words cannot tell it from 52100's 1.25e-5 (on the housing "
        "they choose, both meet the same 23 of 27 fitted claims and miss the other four by "
        "amounts within one reading precision of each other), so the choice falls to the "
        "paper's own figure. Every other entry is reproduced, the contact angle from the "
        "clearance to 4 digits",
        test=_T + "test_table1_bearing_parameters",
    ),
    Row(
        seed="A",
        item="Table 2",
        paper="thermal resistances of the bearing's network (7 nodes, oil-air and air)",
        figure="seed_a_thermal/seed_a_table2_thermal_network",
        quoted="conduction and convection formulas only: no dimensions, no coefficients, no values",
        ours="the same 7 nodes and 2 boundaries solved at 6500 rpm, 100 N m, oil jet, on the "
        "housing the claims chose: 157.4 W in (16.5 W of it ball drag), 157.4 W out (oil-air "
        "96.9 W, air 60.4 W), nodes 32.1-43.3 C",
        status="differs",
        reason="assumption: the paper gives the formulas without the network's dimensions "
        "and convection coefficients, so thermobear's resistances come from stated "
        "dimensions (shaft 40 mm, housing 120 mm; Physics, data notes), not from the paper; "
        "the network's heat balance is what is tested. Of what the paper leaves out, the "
        "housing material and its convection to air are chosen by its fitted claims in words "
        "(Figs. 8, 10): cast iron with 10 times the bare cylinder's convection, the top of "
        "that input's range, meets 23 of 27, the default aluminium housing 19. The paper "
        "states an oil jet at the end cover but no flow: 500 cm^3/min is assumed, and the "
        "drag of the balls in the oil it puts in the cavity is a term the paper leaves out "
        "(without it: 142.3 W, nodes 31.6-41.9 C)",
        test=_T + "test_table2_network_balances_its_heat",
    ),
    Row(
        seed="A",
        item="Table 3",
        paper="parameters of the first gear pair",
        figure="seed_a_gear/seed_a_table3_gear_pair",
        quoted="z = 29/78, m_n = 1.537 mm, alpha_n = 16.5 deg, b = 33 mm, beta = 31.2 deg, "
        "E = 20,600 MPa, density 7.8e9 t/mm^3, masses 1.201/3.1 kg, "
        "inertias 0.1152/1.6 t mm^2",
        ours="the same geometry, masses and inertias; E = 206,000 MPa, density 7.8e-9 t/mm^3",
        status="differs",
        reason="typos in the paper: a modulus of 20,600 MPa and a density of 7.8e9 t/mm^3 "
        "are not steel (206,000 MPa, 7.8e-9 t/mm^3 = 7800 kg/m^3); the preset reports "
        "both corrections (GearPair.typo_warnings)",
        test=_T + "test_table3_gear_pair",
    ),
    Row(
        seed="A",
        item="Fig. 6",
        paper="friction heat against speed and axial preload, (a) no load, (b) 100 N m",
        figure="seed_a_thermal/seed_a_fig6b_heat_loaded",
        quoted="heat rises with speed at every preload and with preload at every speed; "
        "no values in the text",
        ours="rises with speed and with preload at every point of both panels; the four "
        "claims, held out of the housing choice, are met (no load, 300 N: 5.4 times the heat "
        "from 7250 to 22,500 rpm; 100 N m: 3.3 times from 6500 to 16,500 rpm)",
        status="reproduced",
        reason="",
        test=_T + "test_fig6_heat_rises_with_speed_and_preload",
    ),
    Row(
        seed="A",
        item="Fig. 8",
        paper="node temperatures against (a) speed, no load, (b) axial load, (c) radial load",
        figure="seed_a_thermal/seed_a_fig8a_temperatures_vs_speed",
        quoted="every node rises almost linearly with speed; axial load heats far more than "
        "radial load; ball hottest, housing coolest; inner ring above outer ring",
        ours="every node rises with speed, almost linearly (ball 35.6 -> 57.9 C, 7250 -> "
        "22,500 rpm, the second half 3 % more than the first); ball rise 6.8 K over the "
        "axial load against 0.7 K over the radial; housing the coolest node, inner ring above "
        "outer ring, each ring's contact node within 1.4 K of its raceway (16 of the 18 "
        "Fig. 8 claims met); the inner raceway is 0.3-0.7 K above the ball without load and "
        "1.2 K under the full load",
        status="differs",
        reason="assumption: which of ball and inner raceway is hottest depends on the oil-air "
        "film on the balls (R_b-og) against the inner ring's path through the shaft, whose "
        "coefficients and dimensions the paper does not give (Table 2 has no values); none of "
        "the 30 housing options the claims chose among puts the ball above the inner raceway "
        "under load, and the cool housing they chose drops it below at no load too (by 0.7 K "
        "at 22,500 rpm). Every other trend and ordering of Fig. 8 is reproduced. Assumption: "
        "the oil jet's flow (500 cm^3/min; the paper gives none); its ball drag, 20 W at "
        "7250 rpm and 212 W at 22,500 rpm, grows about as n^2 and straightens the curve "
        "(without it: ball 34.1 -> 48.6 C, the second half 12 % less)",
        test=_T + "test_fig8_node_temperatures",
    ),
    Row(
        seed="A",
        item="Fig. 10",
        paper="(a) axial and (b) radial deformation against speed: under load, centrifugal, "
        "thermal and combined (u_a-all, u_r-all), 100 N m",
        figure="seed_a_thermal/seed_a_fig10_deformations",
        quoted="axial thermal part far below the axial load part; radial thermal part close "
        "to the radial load part and above the centrifugal part; thermal and combined "
        "parts grow with speed",
        ours="radial: thermal +2.8 -> +6.1 µm (the clearance closes), under load 4.3 µm, "
        "centrifugal 0.2 -> 1.2 µm, combined 7.3 -> 11.6 µm; axial: thermal +0.6 -> +0.2 µm "
        "against 207 -> 196 µm under load, so the combined part falls (7 of the 9 Fig. 10 "
        "claims met); the default aluminium housing gives -3.7 -> -7.4 µm radially (opens) "
        "and an axial part under load growing 233 -> 248 µm",
        status="differs",
        reason="physical argument: in thermobear's model the radial and the axial claims "
        "cannot all hold. The radial ones need the clearance to close with speed, which it "
        "does on the housing the claims chose (seed A names no housing material); but a "
        "closing clearance lowers the free contact angle and takes axial play out, so at a "
        "fixed axial force the axial deformation under load falls with speed (214 -> 210 µm "
        "already from the centrifugal ring expansion alone, 207 -> 196 µm with the thermal "
        "closing) and the combined axial part, which the paper says grows, falls by 12 µm. "
        "Only a housing that opens the clearance (aluminium) makes it grow, and that one "
        "misses the radial claims. The axial thermal part stays negligible (under 1 µm: on "
        "a cool housing the housing and shaft terms of A-37 nearly cancel) but does not grow. "
        "(A-36) as printed has sign errors (docs/concepts/physics.md, section 5)",
        test=_T + "test_fig10_loaded_deformation_beside_thermal_and_centrifugal",
    ),
    Row(
        seed="A",
        item="Fig. 11",
        paper="axial and radial bearing stiffness against speed, with and without thermal "
        "deformation, 100 N m",
        figure="seed_a_thermal/seed_a_fig11_radial_stiffness_three_cases",
        quoted="radial stiffness rises slowly with speed, axial falls slightly; thermal "
        "deformation raises the radial and lowers the axial stiffness",
        ours="100 N m, 6500 -> 16,500 rpm: the seed formula's (A-39..A-42) radial stiffness "
        "-0.3 % without thermal effects, +2.2 % with them; k_xx -5.0 % and -1.1 %; the seed "
        "axial stiffness -3.2 % and -9.4 %; thermal deformation raises the radial and lowers "
        "the axial stiffness at every speed (the default aluminium housing reverses both). "
        "Without thermal effects the seed radial stiffness rises with speed only at a light "
        "axial load: below 315 N of preload alone, below 1378 N of axial load under the "
        "100 N m radial force (but for 304-425 N, where speed lifts the two balls opposite "
        "the load off their inner contacts); k_xx below 54 N and 240 N",
        status="differs",
        reason="physical argument: the radial claim holds for seed A's series formula at a "
        "light axial load, and the 100 N m case is not one. Per ball the formula puts the "
        "inner and outer contact stiffnesses (times cos^2 of their angles) in series; with "
        "speed the centrifugal force loads the outer contact and flattens its angle (that "
        "term stiffens) and unloads the inner one and steepens its angle (that term "
        "softens), and the series follows both. At 100 N m (2380.9 N of gear axial force "
        "plus the 300 N preload) the outer terms, the softer at 6500 rpm, rise 3.4 % and the "
        "inner fall 3.9 %: net -0.3 %. With the preload alone the outer gain wins below "
        "315 N (the same from the native formula and from A-39..A-42 recomputed on the "
        "solved balls), so the paper's 300 N sits at the turn; under the 100 N m radial force "
        "the axial load would have to stay below 1378 N, and the gear alone puts 2380.9 N: no "
        "preload makes the 100 N m case rise. k_xx, which adds how the angles turn under "
        "load, falls above 54 N (preload alone) and 240 N (100 N m). With thermal effects on "
        "the claims' housing (the clearance closes) the seed formula rises at every preload "
        "alone from 20 N to 4 kN and at every axial load above 398 N at 100 N m: the "
        "paper's rising curve is that of the thermal case (scan: "
        "seed_a_thermal/seed_a_fig11_turning_loads)",
        test=_T + "test_fig11_radial_trend_turns_with_the_axial_load",
    ),
    Row(
        seed="A",
        item="Fig. 13",
        paper="time-varying mesh stiffness of the first gear pair: tooth pairs 1 to 11 "
        "approach and recess in turn, several in mesh at once, their parallel sum",
        figure="seed_a_gear/seed_a_fig13_mesh_stiffness",
        quoted="11 tooth-pair curves, overlapping because more than one pair meshes at a "
        "time; the mesh stiffness is their parallel sum; no values in the text",
        ours="each pair rises on approach and falls on recess over eps_alpha + eps_beta = "
        "5.09 mesh periods; 5 or 6 pairs in mesh (never fewer than 5: the held-out claim "
        "of more than one is met); sum 6.40e8 to 6.85e8 N/m (transverse, mean 6.61e8, "
        "6.8 % peak to peak), equal to the mesh stiffness table",
        status="reproduced",
        reason="",
        test=_T + "test_fig13_tooth_pairs_approach_recess_and_sum",
    ),
    Row(
        seed="A",
        item="Fig. 14",
        paper="bifurcation diagrams of the dynamic transmission error, accelerating, "
        "(a) constant, (b) speed-dependent, (c) thermal bearing stiffness, 100 N m",
        figure="seed_a_gear/seed_a_fig14c_bifurcation_100_n_m_thermal_up",
        quoted="23 transition speeds: period-1 up to 9644 / 9933 / 10,040 rpm (a / b / c), "
        "jumps at 6978 / 10,140 / 10,440 rpm, chaos in 11,750-12,460 rpm, period-2 at "
        "12,840 / 11,550 / 12,960 rpm, periodic windows in chaos above 12,960 rpm",
        ours="with the four inputs seed A leaves out calibrated on the fitted numbers of "
        "cases a and b (TE 48.1 µm, mesh damping ratio 0.171, half backlash 115 µm, mesh "
        "stiffness x 1.40): period-1 up to 9925 / 9925 rpm (a / b), jumps at 6725 / 9775 / "
        "9775 rpm, chaos in 11,625-12,475 rpm, period-2 at 12,900 / 11,600 / 12,950 rpm, "
        "windows in chaos from 13,075 rpm; the thermal case (c) predicted, not fitted, and "
        "22 of its and the others' 23 numbers within 1000 rpm; with the stated inputs "
        "period-1 everywhere",
        status="partly reproduced",
        reason="one miss, a held-out number: in case c the calibrated pair's low-speed "
        "resonance (the 3.27 kHz mode of the gear bodies on their bearings meets the mesh "
        "frequency at 6760 rpm) is already irregular, so its period-1 motion ends at "
        "6625 rpm, not 10,040. The inputs the paper leaves out are found, not assumed, and "
        "they say what its diagrams need: a first-harmonic TE of 48 µm, several times a "
        "ground gear's, on 230 µm of backlash. The paper's jump at 10,140-10,440 rpm is "
        "ours at 9775 rpm, where the motion leaves period-1; the stated inputs (TE 2 µm) "
        "keep the teeth in contact (seed_a_100_n_m_period1)",
        test=_T + "test_fig14_calibrated_structure",
    ),
    Row(
        seed="A",
        item="Fig. 15",
        paper="bifurcation diagrams, decelerating, the same three cases, 100 N m",
        figure="seed_a_gear/seed_a_fig15c_bifurcation_100_n_m_thermal_down",
        quoted="18 numbers: spikes at 6978, 6702, 6600 and 7106 rpm, all below 7500 rpm; "
        "period-2 at 12,840 / 11,550 / 12,960 rpm; periodic windows 14,270-14,620 and "
        "14,990-15,690 (a), 12,960-13,270 and 15,580-15,880 (b), 14,380-14,590 rpm (c)",
        ours="jumps at 6725 / 6725 / 6775 and 6825 rpm, where the mesh frequency meets the "
        "3.2-3.3 kHz mode of the gear bodies on their bearings; period-2 at 12,900 / 11,600 / "
        "12,950 rpm; window edges nearest the quoted ones 14,975-14,675 and 14,975-16,025 "
        "(a), 13,375-13,225 and 15,825-15,775 (b), 14,975-14,875 rpm (c); every number within "
        "1000 rpm, case c predicted",
        status="reproduced",
        reason="",
        test=_T + "test_fig15_spikes_are_the_coupled_mode_resonance",
    ),
)
