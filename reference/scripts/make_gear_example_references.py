#!/usr/bin/python3
"""Write reference/gear_examples/<name>.json, the references of the gearhb_gear examples.

Run:  /usr/bin/python3 reference/scripts/make_gear_example_references.py
Every "value" comes from a script that does not call gearhb:
  * geometry and ISO 6336-1 method B (stiffness, and K_v for the files with a speed range):
    gear_pair_closed_forms.py (closed forms);
  * the loaded STE numbers: gear_pair_beam_ste.py (the beam model written again in
    numpy / scipy), gear_pair_pe_ste.py for the potential-energy files, and for ch. 7's 8 node positions also the independent stepped-beam
    integrals of ch07_closed_form_ste.py (reference/ch07_ste.json);
plus the published values (FZG type C, ISO/TR 6336-30 Ex. 01, the thesis) recorded
beside ours as "published_value" / "thesis_value" with the reason for any gap.
"""
import json
import math
import pathlib
import subprocess

HERE = pathlib.Path(__file__).resolve().parent
OUT = HERE.parent / "gear_examples"


def run(script):
    vals = {}
    for line in subprocess.run(["/usr/bin/python3", str(HERE / script)], check=True, capture_output=True,
                               text=True).stdout.splitlines():
        ex, key, v = line.split()
        vals.setdefault(ex, {})[key] = float(v)
    return vals


GEO = run("gear_pair_closed_forms.py")
STE = run("gear_pair_beam_ste.py")
PE = run("gear_pair_pe_ste.py")
UNITS = {"N_per_m": "N/m", "_rpm": "rpm", "_um": "um", "_deg": "deg", "_m": "m"}
CLOSED = "reference/scripts/gear_pair_closed_forms.py (ISO 21771 involute closed forms, no gearhb)"
ISO = "reference/scripts/gear_pair_closed_forms.py: ISO 6336-1:2006 clause 9 method B written out (C9 x2^2), spur"
BEAM = ("reference/scripts/gear_pair_beam_ste.py: the same beam model written again in numpy/scipy "
        "(dense FE of each tooth, Hermite reading, exact sharing by brentq), no gearhb")


def unit(key):
    if key.startswith("iso6336_c"):
        return "N/(mm um)"
    for suffix, u in UNITS.items():
        if key.endswith(suffix) or ("_" + suffix.strip("_") + "_") in key:
            return u
    return "-"


def entry(key, value, source, tol, why, **extra):
    e = {"value": value, "unit": unit(key), "tolerance": tol, "why_tolerance": why, "source": source}
    e.update(extra)
    return e


def geometry_numbers(name, keys):
    out = {}
    for k in keys:
        out[k] = entry(k, GEO[name][k], CLOSED, {"rel": 1e-12},
                       "closed forms on both sides; only round-off (inv^-1 by Newton vs bisection) differs")
    return out


def iso_numbers(name):
    return {k: entry(k, GEO[name][k], ISO, {"rel": 1e-12}, "the same formula evaluated twice; round-off only")
            for k in ("iso6336_c_prime_th", "iso6336_c_prime", "iso6336_c_gamma_alpha")}


ISO_KV = ("reference/scripts/gear_pair_closed_forms.py: ISO 6336-1:2006 6.3 method B K_v written out (ISO 1328-1:1995 "
          "tolerances, case-hardened running-in, m_red from the file's inertias), no gearhb")


def iso_kv_numbers(name, torques):
    """ISO 6336-1 method B's K_v beside the computed one (issue 21 §1 figures): the same formulas
    written twice; ISO/TR 6336-30 Ex. 01's published K_v = 1.003 checks the library's in
    tests/unit/test_iso6336.cpp."""
    keys = ["iso_f_pb_um", "iso_f_f_alpha_um", "iso_tip_relief_um"]
    for i in torques:
        keys += ["iso_kv_resonance_speed_rpm_%d" % i, "iso_kv_peak_%d" % i]
    return {k: entry(k, GEO[name][k], ISO_KV, {"rel": 1e-12}, "the same formula evaluated twice; round-off only")
            for k in keys}


