"""Captions of the report (figures/report.py): for each chapter program, each figure
(a file-name pattern in build/figures/), its thesis figure number, and one paragraph:
what it shows and what to notice. Plus the thesis figures that cannot be computed."""

CHAPTERS = [
    {"program": "ch02_methods", "title": "Chapter 2: the method, speed against accuracy, and where each method fails", "figures": [
        ("figM1_*.png", "supplement M1", "Error of x_max against CPU time per method and scene (HB exact/stepped/sampled, GSL rk8pd and "
         "rkf45 sweeps). Notice that HB reaches a given error 10-1000x faster than the time-integration sweeps; hollow "
         "circles: a stable solution the method missed."),
        ("figM2_*.png", "supplement M2", "CPU time of one Newton step against the size n(2H+1) of the unknowns. Notice the measured "
         "times follow the (n(2H+1))^3 growth of the LU only for the largest systems; below, fixed costs dominate."),
        ("figM3_*.png", "supplement M3", "Natural continuation (frequency as parameter) against pseudo-arc-length on the same curve. "
         "Notice where natural continuation stops: at the first fold, where the branch turns back; arc length goes round it."),
        ("figM4_*.png", "supplement M4", "Time-integration sweeps up and down in frequency against the HB branch. Notice the jumps "
         "at the two folds (hysteresis): a sweep never sees the unstable middle branch."),
        ("figM5_*.png", "supplement M5", "Classic sampled AFT (contact force sampled at N times) against the exact projection. "
         "Lower panels: zoom on the dashed boxes. Notice the spurious folds (22 at N = 4(2H+1), 24 at 8(2H+1) on the "
         "mass against the wall) and the stalled branches of the sampled version where the contact opens and closes; "
         "the exact projection has only the 2 true folds."),
        ("figM6_*.png", "supplement M6", "Gear response with too few harmonics. Notice the superharmonic resonances below the "
         "primary one, present with enough harmonics, missing with H = 1."),
        ("figM7_*.png", "supplement M7", "Hill's method truncated at H against Floquet on the Mathieu and Meissner stability "
         "charts. Notice where the truncated Hill tongues depart from the Floquet boundaries (large q, few harmonics)."),
        ("figM8_*.png", "supplement M8", "Arc length without scaling on the micrometre gear problem. Notice it stays stuck near "
         "the start: displacements of 1e-6 m beside a frequency unknown of thousands of rad/s (the axis is the mesh "
         "frequency in Hz, omega / 2 pi) make the unscaled arc-length step a step in frequency alone."),
        ("figM9_*.png", "supplement M9", "Grazing: each method's error as the contact interval shrinks to zero. Notice which "
         "methods keep their accuracy at grazing and which lose it."),
    ]},
    {"program": "ch03_mass_wall", "title": "Chapter 3: a mass against a wall", "figures": [
        ("fig07_*.png", "Fig. 7", "Linear frequency response with the contact open (spring k) and closed (k + kc). "
         "Notice the two resonances, 1 and sqrt(2) rad/s: every contact curve of this chapter lives between them."),
        ("fig08_*.png", "Fig. 8", "The contact law max(N0 + kc x0 cos theta, 0) over one cycle for a preload that keeps "
         "contact, one that loses it for part of the cycle, and a gap never closed. Notice the force is clipped at zero, "
         "never negative."),
        ("fig09_*.png", "Fig. 9", "Two clearances. Notice g = -1.2 m is never reached (the curve stays linear) while "
         "g = -0.6 m bends the resonance to the right (hardening): two folds and an unstable (dashed) middle branch."),
        ("fig10_*.png", "Fig. 10", "Two preloads: the mass starts in contact. Notice x_min leaving the wall level near "
         "resonance: the mass separates and the resonance bends to the left (softening). The thesis' g = 1 m curve stays in "
         "full contact; ours separates because the static term is kept (chapter README)."),
        ("fig11_*.png", "Fig. 11", "The same gap (g = -0.6 m) with two forcing amplitudes. Notice the small force never "
         "reaches the wall and the larger one does: the nonlinearity depends on the amplitude."),
        ("fig12_*.png", "Fig. 12", "A larger force makes the far wall (g = -1.2 m) reachable. Notice the overhang appear "
         "only for F = 0.03 N."),
        ("fig13_*.png", "Fig. 13", "Static force F0 = 1 N, gap g = -1.5 m. Point A: 0.02 rad/s before the contact state first "
         "changes. Notice x(t) stays above the wall: an open-contact (linear) orbit."),
        ("fig14_*.png", "Fig. 14", "The same curve at point B, the largest response. Notice x(t) passes the wall every "
         "cycle: the contact closes for part of the period and the orbit is no longer a sine."),
        ("fig15_*.png", "Fig. 15", "The same curve at point C, the first computed point at least 0.05 rad/s after the last change of contact "
         "state (its omega is in the panel title). Notice "
         "the orbit is back above the wall: open again."),
        ("fig16_*.png", "Fig. 16", "Starting in contact (g = -0.5 m, F0 = 1 N), point A before separation. Notice x(t) "
         "stays in contact: the amplitude is not enough to leave the wall."),
        ("fig17_*.png", "Fig. 17", "The same curve at point B, the largest response. Notice the mass leaves the wall for "
         "part of the cycle. Left panel: x_min crosses the wall level between 1.28 and 1.42 rad/s (the separation)."),
        ("fig18_*.png", "Fig. 18", "The same curve at point C, after the last change. Notice the orbit is in full contact "
         "again."),
        ("figS1_*.png", "supplement S1", "Folds found with the classic sampled AFT against the number of time samples. "
         "Notice the spurious micro-folds at small N, against the 2 true folds that the exact projection finds at any N."),
    ]},
    {"program": "ch04_two_masses", "title": "Chapter 4: two masses with contact between them", "figures": [
        ("fig20_*.png", "Fig. 20", "g = -0.5 m: left, relative displacement d = x1 - x2 with the contact level -g; right, each "
         "mass's amplitude. Notice the contact level is far away: never in contact, the linear open response."),
        ("fig21_*.png", "Fig. 21", "g = -0.005 m. Notice d_max reaches the contact level from 2.00125 rad/s and the "
         "resonance bends right (hardening): two folds, unstable middle branch. The right panel shows the masses' "
         "amplitudes on the same (contact) branch."),
        ("fig22_*.png", "Fig. 22", "g = 0.15 m (preloaded). Notice d never reaches the separation level: always in contact, "
         "the linear closed response with the anti-phase resonance at 3 rad/s."),
        ("fig23_*.png", "Fig. 23", "g = 0.6 m: the same with a larger preload (penetration 0.333 m). Notice the curve is the "
         "closed linear response, shifted."),
    ]},
    {"program": "ch05_comparin_singh", "title": "Chapter 5: the Comparin & Singh impact pair", "figures": [
        ("fig25_*.png", "Fig. 25", "F0 = 4.1 N, Fa_1 = 0.05 N, g = -20 and -15 m. Notice the two curves coincide: both gaps "
         "are never reached (type 1, as the classifier predicts)."),
        ("fig26_*.png", "Fig. 26", "F0 = 4.1 N, Fa_1 = 0.05 N, g = -1 and 6 m. Notice, in the zoom, the g = -1 m branch leave "
         "full contact at 1.41145 rad/s and fold back (softening): intermittent solutions also exist below the predicted "
         "(grey) band."),
        ("fig27_*.png", "Fig. 27", "Fa_1 doubled to 0.1 N, g = -20 and -30 m. Notice both stay linear (type 1): the gaps are "
         "far larger than the vibration."),
        ("fig28_*.png", "Fig. 28", "Fa_1 = 0.1 N, g = 6 and 20 m (preloaded). Notice both stay in full contact (type 2): the "
         "closed linear response."),
        ("fig29_*.png", "Fig. 29", "F0 = 2.1 N, Fa_1 = 0.05 N, g = -15 and -8 m. Notice both stay linear (type 1): halving the "
         "mean force does not bring the gap within reach."),
        ("fig30_*.png", "Fig. 30", "F0 = 2.1 N, Fa_1 = 0.05 N, g = 6 and 10 m. Notice both stay in full contact (type 2): with "
         "our reading of the model 11 of the 12 thesis cases are linear; only g = -1 m (Fig. 26) loses contact."),
        ("figS2_*.png", "supplement S2", "The rebuilt regime classifier against every harmonic-balance solution of a "
         "1200-point grid. Notice there is no disagreement."),
    ]},
    {"program": "ch06_gear_pair", "title": "Chapter 6: a 6-DOF spur-gear pair with external forcing", "figures": [
        ("fig40_*.png", "Fig. 40", "Fi = 1e5 (static) with harmonic forcing, kc = 5e8 N/m: Delta_max and Delta_min (top), "
         "oscillating amplitude (bottom), a zoom on the folds (middle). Notice the mesh opens at 7638 rad/s, the fold "
         "pairs and bifurcations at 7-12 krad/s (zoom), and the deep Delta_min dip at 22.2 krad/s on no natural-frequency "
         "line: the bilinear mode of the mesh (closed-mesh mode 5 while in contact, free gears while apart; README). "
         "Grey bands: no stable period-1 orbit; in them the period-2 branches switched at the period doublings, a "
         "colour each (console: where each ends, and the switches that fail). Magenta hatching with a dotted line: "
         "a period-1 stretch labelled stable whose shooting correction fails (stability unresolved, not counted "
         "stable: key numbers unresolved_period1_*)."),
        ("fig41_*.png", "Fig. 41", "Fi = 1e7. Notice full contact everywhere except two narrow windows: 13.53-13.87 krad/s "
         "(four folds, near the closed-mesh mode 13.69 krad/s; middle panel: zoom) and near 47 krad/s. The thesis says it stays in full "
         "contact (chapter README). Brown (thicker): a second period-1 branch the continuation from 2 krad/s never "
         "reaches, continued from the time-integrated orbit at 13.595 krad/s (supplement S47): an isola over "
         "13.48-13.86 krad/s in intermittent contact, stable (solid) from its Neimark-Sacker point at 13.51 to its "
         "fold at 13.86 krad/s, where Delta swings up to 5.17 mm (from -3.35 to 2.05 mm) against at most 1.88 mm on "
         "the continued curve; with it every speed has a stable period-1 orbit (no grey band)."),
        ("fig42_*.png", "Fig. 42", "Fi = -1e8: the static load pulls the teeth apart. Notice the mesh never closes: the "
         "open linear response."),
        ("fig43_*.png", "Fig. 43", "Fi = -1e6. Notice the first touch at 10716 rad/s, then a hardening band up to the fold "
         "at 21718 rad/s (towards the mesh's bilinear mode, 22.18 krad/s: README) with period doublings and "
         "Neimark-Sacker points on it. The period-2 branches from the period doublings at 10716 and 12664 rad/s "
         "rejoin the period-1 branch near 10976 and 13925 rad/s; between the Neimark-Sacker points at 16.0 and "
         "17.0 krad/s (grey) no period-2 branch starts: there a complex pair of multipliers lies outside the circle."),
        ("fig44_*.png", "Fig. 44", "Fi = 1e7 with 100x the harmonic forcing. Notice it is Fig. 40 multiplied by 100 "
         "(the contact law with zero gap is positively homogeneous; only Fi/Fa matters): the same folds (zoom) and "
         "the same bilinear-mode dip at 22.2 krad/s, now -388 mm."),
        ("fig45_*.png", "Fig. 45", "Fi = -1e8 with 100x the harmonic forcing. Notice it is Fig. 43 multiplied by 100."),
    ] + [("figS%d_*.png" % n, "supplement S%d" % n, "Fig. %d's case (%s) with the printed kc = 5e2 N/m (kc_alt). "
           "Notice the curve is the linear open response shifted: a 5e2 N/m contact does nothing, which is why 5e8 is "
           "the default (chapter README)." % (n, load))
         for n, load in ((40, "Fi = 1e5"), (41, "Fi = 1e7"), (42, "Fi = -1e8"), (43, "Fi = -1e6"),
                         (44, "Fi = 1e7, 100x forcing"), (45, "Fi = -1e8, 100x forcing"))] + [
        ("figS46_*.png", "supplement S46", "Beyond Fig. 43's first period doubling. Notice the time-integrated orbit "
         "repeats after two forcing periods, not one; dashed: the unstable period-1 orbit of harmonic balance."),
        ("figS47_ch06_diagram_fig40.png", "supplement S47", "What the gear does where Fig. 40 has no stable "
         "period-1 orbit: the bifurcation diagram by time integration (GSL rk8pd, the speed stepped up then down over "
         "eight bands, 255 speeds each way; the mesh deflection once per forcing period) under the harmonic-balance "
         "branches, in four columns: 7.5-12 krad/s (bands 7.5-11.2 and 11.5-12.0 krad/s, 75 and 21 speeds), "
         "12.4-15.5, 17.6-18.4 and 26.2-62 krad/s (hatched: between two bands, no diagram; the HB curves may leave "
         "the panel there). First column: notice chaotic motion (red) in both sweeps over 8.45-8.65, 8.8-9.0 and "
         "9.3-10.1 krad/s and most of 10.35-10.65 krad/s, also at 8.25 and 9.3 krad/s where HB's period-1 orbit is "
         "stable and at 8.0, 9.0 and 10.35 krad/s where a period-2 branch of HB is: there attractors coexist, and the "
         "time integration started on the HB orbit stays on it (hollow diamonds; CTest "
         "ch06_gear_pair.fig40_diagram.diagram_vs_hb: at every speed with a stable HB orbit a sweep or that start is "
         "periodic on it, with its period). Coloured lines below: the period-2 branches at the same phase, their two "
         "values (a colour each, as above); the one from the non-smooth period doubling at 7.98 krad/s carries the "
         "sweeps' period-2 points at 8.05-8.1 krad/s. Periods 2-6 (blue) at 7.9-8.1, 8.7-8.75 (sweep up) and 10.2-10.3 krad/s, quasi-periodic points (green) at 10.15 and "
         "10.95-11.05 krad/s, period 1 on HB's orbit again from 10.7 krad/s. Magenta squares: HB points whose shooting "
         "correction fails, so their stability is not resolved at H = 10. At 7.75-7.9 krad/s such points are drawn "
         "unstable, but the orbit is stable (H = 14) and the sweeps sit on it (chapter README, step 3b). In the "
         "second band, the Neimark-Sacker stretch 11.63-11.87 krad/s: quasi-periodic (green), then chaotic from "
         "11.7 krad/s, and the up sweep stays chaotic to 11.9 krad/s. Second column: chaos at 12.7-13.3 krad/s in "
         "both sweeps, then period 2 on HB's period-2 branch to 15.1 krad/s (period 4 at 14.2 krad/s, past that "
         "branch's period doubling at 14.20). Third: at 17.7-18.4 krad/s mostly period 4 (chaos at 17.8-17.85 krad/s), "
         "the down sweep back on HB's period-1 orbit from 18.25. Fourth: period 2 and chaos at 26.3-27.3 krad/s; a period-3 orbit at 34.8-37.6 and 42.6-43.5 "
         "krad/s, also where HB's period-1 orbit is stable (34.8-35.0, 42.6-42.9 krad/s: the start on HB's orbit "
         "stays on it, two attractors); quasi-periodic at 36.4-39.0 and 43.4-46.5, chaotic at 39.8-41.0 krad/s; "
         "period 2 on HB's period-2 branch at 47.5-52 and 55-62 krad/s, period 4 and chaos at 52.5-54.5 krad/s."),
        ("figS47_ch06_diagram_fig41.png", "supplement S47", "What the gear does where Fig. 41 has no stable "
         "period-1 orbit: the bifurcation diagram by time integration over 13.4-14.0 krad/s (41 speeds each way) "
         "under the harmonic-balance branches. Notice the up sweep leaves HB's orbit at 13.595 krad/s for a period-1 "
         "orbit that is not on the continued curve (Delta at phase 0 down to -2.6 mm) and stays on it to 13.85 "
         "krad/s; the down sweep is chaotic (red) at 13.715-13.79 krad/s and on that orbit from 13.70 down to 13.52 "
         "krad/s. Brown: the HB branch continued from that orbit at 13.595 krad/s (chapter step 3c), an isola over "
         "13.48-13.86 krad/s, stable (solid) from its Neimark-Sacker point at 13.51 to its fold at 13.86 krad/s; "
         "below, its section at phase 0 runs through all 31 off-curve Poincare points of both sweeps. HB's stable "
         "stretches of the continued curve are visited by neither sweep there, but the time integration started on "
         "their orbits stays on them (hollow diamonds): two stable period-1 orbits coexist. With the isola every speed "
         "of the band has a stable period-1 orbit (no grey band)."),
        ("figS47_ch06_diagram_fig44.png", "supplement S47", "Fig. 44's case (Fig. 40 x 100): the diagram is Fig. "
         "40's with every Poincare point times 100 (the starts on HB's orbits too; the model is homogeneous in the "
         "loads), in the same four columns, under Fig. 44's own harmonic-balance branches; notice they match Fig. 40's x 100."),
        ("figS47_ch06_diagram_fig45.png", "supplement S47", "Fig. 45's case (Fig. 43 x 100): the diagram is Fig. "
         "43's with every Poincare point times 100, under Fig. 45's own harmonic-balance branches; notice the "
         "period-1 points lie on HB's stable orbit as in Fig. 43."),
        ("figS47_ch06_diagram_fig43.png", "supplement S47", "What the gear does where Fig. 43 has no stable period-1 orbit: the "
         "bifurcation diagram by time integration (GSL rk8pd, the speed stepped up then down over 10-15 krad/s, 150 "
         "speeds each way, and over 15.8-17.3 krad/s, 16; the mesh deflection once per forcing period; hatched: "
         "between the two bands, no diagram) under the harmonic-balance branches. Notice the two views agree "
         "where HB has a stable orbit (CTest ch06_gear_pair.fig43_diagram.diagram_vs_hb): the period-1 points on the "
         "grey line, and in both grey bands the period-2 points on the two lines of HB's stable period-2 branches "
         "(coloured); period 4 at a few speeds, and chaotic motion (red) near 12.7-13.0 krad/s in both sweeps, where "
         "the period-2 branch is unstable (dashed). In the second band, the Neimark-Sacker stretch 16.02-17.04 "
         "krad/s: quasi-periodic (green) and not settled at most speeds, chaotic at one speed in each sweep, period 1 "
         "on HB's orbit on either side."),
    ]},
    {"program": "ch07_ste", "title": "Chapter 7: static transmission error from a beam FE tooth model", "figures": [
        ("fig46_*.png", "Fig. 46", "The four-beam model of two meshing tooth pairs drawn from the run's nodes (1-44; "
         "driving roots below, driven roots above) with the contact node pairs of Figs. 48-49 and 52-55. Notice a "
         "pair sits at one height: contact near A meets the driven tooth's tip (2-22), near C the middle (6-18)."),
        ("fig65_*.png", "Fig. 65", "The tooth axis in its three limit positions on the path of contact (drawn from "
         "geometry.csv and tooth_axis_angles.csv): along the centre line, along O2E and along O2A. Notice the angle "
         "between the axis' perpendicular and the line of action, alpha, alpha - beta, alpha + epsilon: the force on "
         "the beam would be scaled by its cosine, a 7 % variation along the path."),
        ("fig73_*.png", "Fig. 73", "One base pitch laid along the path of contact from each end (geometry.csv): "
         "A-A' and E'-E have two pairs in contact, A'-E' one. Notice AE/p_b = 1.7547, the contact ratio, and that "
         "the single-pair zone around C is where chapter 9's backlash can be reached."),
        ("fig48_*.png", "Fig. 48", "Nodal deflections of one tooth pair loaded at contact nodes 6 and 18 (circled; constant "
         "thickness, 300 N m). Notice the STE, the sum of the two teeth's deflections at the contact nodes: 1.8764 um, "
         "the thesis' printed value (box)."),
        ("fig49_*.png", "Fig. 49", "The same with the load at nodes 7 and 17, the next contact position along the "
         "profile."),
        ("fig50_*.png", "Fig. 50", "The FE cantilever loaded at node 7 against the exact cubic elastic line. Notice the FE "
         "nodes lie on the exact line (to round-off)."),
        ("fig51_*.png", "Fig. 51", "The same loaded at node 6."),
        ("fig52_*.png", "Fig. 52", "Two pairs in contact, fused node pairs 2-22 and 30-38 (circled): a common transmission "
         "error. Notice the driving roots moved by -X_STE = -0.9155 um: load sharing halves the STE of one pair."),
        ("fig53_*.png", "Fig. 53", "Two pairs, fused node pairs 3-21 and 31-37 (circled), the next contact position."),
        ("fig54_*.png", "Fig. 54", "Two pairs, fused node pairs 4-20 and 32-36 (circled)."),
        ("fig55_*.png", "Fig. 55", "Two pairs, fused node pairs 5-19 and 33-35 (circled). Notice X_STE is the same "
         "0.9155 um at every position of the constant-thickness model."),
        ("fig56_*.png", "Fig. 56", "Bending moment along the fused 11-element beam. Notice it runs from +7.425 to -7.425 N m "
         "and is zero mid-span: the reaction moments the thesis prints."),
        ("fig57_*.png", "Fig. 57", "The involute tooth thickness and the stepped beam thickness of the 10- and 14-element "
         "models. Notice the steps approximate the involute."),
        ("fig58_*.png", "Fig. 58", "Deformed teeth, one pair in contact at nodes 6 and 18 (circled), involute "
         "thickness, 300 N m (deflection x200)."),
        ("fig59_*.png", "Fig. 59", "Deformed teeth, two pairs in contact, fused nodes 2-22 and 30-38 circled, 300 N m "
         "(deflection x200). Notice each pair carries part of the load."),
        ("fig60_*.png", "Fig. 60", "STE over the mesh cycle for 100, 200, 300 N m. Notice the jumps where the second pair "
         "enters and leaves: the single-pair zone has the largest STE."),
        ("fig61_*.png", "Fig. 61", "Fourier coefficients of the STE (harmonics 1 and up; the mean is printed in the title). Notice "
         "the first few harmonics: with the mean they are the excitation of chapter 8."),
        ("fig62_*.png", "Fig. 62", "The refined 14-element model with its contact node pairs."),
        ("fig63_*.png", "Fig. 63", "STE of the 14-element model. Notice its maximum at 300 N m, 13.753 um, 0.12 % below the "
         "thesis' 13.77 um (key numbers below)."),
        ("fig64_*.png", "Fig. 64", "Fourier coefficients of the 14-element STE."),
        ("ch07_extra_*.png", "supplement", "Max STE and mean stiffness for P = 8 ... 64 contact positions. Notice how much "
         "the 14-node values still change as positions are added."),
    ]},
    {"program": "ch08_gear_response", "title": "Chapter 8: the gear driven by its own static transmission error", "figures": [
        ("fig67_*.png", "Fig. 67", "Mesh stiffness k(t) = F0/e(t) over one mesh cycle for 100, 200, 300 N m with its mean kc. "
         "Notice the jumps: the second tooth pair entering and leaving."),
        ("fig69_*.png", "Fig. 69", "RMS of the oscillating dynamic transmission error against mesh frequency, one harmonic, "
         "three torques and the linear closed-contact curve. Notice contact is lost near resonance for every torque "
         "(the overhang)."),
        ("fig70_*.png", "Fig. 70", "The same with five harmonics. Notice the superharmonic resonances below the primary "
         "one and the higher peak (H = 5 is not converged: see fig70s_H_convergence)."),
        ("fig70s_time*.png", "supplement", "x(t) and the contact force over two mesh periods at a contact-loss point. "
         "Notice the force is zero while the mesh is open."),
        ("fig70s_H*.png", "supplement", "Convergence in H of the 300 N m curve (H = 1, 5, 10, 20). Notice 5 harmonics are "
         "not converged at the peak (2.8 % below H = 20), see the chapter README."),
        ("fig70s_param*.png", "supplement", "The 300 N m curve of the thesis' constant-stiffness model and of the "
         "parametric model it approximates (k(t) = F0/e(t)). Notice where they differ (chapter README)."),
    ]},
    {"program": "ch09_backlash", "title": "Chapter 9: backlash limits the STE at high torque", "figures": [
        ("fig75_*.png", "Fig. 75", "The limit condition for the normal backlash (drawn from backlash_geometry.csv): "
         "contact at E' while the adjacent pair is at A. Notice the tangential directions at A and E' turned by "
         "epsilon and epsilon' from the one at C: mu(E') = alpha + epsilon + epsilon', so b_n = b cos(mu) is smallest there."),
        ("fig77_*.png", "Fig. 77", "STE over one mesh cycle with backlash (clip and adjacent-pair spring) and without, "
         "100/200/300 N m. Notice only 300 N m reaches the local normal backlash, near the ends of the single-pair zone."),
        ("fig77s_*.png", "supplement", "The local normal backlash b cos(mu) along the single-pair zone against the 300 N m "
         "STE. Notice where the STE exceeds it: there the adjacent pair engages."),
        ("fig78_*.png", "Fig. 78", "Fourier coefficients of the STE with and without backlash. Notice only 300 N m changes, "
         "by a few per cent."),
        ("fig79_*.png", "Fig. 79", "Our STE coefficients with backlash; Parker, Vijayakar & Imajo's bars are not available "
         "and not drawn."),
        ("fig80_*.png", "Fig. 80", "DTE response with backlash, one harmonic, three torques and the linear closed-contact "
         "curve. Notice it is almost Fig. 69: backlash changes only the 300 N m excitation."),
        ("fig81_*.png", "Fig. 81", "The same with five harmonics."),
        ("fig82_*.png", "Fig. 82", "300 N m with and without backlash (both readings), H = 1 and 5, with a zoom on the peak. "
         "Notice the peak drops by 1.3 % and moves up in frequency."),
    ]},
]

