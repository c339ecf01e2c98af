"""Captions of the report (figures/report.py): for each chapter program, each figure
(a file-name pattern in build/figures/), its thesis figure number, and one paragraph:
what it shows and what to notice. Plus the thesis figures that cannot be computed."""

CHAPTERS = [
    {"program": "ch02_methods", "title": "Chapter 2: the method, speed against accuracy, and where each method fails", "figures": [
        ("figM1_*.png", "supplement", "Error of x_max against CPU time per method and scene (HB exact/stepped/sampled, GSL rk8pd and "
         "rkf45 sweeps); hollow circles: a stable solution missed."),
        ("figM2_*.png", "supplement", "CPU time of one Newton step against n(2H+1), with the (n(2H+1))^3 model of the LU."),
        ("figM3_*.png", "supplement", "Natural continuation stops at the first fold; arc length goes round it."),
        ("figM4_*.png", "supplement", "Time-integration sweeps up and down jump at the folds and never see the unstable branch."),
        ("figM5_*.png", "supplement", "Sampled AFT: spurious folds and stalled branches at contact; the exact projection has none."),
        ("figM6_*.png", "supplement", "Too few harmonics: the gear's superharmonic resonances disappear."),
        ("figM7_*.png", "supplement", "Hill truncated at H against Floquet on the Mathieu and Meissner stability charts."),
        ("figM8_*.png", "supplement", "Arc length without scaling on the micrometre gear problem: stuck near the start."),
        ("figM9_*.png", "supplement", "Grazing: each method's error as the contact interval shrinks to zero."),
    ]},
    {"program": "ch03_mass_wall", "title": "Chapter 3: a mass against a wall", "figures": [
        ("fig07_*.png", "Fig. 7", "Linear frequency response with the contact open (spring k) and closed (k + kc): "
         "the two resonances, 1 and sqrt(2) rad/s, between which the contact curves live."),
        ("fig08_*.png", "Fig. 8", "The contact law max(N0 + kc x0 cos theta, 0) over one cycle for a preload that keeps "
         "contact, one that loses it for part of the cycle, and a gap never closed: the force is clipped, not negative."),
        ("fig09_*.png", "Fig. 9", "Two clearances: g = -1.2 m is never reached (the linear curve); g = -0.6 m bends the "
         "resonance to the right (hardening) with two folds and an unstable (dashed) middle branch."),
        ("fig10_*.png", "Fig. 10", "Two preloads: the mass starts in contact; where the vibration exceeds the static "
         "penetration it separates and the resonance bends to the left (softening). Notice x_min leaving the wall level."),
        ("fig11_*.png", "Fig. 11", "The same gap with two forcing amplitudes: the small force never reaches the wall, "
         "the larger one does. Nonlinearity depends on amplitude."),
        ("fig12_*.png", "Fig. 12", "A larger force makes the far wall (g = -1.2 m) reachable: the overhang appears."),
        ("fig1[345]_*.png", "Figs. 13-15", "With a static force F0 the mass sits 1 m off centre: the curve with the current "
         "point, beside x(t) there, before, during and after contact (points chosen by a stated rule)."),
        ("fig1[678]_*.png", "Figs. 16-18", "Starting in contact (g = -0.5 m, F0 = 1 N) and separating near resonance."),
        ("figS1_*.png", "supplement", "Folds found with the classic sampled AFT against the number of time samples: spurious "
         "micro-folds, against the 2 true ones that the exact projection finds at any N."),
    ]},
    {"program": "ch04_two_masses", "title": "Chapter 4: two masses with contact between them", "figures": [
        ("fig2[0-3]_*.png", "Figs. 20-23", "Relative displacement d = x1 - x2 (left, with the contact level -g) and each mass's "
         "amplitude (right) for g = -0.5, -0.005, 0.15, 0.6 m: never in contact, intermittent (two folds), always in contact."),
    ]},
    {"program": "ch05_comparin_singh", "title": "Chapter 5: the Comparin & Singh impact pair", "figures": [
        ("fig2[5-9]_*.png", "Figs. 25-29", "Frequency responses for the thesis' (Fm, Fp, g) cases; the title states the regime "
         "predicted by the analytic criteria, the curve the harmonic-balance result; the shaded band is the predicted "
         "intermittent range."),
        ("fig30_*.png", "Fig. 30", "The last pair of the thesis' cases."),
        ("figS2_*.png", "supplement", "The rebuilt regime classifier against every harmonic-balance solution of a 1200-point grid."),
    ]},
    {"program": "ch06_gear_pair", "title": "Chapter 6: a 6-DOF spur-gear pair with external forcing", "figures": [
        ("fig4[0-5]_*.png", "Figs. 40-45", "Mesh deflection Delta against forcing frequency for the thesis' static and "
         "harmonic loads (kc = 5e8 N/m): dashed where unstable; where the mesh opens the curves bend and fold."),
        ("figS4[0-5]_*.png", "supplement", "The same with the printed kc = 5e2 N/m (kc_alt): every curve is the linear open response "
         "shifted, which is why 5e8 is the default (chapter README)."),
        ("figS46_*.png", "supplement", "Beyond Fig. 43's first period doubling: time integration settles on an orbit that "
         "repeats after two forcing periods, not one; the dashed curve is the unstable period-1 orbit of harmonic balance."),
    ]},
    {"program": "ch07_ste", "title": "Chapter 7: static transmission error from a beam FE tooth model", "figures": [
        ("fig4[89]_*.png", "Figs. 48-49", "Deflection of one tooth pair loaded at two contact node pairs (constant thickness)."),
        ("fig5[01]_*.png", "Figs. 50-51", "The FE cantilever against the exact cubic deflection."),
        ("fig5[2-5]_*.png", "Figs. 52-55", "Two pairs in contact: the load shared by the constraint of a common transmission error."),
        ("fig56_*.png", "Fig. 56", "Bending moment of the fused beams."),
        ("fig57_*.png", "Fig. 57", "The involute tooth thickness used by the variable-thickness model."),
        ("fig5[89]_*.png", "Figs. 58-59", "Deformed teeth, one and two pairs in contact."),
        ("fig60_*.png", "Fig. 60", "STE over the mesh cycle for 100, 200, 300 N m: jumps where the second pair enters."),
        ("fig61_*.png", "Fig. 61", "Fourier coefficients of the STE: the excitation of chapter 8."),
        ("fig6[2-4]_*.png", "Figs. 62-64", "The refined 14-node model and its STE and coefficients."),
        ("ch07_extra_*.png", "supplement", "Convergence of the STE beyond 14 nodes."),
    ]},
    {"program": "ch08_gear_response", "title": "Chapter 8: the gear driven by its own static transmission error", "figures": [
        ("fig67_*.png", "Fig. 67", "Mesh stiffness k(t) = F0/e(t) over one mesh cycle for 100, 200, 300 N m with its mean kc: "
         "the jumps are the second tooth pair entering and leaving."),
        ("fig69_*.png", "Fig. 69", "RMS of the oscillating dynamic transmission error against mesh frequency, one harmonic, three "
         "torques and the linear closed-contact curve: contact is lost near resonance for every torque (the overhang)."),
        ("fig70_*.png", "Fig. 70", "The same with five harmonics: superharmonic resonances appear below the primary one."),
        ("fig70s_time*.png", "supplement", "x(t) and the contact force over two mesh periods at a contact-loss point."),
        ("fig70s_H*.png", "supplement", "Convergence in H of the 300 N m curve (H = 1, 5, 10, 20): 5 harmonics are not "
         "converged at the peak (2.8 % below H = 20), see the chapter README."),
        ("fig70s_param*.png", "supplement", "The 300 N m curve of the thesis' constant-stiffness model and of the "
         "parametric model it approximates (k(t) = F0/e(t)), see the chapter README."),
    ]},
    {"program": "ch09_backlash", "title": "Chapter 9: backlash limits the STE at high torque", "figures": [
        ("fig77_*.png", "Fig. 77", "STE over one mesh cycle with backlash (clip and adjacent-pair spring) and without, 100/200/300 N m: "
         "only 300 N m reaches the local normal backlash, near the ends of the single-pair zone."),
        ("fig77s_*.png", "supplement", "The local normal backlash b cos(mu) along the single-pair zone against the 300 N m STE."),
        ("fig78_*.png", "Fig. 78", "Fourier coefficients of the STE with and without backlash: only 300 N m changes, by a few per cent."),
        ("fig79_*.png", "Fig. 79", "Our STE coefficients with backlash; Parker, Vijayakar & Imajo's bars are not available and not drawn."),
        ("fig80_*.png", "Fig. 80", "DTE response with backlash, one harmonic, three torques and the linear closed-contact curve."),
        ("fig81_*.png", "Fig. 81", "The same with five harmonics."),
        ("fig82_*.png", "Fig. 82", "300 N m with and without backlash (both readings), H = 1 and 5, with a zoom on the peak: "
         "the peak drops by 1.3 % and moves up in frequency."),
    ]},
]