def loaded_ratio_entry(k, fine, source, name):
    """The loaded contact ratio: with tip relief a 2048-phase count of the independent model
    (`fine`), without it the geometric AE / pb of the closed forms (every pair on A-E loaded)."""
    if fine:
        return entry(k, fine[k], source + "; loaded pairs counted over 2048 phases", {"abs": 3e-3},
                     "the count converges as 2 / 2048 (two lift-off points a cycle); gearhb locates the "
                     "lift-off between its 64 phases by linear extrapolation of the pair force")
    geo = GEO.get(name) or GEO[name.rsplit("_", 1)[0]]   # thesis_pair_p8: the thesis pair's geometry
    return entry(k, geo["contact_ratio"], CLOSED, {"abs": 1e-12},
                 "no tip relief: every pair on A-E is loaded, so the loaded contact ratio is the geometric "
                 "AE / pb, found exactly from the samples (ends A and E exact)")


def ste_numbers(name, torques, source_name=None):
    src = STE[source_name or name]
    out = {}
    for i in torques:
        for k in ("ste_max_um_%d" % i, "ste_ptp_um_%d" % i, "mesh_stiffness_mean_N_per_m_%d" % i,
                  "single_pair_deflection_um_%d" % i):
            out[k] = entry(k, src[k], BEAM, {"rel": 1e-9},
                           "two implementations of one model: dense solves and Brent (1e-14) differ by round-off "
                           "(measured 1e-14); 1e-9 leaves margin, far below any modelling effect")
        k = "loaded_contact_ratio_%d" % i
        out[k] = loaded_ratio_entry(k, STE.get((source_name or name) + "_fine"), BEAM, source_name or name)
    return out


PE_SOURCE = ("reference/scripts/gear_pair_pe_ste.py: the potential-energy tooth of tests/pe_independent_check.py "
             "(Simpson in the centre-line coordinate, not the library's Gauss-Legendre in the pressure angle), "
             "linear Hertz, exact linear sharing; no gearhb")


def pe_numbers(name, torques):
    src = PE[name]
    out = {"method_potential_energy": entry("method_potential_energy", 1.0, "the file's model.method", {"abs": 0},
                                            "a flag")}
    for i in torques:
        for k in ("ste_max_um_%d" % i, "ste_ptp_um_%d" % i, "mesh_stiffness_mean_N_per_m_%d" % i,
                  "single_pair_deflection_um_%d" % i):
            out[k] = entry(k, src[k], PE_SOURCE, {"rel": 1e-9},
                           "two quadratures of one model (Gauss-Legendre 24 points in the pressure angle against "
                           "Simpson 20000 intervals in x): measured 2e-13 worst (FZG pinion, root below the base "
                           "circle), 1e-15 elsewhere; 1e-9 leaves margin, far below any modelling effect")
        k = "loaded_contact_ratio_%d" % i
        out[k] = loaded_ratio_entry(k, PE.get(name + "_fine"), PE_SOURCE, name)
    return out


def dynamics_numbers(torques, back_impact_torques=()):
    """The dynamics of a file with a speed range (issue 21 §2): checked by the run's own GSL rk8pd
    integration of the same mesh law (an independent integrator, hb/time_integration.hpp), never
    by a stored value of gearhb's."""
    out = {}
    for i in torques:
        n = str(i)
        out["time_integration_rel_diff_max_" + n] = entry(
            "time_integration_rel_diff_max_" + n, 0.0, "GSL rk8pd integrated to the periodic state of the same "
            "two-flank mesh law at stable points (check_time_integration_%s.csv)" % n, {"abs": 0.01},
            "issue 21 §2: HB and time integration within 1 % (DTE RMS and K_v) at every compared point")
        out["time_integration_points_" + n] = entry(
            "time_integration_points_" + n, 8.0, "dynamics.time_check_points", {"abs": 0},
            "issue 21 §2: at least 8 stable points per curve against time integration")
        out["mean_force_rel_dev_" + n] = entry(
            "mean_force_rel_dev_" + n, 0.0, "static balance of the mesh: mean(drive force - back force) = F0 "
            "(thesis §8.1), over every point of the curve", {"abs": 1e-9},
            "issue 21 §2: the mean mesh force equals F0 to 1e-9")
    for i in back_impact_torques:
        n = str(i)
        out["time_integration_back_impact_points_" + n] = entry(
            "time_integration_back_impact_points_" + n, 2.0, "check_time_integration_%s.csv" % n, {"abs": 1},
            "1 to 3: the check compares at least one point with back-flank impacts (a third of 8 points at most "
            "when the curve has more than two)")
    return out