NOT_COMPUTABLE = [
    ("Figs. 1-4", "introduction: gear drives, engines and their data from other sources"),
    ("Fig. 5", "sketch of the pseudo-arc-length continuation method"),
    ("Fig. 6", "sketch of the mass-against-wall model"),
    ("Fig. 19", "sketch of the two-mass system"),
    ("Fig. 24", "sketch of the Comparin & Singh system"),
    ("Figs. 31-39", "sketches: tooth profile, line of action, pressure angle, gear-pair reference frames, forces and displacements"),
    ("Fig. 47", "sketch of the teeth as springs in series and in parallel (Fig. 46 is drawn from the model's nodes: "
     "fig46_four_beam_model.png)"),
    ("Fig. 66", "sketch of the 1-DOF gear model (after Ozguven & Houser)"),
    ("Fig. 68", "mesh stiffness found by Parker, Vijayakar & Imajo (2000): their data are not available"),
    ("Figs. 71-72, 83-84", "comparisons with the FE and experimental curves of Parker, Vijayakar & Imajo (2000): not available; our curves are drawn alone"),
    ("Fig. 74", "sketch of the normal and nominal directions (Fig. 73 is drawn from geometry.csv: "
     "fig73_base_pitch.png)"),
    ("Fig. 76", "a contact condition taken from the thesis' reference [27] (another source)"),
    ("Parker's curves in Figs. 60 and 79", "not available: our STE and coefficients are drawn alone, nothing in their place"),
]

