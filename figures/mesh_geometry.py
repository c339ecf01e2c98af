"""Figs. 65 and 75 of the thesis: geometric constructions on the line of action, drawn from
the numbers the programs write (ch07 tooth_axis_angles.csv / geometry.csv, ch09
backlash_geometry.csv), not from a sketch.

Frame: the lower gear's centre O2 at the origin, the centre line vertical, the pitch point C at
(0, r); the line of action through C at -alpha to the horizontal is tangent to the base circle
at T2 = rb (sin alpha, cos alpha); a point at signed distance s from C along it (towards T2
positive) is C + s (cos alpha, -sin alpha). E lies between C and T2, A on the other side.
"""
import math

import matplotlib.pyplot as plt
from style import COMPARISON_COLOURS

PRINTED_BN_E_PRIME_UM = "13.5"   # thesis §9 p. 80-84 (reference/ch09_backlash.json bn_E_prime_um_thesis)
AXIS, PERP, LOA, CENTRE, TANGENT = "C1", "C0", "C2", "k", "0.55"   # the thesis' colour code of Fig. 65


def on_line(r, alpha, s):
    return (s * math.cos(alpha), r - s * math.sin(alpha))


def ray(ax, p, angle, length, **kw):
    ax.plot([p[0] - length * math.cos(angle), p[0] + length * math.cos(angle)],
            [p[1] - length * math.sin(angle), p[1] + length * math.sin(angle)], **kw)