def write(name, example_file, args, numbers, bad_inputs=None, extra=None):
    ref = {"example": name, "example_file": example_file, "regression_args": args, "numbers": numbers}
    if bad_inputs:
        ref["bad_inputs"] = bad_inputs
    if extra:
        ref.update(extra)
    (OUT / (name + ".json")).write_text(json.dumps(ref, indent=2) + "\n")


GEOM_KEYS = ["centre_distance_m", "operating_pressure_angle_deg", "contact_ratio", "path_of_contact_m", "base_pitch_m",
             "base_radius_1_m", "base_radius_2_m", "tip_radius_1_m", "tip_radius_2_m", "root_radius_1_m",
             "root_radius_2_m", "tip_thickness_1_m", "undercut", "undercut_z_min_1", "undercut_z_min_2"]

# --- thesis pair, continuous reading (ch. 8) ---------------------------------------------
n = geometry_numbers("thesis_pair", GEOM_KEYS)
n.update(iso_numbers("thesis_pair"))
n.update(ste_numbers("thesis_pair", [1, 2, 3]))
n["ste_max_um_3"]["thesis_value"] = 13.77
n["ste_max_um_3"]["note"] = ("chapter 8's continuous reading (chapters/ch08_gear_response/README.md: 13.978 um); the "
                             "thesis prints 13.77 for its 8-position reading (see thesis_pair_p8)")
n["mesh_stiffness_mean_N_per_m_3"]["thesis_value"] = 473.2e6
n["mesh_stiffness_mean_N_per_m_3"]["note"] = "chapter 8: 470.97 MN/m continuous, 473.29 on 8 positions (thesis 473.2)"
n["iso6336_c_gamma_alpha"]["note"] = "times b = 20 mm: 440.2 MN/m (ISO 6336-1 method B; reference/ch07_ste.json)"
n.update(dynamics_numbers([1, 2, 3]))
n.update(iso_kv_numbers("thesis_pair", [1, 2, 3]))
write("thesis_pair", "thesis_pair.json", ["--set", "plot=0"], n)

# --- thesis pair on ch. 7's 8 node positions ------------------------------------------------
ch07 = json.load(open(HERE.parent / "ch07_ste.json"))["numbers"]
n = ste_numbers("thesis_pair", [1, 2, 3], "thesis_pair_p8")
del n["single_pair_deflection_um_1"], n["single_pair_deflection_um_2"], n["single_pair_deflection_um_3"]
n["ste_max_um_3"] = entry("ste_max_um_3", ch07["ste_max_T3_um"]["value"],
                          "reference/ch07_ste.json ste_max_T3_um: reference/scripts/ch07_closed_form_ste.py "
                          "(stepped-beam integrals by scipy quad, no FE, no gearhb)", {"rel": 1e-8},
                          "independent closed-form evaluation of ch. 7's model, 10 digits", thesis_value=13.77,
                          note="ch. 7 README: 0.12 % below the printed 13.77")
n["mesh_stiffness_mean_N_per_m_3"] = entry(
    "mesh_stiffness_mean_N_per_m_3", ch07["mean_stiffness_T3_MN_per_m"]["value"] * 1e6,
    "reference/ch07_ste.json mean_stiffness_T3_MN_per_m (ch07_closed_form_ste.py)", {"rel": 1e-8},
    "independent closed-form evaluation of ch. 7's model, 10 digits", thesis_value=473.2e6,
    note="0.02 % above the printed 473.2 MN/m")