# The figures of a gearhb_gear run (figures/gearhb_gear.py, figures/gear_dynamics.py), one
# page per example in the report: file name in the run folder -> what it shows.
# The captions that speak of the relief, for a file without one (figures/report.py gear_caption).
GEAR_CAPTIONS_NO_RELIEF = {
    "ste.png": "Loaded static transmission error over one mesh cycle, one curve per torque. Notice the "
               "steps where a pair enters or leaves the path (the file has no tip relief to flatten them).",
    "harris.png": "Harris map: STE peak-to-peak against torque. The file has no tip relief, so there is one "
                  "curve, rising with the load; a relief would bring a minimum at the load it suits.",
}

# The captions that differ for a helical file (helix_angle_deg > 0; figures/report.py gear_caption).
GEAR_CAPTIONS_HELICAL = {
    "ste.png": "Loaded static transmission error over one mesh cycle of the helical pair (the face in slices), "
               "one curve per torque. Notice how small and smooth its fluctuation is beside a spur pair's: the "
               "contact lines enter and leave the path gradually, across the face.",
    "stiffness.png": "Mesh stiffness k = F / STE over the mesh cycle per torque, its mean dotted. It follows the "
                     "contact-line length on the path, which varies with the fractional part of the overlap ratio "
                     "and is constant only at whole eps_beta.",
    "shares.png": "Load share of each tooth pair, summed over the slices of the face, along the mesh cycle (exact "
                  "contact problem over slices x pairs): a pair takes up and gives off its load gradually.",
}