NOT_COMPUTABLE = [
    ("Figs. 1-4", "introduction: gear drives, engines and their data from other sources"),
    ("Fig. 5", "sketch of the pseudo-arc-length continuation method"),
    ("Fig. 6", "sketch of the mass-against-wall model"),
    ("Fig. 19", "sketch of the two-mass system"),
    ("Fig. 24", "sketch of the Comparin & Singh system"),
    ("Figs. 31-39", "sketches: tooth profile, line of action, pressure angle, gear-pair reference frames, forces and displacements"),
    ("Figs. 46-47", "sketches of the tooth model (teeth as beams and as springs)"),
    ("Fig. 65", "sketch of the limit positions for the angle of the tooth axis"),
    ("Fig. 66", "sketch of the 1-DOF gear model (after Ozguven & Houser)"),
    ("Fig. 68", "mesh stiffness found by Parker, Vijayakar & Imajo (2000): their data are not available"),
    ("Figs. 71-72, 83-84", "comparisons with the FE and experimental curves of Parker, Vijayakar & Imajo (2000): not available; our curves are drawn alone"),
    ("Figs. 73-76", "sketches of the base pitch along the line of action and of the backlash geometry"),
    ("Parker's curves in Figs. 60 and 79", "not available: our STE and coefficients are drawn alone, nothing in their place"),
]