write("thesis_pair_p8", "thesis_pair.json", ["--set", "plot=0", "--set", "model.positions_per_base_pitch=8"], n)

# --- thesis pair with the long linear relief ---------------------------------------------------
n = ste_numbers("thesis_pair_relief", [1, 2, 3])
n["single_pair_deflection_um_3"]["note"] = ("the relief amount of the file (13.9165 um) is this number at 300 N m, "
                                            "rounded to 0.1 nm")
write("thesis_pair_relief", "thesis_pair_relief.json", ["--set", "plot=0"], n)

# --- the same relieved pair at light load: drive-flank loss and back-flank impacts ----------------
n = ste_numbers("thesis_pair_light_load", [1, 2])
n.update(dynamics_numbers([1, 2], back_impact_torques=[1]))
n.update(iso_kv_numbers("thesis_pair_light_load", [1, 2]))
write("thesis_pair_light_load", "thesis_pair_light_load.json", ["--set", "plot=0"], n)

# --- both on bearings (six DOFs): where the torsional model is not enough ---------------------------
n = ste_numbers("thesis_pair_six_dof", [1, 2, 3])
n.update(dynamics_numbers([1, 2, 3], back_impact_torques=[1, 2, 3]))
n.update(iso_kv_numbers("thesis_pair_six_dof", [1, 2, 3]))
write("thesis_pair_six_dof", "thesis_pair_six_dof.json", ["--set", "plot=0"], n)
n = ste_numbers("thesis_pair_light_load_six_dof", [1, 2])
n.update(dynamics_numbers([1, 2], back_impact_torques=[1]))
n.update(iso_kv_numbers("thesis_pair_light_load_six_dof", [1, 2]))
write("thesis_pair_light_load_six_dof", "thesis_pair_light_load_six_dof.json", ["--set", "plot=0"], n)

# --- FZG type C -------------------------------------------------------------------------------
n = geometry_numbers("fzg_c", GEOM_KEYS + ["tip_thickness_2_m"])
published = {"centre_distance_m": 91.5e-3, "contact_ratio": 1.4625, "base_radius_1_m": 33.829e-3,
             "base_radius_2_m": 50.743e-3, "tip_radius_1_m": 41.318e-3, "tip_radius_2_m": 59.272e-3,
             "path_of_contact_m": 19.43e-3, "base_pitch_m": 13.285e-3}
for k, v in published.items():
    n[k]["published_value"] = v
    n[k]["published_source"] = ("FZG type C test gear (DIN ISO 14635-1): m 4.5 mm, z 16/24, "
                                "x 0.1817/0.1715, a 91.5 mm")
n["contact_ratio"]["note"] = ("ours 1.462446 at a = 91.5 mm; the published 1.4625 is the same formula with the "
                              "published radii rounded to 1 um (1.46251), i.e. rounding in the last digit")
n.update(iso_numbers("fzg_c"))
for k in ("iso6336_c_prime_th", "iso6336_c_prime", "iso6336_c_gamma_alpha"):
    n[k]["note"] = ("shifted gears: needs the q' shift terms as ISO 6336-1 Table 9 pairs them (C4 x1, C5 x1/zn1, "
                    "C6 x2, C7 x2/zn2), fixed in commit 5f4444b; before it lib/iso6336.cpp paired C4..C7 with "
                    "the wrong variables and this check failed (c'_th 39.70)")
n.update(ste_numbers("fzg_c", [1, 2, 3]))
write("fzg_c", "fzg_c.json", ["--set", "plot=0"], n)

# --- ISO/TR 6336-30 Example 01, the helical pair as printed (issue 35) --------------------------------
HELIX_KEYS = ["overlap_ratio", "total_contact_ratio", "transverse_module_m", "transverse_pressure_angle_deg",
              "base_helix_angle_deg"]