def tooth_axis_figure(angles, geometry, alpha_deg, path):
    """Fig. 65: the tooth axis along the centre line, along O2E and along O2A; the angle between
    its perpendicular and the line of action is alpha, alpha - beta and alpha + epsilon."""
    a = math.radians(alpha_deg)
    rb, AC, CE = geometry["base_radius"], geometry["AC"], geometry["CE"]
    r = rb / math.cos(a)
    A, C, E = on_line(r, a, -AC), (0.0, r), on_line(r, a, CE)
    ours = angles["corrected_rb_tan"]
    thesis = angles["thesis_printed_values"]
    cases = [("axis along the centre line", C, 0.0, r"$\alpha$ = %.2f°" % alpha_deg, "cos α"),
             ("axis along $O_2E$ (tooth at E)", E, math.atan2(E[0], E[1]),
              r"$\alpha - \beta$, $\beta$ = %.2f° (thesis %.2f°)" % (ours["beta_deg"], thesis["beta_deg"]),
              "cos(α − β) = %.4f" % ours["cos_alpha_minus_beta"]),
             ("axis along $O_2A$ (tooth at A)", A, math.atan2(A[0], A[1]),
              r"$\alpha + \varepsilon$, $\varepsilon$ = %.2f° (thesis %.2f°)" % (ours["epsilon_deg"], thesis["epsilon_deg"]),
              "cos(α + ε) = %.4f" % ours["cos_alpha_plus_epsilon"])]
    fig, axes = plt.subplots(1, 3, figsize=(12.6, 5.0))
    half = 1.6 * AC
    for ax, (title, P, tilt, angle_text, scale) in zip(axes, cases):
        ax.plot([0, 0], [r - 2.2 * half, r + half], color=CENTRE, lw=1.2, label="centre line $O_2 O_1$")
        ax.plot([-half, half], [r, r], color=TANGENT, lw=1, ls="--", label="perpendicular to the centre line at C")
        ax.plot([A[0], E[0]], [A[1], E[1]], color=LOA, lw=2.4, label="path of contact A-E (line of action)")
        # the tooth axis through P (direction from O2 to P, tilted by `tilt` from the vertical) and its perpendicular
        ax.plot([P[0] - 1.3 * half * math.sin(tilt), P[0] + 0.6 * half * math.sin(tilt)],
                [P[1] - 1.3 * half * math.cos(tilt), P[1] + 0.6 * half * math.cos(tilt)],
                color=AXIS, lw=2, label="tooth axis")
        ray(ax, P, -tilt, 0.9 * half, color=PERP, lw=1.5, label="perpendicular to the tooth axis")
        for name, Q in (("A", A), ("C", C), ("E", E)):
            ax.plot(*Q, "ko", ms=4)
            ax.annotate(name, Q, xytext=(4, 5), textcoords="offset points", fontsize=10, fontweight="bold")
        ax.set_title("%s\nangle (perpendicular, line of action) = %s\nforce on the beam scaled by %s"
                     % (title, angle_text, scale), fontsize=8.5)
        ax.set_aspect("equal")
        ax.set_xlim(-half, half)
        ax.set_ylim(r - 1.6 * half, r + 0.9 * half)
        ax.set_xticks([])
        ax.set_yticks([])
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, fontsize=8, loc="lower center", ncol=3, frameon=True)
    fig.suptitle("Fig. 65: limit positions of the tooth axis on the path of contact (thesis gear, $O_2$ below)\n"
                 "angles with $T_2C = r_b \\tan\\alpha$, the thesis' printed reading in brackets "
                 "(ch07 tooth_axis_angles.csv)", fontsize=9.5)
    fig.subplots_adjust(left=0.02, right=0.98, top=0.78, bottom=0.16, wspace=0.08)
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def backlash_limit_figure(bg, path):
    """Fig. 75: contact at E' on the driving flank while the adjacent pair is at A: the tangential
    direction at A (perpendicular to O2A) is turned by epsilon and the one at E' (perpendicular to
    O1E') by epsilon', so the nominal backlash is scaled by cos(mu), mu = alpha + epsilon + epsilon'."""
    ex, th = bg["exact"], bg["thesis"]
    a = math.radians(ex["alpha_deg"])
    rb, AC, CEp = ex["rb_mm"], ex["AC_mm"], ex["CE_prime_mm"]
    r = rb / math.cos(a)
    A, C, Ep = on_line(r, a, -AC), (0.0, r), on_line(r, a, CEp)
    # The tangent (circumferential direction) at a point is perpendicular to the radius to it: at A
    # (lower gear, O2A leaning left by |eps_A|) it rises to the right by |eps_A|, at E' (upper gear,
    # O1 at (0, 2r)) by eps_E; with the line of action at -alpha the angles are alpha + epsilon and
    # alpha + epsilon' (ch09 README: atan(T P / rb) at P).
    eps_A = math.atan2(A[0], A[1])             # O2A from the centre line (negative: A left of it)
    eps_E = math.atan2(Ep[0], 2 * r - Ep[1])   # O1E' from the centre line
    half = 1.5 * AC
    fig, ax = plt.subplots(figsize=(8.6, 6.2))
    ax.plot([0, 0], [r - 1.4 * half, r + 1.4 * half], color=CENTRE, lw=1.2, label="centre line $O_2 O_1$")
    ax.plot([A[0] - 0.3 * half, Ep[0] + 0.6 * half], [A[1] + 0.3 * half * math.tan(a), Ep[1] - 0.6 * half * math.tan(a)],
            color=LOA, lw=2.4, label="line of action (A-E')")
    ray(ax, C, 0.0, 0.8 * half, color=TANGENT, lw=1, ls="--", label=r"tangent at C: $\mu = \alpha$")
    ray(ax, A, -eps_A, 0.7 * half, color=COMPARISON_COLOURS[0], lw=1.8,
        label=r"tangent at A (lower gear): turned by $\varepsilon$ = %.2f° (thesis %.2f°)" % (ex["epsilon_deg"], th["epsilon_deg"]))
    ray(ax, Ep, eps_E, 0.7 * half, color=COMPARISON_COLOURS[1], lw=1.8,
        label=r"tangent at E' (upper gear): turned by $\varepsilon'$ = %.3f° (thesis %.3f°)"
        % (ex["epsilon_prime_deg"], th["epsilon_prime_deg"]))
    for name, Q in (("A", A), ("C", C), ("E'", Ep)):
        ax.plot(*Q, "ko", ms=4)
        ax.annotate(name, Q, xytext=(4, 6), textcoords="offset points", fontsize=11, fontweight="bold")
    ax.text(0.98, 0.04, "CE' = p_b - AC = %.3f mm" % CEp, transform=ax.transAxes, fontsize=8, ha="right")
    ax.set_title("Fig. 75: limit condition for the normal backlash: contact at E', the adjacent pair at A\n"
                 r"$\mu(E') = \alpha + \varepsilon + \varepsilon'$ = %.2f° (thesis %.2f°): "
                 r"$b_n = b \cos\mu$ = %.2f µm" "\n(with the thesis' angles %.2f µm, printed truncated as %s µm), "
                 "against %.2f µm at C"
                 % (ex["mu_E_prime_deg"], th["mu_E_prime_deg"], ex["bn_E_prime_um"], th["bn_E_prime_um"],
                    PRINTED_BN_E_PRIME_UM, ex["bn_C_um"]),
                 fontsize=9)
    ax.set_aspect("equal")
    ax.set_xlim(-1.3 * half, 1.3 * half)
    ax.set_ylim(r - 0.75 * half, r + 0.6 * half)
    ax.set_xticks([])
    ax.set_yticks([])
    handles, labels = ax.get_legend_handles_labels()
    fig.legend(handles, labels, fontsize=7.5, loc="lower center", ncol=1, frameon=True)
    fig.subplots_adjust(left=0.03, right=0.97, top=0.85, bottom=0.24)
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path