GEAR_CAPTIONS = {
    "ste.png": "Loaded static transmission error over one mesh cycle, one curve per torque. Notice the "
               "steps where a pair enters or leaves the path, and how tip relief flattens them at its design load.",
    "stiffness.png": "Mesh stiffness k = F / STE over the mesh cycle per torque, its mean dotted: the one-pair / "
                     "two-pair step at eps_alpha - 1 of the cycle.",
    "shares.png": "Load share of each tooth pair along the mesh cycle (exact contact problem): where a pair "
                  "takes up and gives off its load.",
    "load_map.png": "A helical (or lead-modified) face in slices: the line load of every slice contact over the "
                    "roll angle of gear 1 (A to E) and across the face, at the largest torque. Notice the contact "
                    "lines' stagger and where a lead modification unloads the ends of the face.",
    "spectrum.png": "STE amplitude per mesh order: what the mesh excites at each multiple of the mesh frequency.",
    "harris.png": "Harris map: STE peak-to-peak against torque with the file's relief and without it. The "
                  "minimum marks the load the relief suits.",
    "root_stress.png": "Finite elements only: the root stress of one tooth of each gear while its pair moves "
                       "from A to E, per torque, ISO 6336-3's nominal sigma_F0 dotted. The peak sits at the outer "
                       "point of single contact (D for the driver, B for the driven gear), where ISO loads the tooth. "
                       "Below: the stress along both fillets there, tension under the loaded flank, compression under "
                       "the other; its peak lies near, not at, ISO's 30-degree point.",
    "response.png": "DTE RMS and dynamic factor K_v over speed per torque (stable solid, unstable dashed, "
                    "magenta squares where a stretch labelled stable has no converged shooting correction: "
                    "stability unresolved, where there are any; bifurcations marked, ISO 6336-1 K_v dotted where computed), the period-2 (period-4) branches "
                    "switched at the period doublings in colours of their own and the speeds with no stable "
                    "period-1 orbit shaded (where there are any; hatched magenta where the period-1 curve is "
                    "labelled stable but no shooting correction converged: unresolved); the rug below the axis is the contact of each "
                    "flank (drive-flank loss, back-flank impact), one row per curve. Under it, per torque with such "
                    "speeds, the bifurcation diagram by time integration (the DTE once per mesh period), by default "
                    "over a band around each of them (the panel's title gives the bands); hollow diamonds, where "
                    "there are any, are integrations started on a stable HB orbit that no sweep reached at its speed.",
    "mesh_stiffness.png": "Mesh stiffness from the teeth (mesh.stiffness tooth_model) over one mesh cycle at the "
                          "static load: the sun-planet mesh by gearhb_gear's pair model of the same pair, the "
                          "ring-planet mesh by the potential-energy method with an internal tooth (or ISO 6336-1's "
                          "rectangular wave); dotted, their means. Notice the steps where a pair enters and leaves "
                          "(contact ratios from the geometry) and how much stiffer the internal mesh is.",
    "campbell.png": "Campbell diagram: mesh orders 1-4 against speed with the natural frequencies of the "
                    "linear, always-closed mesh. An order line crosses one where that linear mesh would resonate; the "
                    "computed peaks (response.png) lie lower wherever the teeth separate, the softening of contact loss.",
    "time_history.png": "Two periods of the DTE and the mesh force (drive and back flank) at the hardest contact "
                        "of the run: where the teeth separate and where the back flank is hit, if anywhere in the run.",
    "dte_spectrum.png": "DTE per mesh order at the speeds named in its legend (the peak's among them): which "
                        "order carries the response.",
}