n = geometry_numbers("iso_tr_6336_30_ex01", GEOM_KEYS + HELIX_KEYS)
n.update(iso_numbers("iso_tr_6336_30_ex01"))
n["iso6336_c_gamma_beta"] = entry("iso6336_c_gamma_beta", GEO["iso_tr_6336_30_ex01"]["iso6336_c_gamma_beta"], ISO,
                                  {"rel": 1e-12}, "the same formula evaluated twice; round-off only")
TR = "ISO/TR 6336-30:2017 Example 01 (shared GEARS.md)"
tr = {"iso6336_c_prime_th": 17.85584, "iso6336_c_prime": 12.37047, "iso6336_c_gamma_alpha": 17.46485,
      "iso6336_c_gamma_beta": 14.84512}
for k, v in tr.items():
    n[k]["published_value"] = v
    n[k]["published_source"] = TR
    n[k]["source"] = ISO.replace(", spur", ", helical (z_n = z / (cos^2 beta_b cos beta), c' with cos beta)")
for k in ("iso6336_c_gamma_alpha", "iso6336_c_gamma_beta"):
    n[k]["note"] = ("ours is 1.34e-4 above the TR's: the TR's eps_alpha = 1.549090 is that of the tip diameters "
                    "rounded to 0.01 mm (159.66 / 872.35 mm), ours 1.549342 that of the unrounded d + 2 m_n (1 + x) "
                    "(tests/unit/test_iso6336.cpp reproduces the TR's to 1e-5 with the rounded ones)")
for k in ("iso6336_c_prime_th", "iso6336_c_prime"):
    n[k]["note"] = "agrees with the TR to its printed digits (no eps_alpha in c'_th and c')"
n["centre_distance_m"]["published_value"] = 0.5
n["centre_distance_m"]["published_source"] = TR
n["overlap_ratio"]["published_value"] = 1.083369
n["overlap_ratio"]["published_source"] = TR + ": eps_beta = b sin(beta) / (pi m_n) as used for its K_v"
n.update(ste_numbers("iso_tr_6336_30_ex01", [1]))
for k in ("ste_max_um_1", "ste_ptp_um_1", "mesh_stiffness_mean_N_per_m_1", "single_pair_deflection_um_1"):
    n[k]["source"] = BEAM + "; sliced as its docstring says (issue 35: 20 slices, stagger eps_beta y / b)"
write("iso_tr_6336_30_ex01", "iso_tr_6336_30_ex01.json", ["--set", "plot=0"], n,
      extra={"published_not_run": {
        "K_v": {
                "published_value": 1.003,
                "published_source": "ISO/TR 6336-30:2017 Example 01 (shared GEARS.md): n1 360 rpm, grade 5, C_a 70 um, K_A 1, solid discs",
                "ours": 1.0031887,
                "checked_by": "tests/unit/test_pair_helical.cpp PairHelical.IsoTr6336_30Example01DynamicFactor (pair_iso6336_kv with the helix, the TR's C_a and reduced mass: 1.003 +- 0.0005)",
                "note": "not a key number of this file: it has no speed range and the TR data at hand give no relief start for its C_a = 70 um; the library's K_v formulas alone: Iso6336.DynamicFactorIsoTr6336_30Example01 (1.00319)"
        }
      }})
# --- the thesis pair made helical, potential energy, over its speed range (issue 35) ------------------
n = geometry_numbers("helical_pair", GEOM_KEYS + HELIX_KEYS)
n.update(iso_numbers("helical_pair"))
n["iso6336_c_gamma_beta"] = entry("iso6336_c_gamma_beta", GEO["helical_pair"]["iso6336_c_gamma_beta"], ISO,
                                  {"rel": 1e-12}, "the same formula evaluated twice; round-off only")
n.update(pe_numbers("helical_pair", [1, 2, 3]))
for k in [k for k in n if k.startswith(("ste_", "mesh_stiffness_", "single_pair_"))]:
    n[k]["source"] = PE_SOURCE + "; sliced as its docstring says (issue 35: 20 slices, stagger eps_beta y / b)"