# The gear tools' figures of make figures that are not one gearhb_gear run's (figures/report.py,
# section "Gear tools"): file name -> what it shows and what to notice, true for every run.
TOOL_CAPTIONS = {
    "gear_methods.png": "The three tooth models (finite elements, beam, potential energy) on the three example pairs, "
                        "each as its example file has it, at the pair's largest torque: mesh stiffness k = F / STE "
                        "(top, ISO 6336-1 c_gamma_alpha b dotted) and STE (bottom) over one mesh cycle. Notice that "
                        "the models do not agree; gear_tooth_models.png says which lies nearer the converged FE.",
    "gear_methods_harris.png": "Harris map of the thesis gear with one long linear tip relief on both gears, by the "
                               "beam and the potential-energy model: STE peak-to-peak against torque with the relief "
                               "(solid, each model's smallest circled) and without it (dotted); the relief's design "
                               "torque dashed. Notice where each model's minimum lies against that design torque.",
    "gear_models.png": "One DOF (the torsional mesh on rigid bearings) against six (x, y, theta per gear on "
                       "bearings) for the thesis gear at 300 N m (top) and the relieved light-load gear at 20 N m "
                       "(bottom): DTE RMS of the exact orbit (left) and K_v (right) over speed, stable solid, "
                       "unstable dashed, bifurcations x. Notice where the curves part: the bearings add modes the "
                       "torsional model cannot have.",
    "gear_tooth_models.png": "Which tooth model a scene needs (figures/tooth_model_chart.py): each model's error "
                             "in the mean mesh stiffness (left) and the STE peak-to-peak (right) against the "
                             "converged FE (the Richardson limit of three mesh sizes), over its wall time, for "
                             "three pairs, like for like (the FE's bores for every model); dotted: 1 %. Read off "
                             "what each model costs and how far it lies from the FE.",
    "gear_helical_ste.png": "A helical version of the thesis pair, the transverse section fixed (figures/"
                            "helical_ste.py): STE peak-to-peak against the helix angle per torque (beam model, "
                            "slices), beside theory's peak-to-peak of the total contact-line length (dashed, right "
                            "axis). Notice both fall to their minima at whole overlap ratios, eps_beta = 1 and 2, "
                            "where the contact-line length on the path is constant.",
}

# The figures of a gearhb_planetary run, copied as planetary_<example>_<figure>: figure -> caption.
PLANETARY_CAPTIONS = {
    "modes.png": "Mode shapes of the set at carrier speed 0, one of each mode type the set has: the rest position "
                 "grey, the mode in colour. Notice the central members (sun, ring, carrier): in a rotational mode "
                 "they only turn, in a translational mode they only translate, in a planet mode (N > 3) they stay "
                 "still - Lin & Parker's three types, with multiplicities 1, 2 and N - 3.",
    "mesh_stiffness.png": "Mesh stiffness from the teeth (mesh.stiffness tooth_model) over one mesh cycle at the "
                          "static load: the sun-planet mesh by gearhb_gear's pair model of the same pair, the "
                          "ring-planet mesh by the potential-energy method with an internal tooth (or ISO 6336-1's "
                          "rectangular wave); dotted, their means. Notice the steps where a pair enters and leaves "
                          "(contact ratios from the geometry) and how much stiffer the internal mesh is.",
    "campbell.png": "Campbell diagram: the natural frequencies in the carrier frame against the carrier speed, with "
                    "the gyroscopic and centripetal terms; each line is the k-th frequency at each speed, not a "
                    "mode followed.",
    "phasing.png": "Mesh phasing: the largest amplitude of the sun's rotation and of its centre at each mesh "
                   "harmonic l over the computed curve; for a cyclically symmetric set, above the bars, the mode "
                   "family harmonic l may drive (Parker's rule on l z_s mod N), and the harmonics the rule "
                   "forbids fall to round-off (the bottom of the axis). Pin errors, unequal spacing or unequal "
                   "backlash break the symmetry: the title then says no rule applies.",
    "response.png": "Response over the mesh frequency (harmonic balance with exact contact on every mesh, arc "
                    "length): the sun's rotation and centre (AC RMS; solid where stable, dashed where unstable by "
                    "the Floquet multipliers, where the run computed them) and the largest K_v of the sun-planet and "
                    "of the ring-planet meshes, with a rug where a mesh of that kind loses contact. Where the run "
                    "switched at a period doubling, each period-2 branch in its own colour (its measures over two "
                    "mesh periods, its own rug rows), and the mesh frequencies with no stable period-1 orbit "
                    "shaded.",
    "meshes.png": "Every mesh over the mesh frequency: its dynamic factor K_v (largest |drive - back force| over "
                  "the static force), one line per planet, sun-planet meshes above, ring-planet below; its "
                  "contact class as a broad stroke under its own curve (drive flank loses contact, back flank "
                  "hits, both; no stroke: full contact), on each branch: a period-2 branch dotted with its points "
                  "(hollow where unstable) and its own strokes. Notice which meshes lose contact first, on which "
                  "branch, and where the back flanks hit.",
    "load_sharing.png": "Planet load sharing over the mesh frequency: L_n = N max F_sn / sum_m max F_sm for each "
                        "planet (F_sn the drive-flank force of its sun-planet mesh over the period), 1 for equal "
                        "shares. With a pin error (planet.pin_errors) notice how its planet sheds load to its "
                        "neighbours and how the resonances change the split; without, every L_n is 1 on the "
                        "symmetric response. A period-2 branch dotted, with its points.",
}