n.update(dynamics_numbers([1, 2, 3]))
# No iso_kv_numbers: gear_pair_closed_forms.py writes ISO 6336-1's K_v for spur pairs only (z, eps_alpha,
# c_gamma_alpha); the helical K_v of the library is checked against ISO/TR 6336-30 Ex. 01's published 1.003
# (tests/unit/test_pair_helical.cpp, PairHelical.IsoTr6336_30Example01DynamicFactor).
write("helical_pair", "helical_pair.json", ["--set", "plot=0"], n)

# --- the same helical pair on bearings with an axial DOF per gear (issue 35 c) -------------------------
name = "helical_pair_six_dof"
f = json.load(open(HERE.parents[1] / "programs" / "gearhb_gear" / "examples" / (name + ".json")))
n = geometry_numbers(name, GEOM_KEYS + HELIX_KEYS)
n.update(ste_numbers(name, [1, 2, 3]))
for k in [k for k in n if k.startswith(("ste_", "mesh_stiffness_", "single_pair_"))]:
    n[k]["source"] = BEAM + "; sliced as its docstring says (issue 35: 20 slices, stagger eps_beta y / b)"
n.update(dynamics_numbers([1, 2, 3]))
beta = math.radians(f["helix_angle_deg"])
d1 = f["module"] / math.cos(beta) * f["gears"][0]["z"]   # reference diameter of gear 1 (ISO 21771)
for i, T in enumerate(f["torques"]):
    Fa = 2 * T / d1 * math.tan(beta)
    for g, sign in ((1, 1.0), (2, -1.0)):
        k = "axial_bearing_force_N_%d_%d" % (g, i + 1)
        n[k] = entry(k, sign * Fa, "closed form: the static axial bearing force F_t tan(beta), F_t = 2 T1 / d1 at the "
                     "reference circle, d1 = m_n z1 / cos(beta) (gear 2 the opposite sense)", {"rel": 1e-9},
                     "the mean of the HB orbit's axial coordinate times ka at the curve's first point: exact up to the "
                     "mean mesh force's balance (mean_force_rel_dev, 1e-9) and round-off", unit="N")
write(name, name + ".json", ["--set", "plot=0"], n)

# --- the ROSS test gear (petrobras/ross), beam model, consistent reading ------------------
n = geometry_numbers("ross_pair", GEOM_KEYS)
n["contact_ratio"]["published_value"] = 1.7897798668
n["contact_ratio"]["published_source"] = "ROSS (petrobras/ross) test gear documentation: z 62/62, m 2 mm, 20 deg, ha* 1"
n.update(iso_numbers("ross_pair"))
n.update(ste_numbers("ross_pair", [1, 2, 3]))
write("ross_pair", "ross_pair.json", ["--set", "plot=0"], n)

# --- the potential-energy method (model.method = potential_energy) ---------------------------------
for name in ("thesis_pair_pe", "thesis_pair_relief_pe", "ross_pair_pe", "fzg_c_pe"):
    write(name, name + ".json", ["--set", "plot=0"], pe_numbers(name, [1, 2, 3]))

# --- tooth contact by finite elements (model.method = fe) -------------------------------------------
# Checked against the FE's own mesh convergence (an independent check of the discretisation, not a
# stored output): the Richardson limits of reference/fe_tooth_contact.md section 1
# (DISABLED_FeToothContactStudy.MeshConvergence: element sizes times 1, 1/sqrt 2, 1/2, 64 phases, the
# files' largest torque), and for ROSS's deep web the body torsion against the annulus r_i..r_f in
# torsion, (1/r_i^2 - 1/r_f^2) / (4 pi G b), G = E / (2 (1 + nu)): a closed form.
FE_LIMITS = {  # mean and single-pair stiffness [N/m] at torque 3, Richardson limits
    "thesis_pair_fe": ("thesis_pair", 545.634e6, 375.923e6),
    "fzg_c_fe": ("fzg_c", 277.257e6, 227.074e6),
    "ross_pair_fe": ("ross_pair", 285.603e6, 230.604e6)}