# The figures of a gearhb_frc run, copied as frc_<example>_<figure>: figure -> caption.
FRC_CAPTIONS = {
    "frc.png": "The frequency response of a model file (gearhb_frc): the output's largest and least value over a "
               "period against the forcing frequency, stable solid, unstable dashed (Floquet; magenta squares "
               "where a stretch labelled stable has no converged shooting correction: stability unresolved, "
               "where there are any), bifurcations marked, the contact state as a rug at the bottom (one row per branch, named by a tick in its "
               "colour at the left). Where the file asks for them: the period-2 "
               "branches switched at the period doublings (colours of their own, x_min close up on the right), a "
               "torus past a Neimark-Sacker point (dash-dot, its rotation number on the right; the points whose "
               "stability the time integration tested by two Lyapunov exponents filled where stable, open where "
               "unstable, grey where unresolved). Under every response with frequencies where no period-1 "
               "orbit is stable (shaded; hatched magenta where the curve is labelled stable but no shooting "
               "correction converged: unresolved, not counted stable), the Poincare points of the bifurcation diagram by time integration "
               "(below), by default over a band around each such range (the panel's title gives the bands); "
               "hollow diamonds, where there are any, are integrations started on a stable HB orbit that no sweep "
               "reached at its speed. Where the diagram has periodic orbits (period 1 or 2) on none of those "
               "branches, the HB branch continued from such an orbit in brown, thicker (and at phase 0 under the "
               "Poincare points); the shading then marks where no period-1 branch, the new ones included, is "
               "stable.",
    "bifurcation_diagram.png": "The bifurcation diagram by time integration (GSL, exact contact switching): the "
                               "output at phase 0 of each forcing period after the transient, over its bands "
                               "(the title: by default each range with no stable period-1 orbit, padded), sweeping up (top) "
                               "and down (bottom), each point coloured by what the motion is (period n, "
                               "quasi-periodic, chaotic by its largest Lyapunov exponent), under the harmonic "
                               "balance's period-1 curve at the same phase (and, brown, any branch continued from "
                               "the diagram's orbits off the others); in both panels, where there are any, "
                               "hollow diamonds: integrations started on a stable HB orbit that no sweep reached "
                               "at its speed. Notice that the two views agree where "
                               "both apply: the stable HB curve runs through the period-1 points.",
}