FE_ROOT = {  # FE root stress peak [MPa] at torque 3, gears 1 and 2, at element sizes x 1/2; ISO sigma_F0 beside
    "thesis_pair_fe": ((163.24, 163.61), 167.87, 167.87),
    "fzg_c_fe": ((387.43, 376.37), 414.72, 402.48),
    "ross_pair_fe": ((192.13, 192.94), 198.94, 198.94)}
FE_ROOT_SOURCE = ("reference/fe_tooth_contact.md section 8: the FE at element sizes x 1/2 "
                  "(DISABLED_FeToothContactStudy.RootStress), largest torque, 64 phases")
FE_ROOT_WHY = ("sizes x 1, 1/sqrt 2, 1/2 give peaks 0.3-1.1 % apart (the peak of a flat stress maximum moves between "
               "the nodes of the fillet): 1.5 % bounds the default's discretisation error")
FE_SOURCE = ("reference/fe_tooth_contact.md section 1: Richardson limit of the FE at element sizes times 1, "
             "1/sqrt 2, 1/2 (DISABLED_FeToothContactStudy.MeshConvergence), largest torque, 64 phases")
FE_WHY = ("the default mesh's discretisation error: measured 0.02-0.05 % against the limit (observed orders "
          "2.8-3.9); 0.5 % is the bound the default mesh is held to (issue 33 asks for 1 %)")
for name, (geo_name, k_mean, k_single) in FE_LIMITS.items():
    f = json.load(open(HERE.parents[1] / "programs" / "gearhb_gear" / "examples" / (name + ".json")))
    F = f["torques"][2] / GEO[geo_name]["base_radius_1_m"]
    n = {"method_fe": entry("method_fe", 1.0, "the file's model.method", {"abs": 0}, "a flag"),
         "mesh_stiffness_mean_N_per_m_3": entry("mesh_stiffness_mean_N_per_m_3", k_mean, FE_SOURCE, {"rel": 5e-3},
                                                FE_WHY),
         "single_pair_deflection_um_3": entry("single_pair_deflection_um_3", F / k_single * 1e6,
                                              FE_SOURCE + "; F = T1 / rb1 / k_single", {"rel": 5e-3}, FE_WHY)}
    for i in (1, 2, 3):
        k = "loaded_contact_ratio_%d" % i
        n[k] = loaded_ratio_entry(k, None, CLOSED, geo_name)
    if name == "ross_pair_fe":
        g = f["gears"][0]
        G = g["E"] / (2 * (1 + g["nu"]))
        rf = GEO[geo_name]["root_radius_1_m"]
        c = (1 / g["rim_radius"] ** 2 - 1 / rf ** 2) / (4 * math.pi * G * g["b"])
        for j in (1, 2):
            k = "fe_body_torsion_compliance_%d_rad_per_Nm" % j
            n[k] = entry(k, c, "the annulus r_i..r_f in torsion, (1/r_i^2 - 1/r_f^2) / (4 pi G b): closed form",
                         {"rel": 1e-2}, "the annulus leaves out the teeth, which stiffen only the outer edge; with "
                         "r_i / r_f = 0.29 the compliance sits at the bore (measured 0.16 %); for the thesis and "
                         "FZG rims (r_i / r_f 0.57-0.87) the teeth matter (3-7 %), so only ROSS is checked so",
                         unit="rad/(N m)")
    fine, iso1, iso2 = FE_ROOT[name]
    for j, iso in ((1, iso1), (2, iso2)):
        k = "fe_root_stress_max_MPa_%d_3" % j
        n[k] = entry(k, fine[j - 1], FE_ROOT_SOURCE, {"rel": 1.5e-2}, FE_ROOT_WHY, unit="MPa",
                     note="ISO 6336-3 method B's nominal sigma_F0 for the same load: %.2f MPa (a comparison, "
                          "not a check: ISO's 30-degree critical section approximates where the FE finds the peak)"
                          % iso)
    if "speed" in f:
        n.update(dynamics_numbers([1, 2, 3]))
    write(name, name + ".json", ["--set", "plot=0"], n)

print("wrote", sorted(p.name for p in OUT.glob("*.json")))
