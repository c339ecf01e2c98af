#!/usr/bin/env python3
"""The browsable report build/figures/index.html (`make figures` writes it).

    report.py BUILD_DIR            write BUILD_DIR/figures/index.html
    report.py --check INDEX.html   exit 1 unless every image the page links exists

At the top: a table from thesis figure number to image. Then, per chapter: every figure
with its thesis figure number and its own caption (what it shows, what to notice:
figures/captions.py); the chapter's key numbers, each with three things:
  - the thesis value (or "not printed": chapters 2-6 of the thesis print figures, not numbers;
    a claim in words, the reference's "thesis_text", is shown and marked as differing),
  - ours (this run, build/data/<chapter>/key_numbers.json),
  - the verdict of the independent check (reference/<chapter>.json: a closed form, a second
    method, an independent script), and, where ours and the thesis differ beyond the thesis'
    printed digits, the deviation and its reason (the reference's "note", from the README);
and the chapter's deviations from the thesis, copied from its README. A reference number
made by the quick run that counts the run's own points ("quick_run_only" in the reference:
CTest checks it on the quick run) is shown, never compared with the full run: a report
never shows a failure that is not one. Last, the thesis figures that cannot be computed.
Static HTML, no JavaScript; a figure opens full size when clicked.
"""
import csv
import html
import json
import math
import pathlib
import re
import struct
import sys

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from captions import (CHAPTERS, GEAR_CAPTIONS, GEAR_CAPTIONS_HELICAL, GEAR_CAPTIONS_NO_RELIEF, NOT_COMPUTABLE,  # noqa: E402
                      FRC_CAPTIONS, PLANETARY_CAPTIONS, TOOL_CAPTIONS)

STYLE = """body{font-family:sans-serif;max-width:1300px;margin:auto;padding:1em;color:#222}
h1{font-size:1.5em}h2{border-bottom:1px solid #ccc;margin-top:2em}
figure{display:inline-block;width:48%;vertical-align:top;margin:0 1% 1.5em 0}
figure.wide{width:98%}
figure img{width:100%;border:1px solid #ddd}figcaption{font-size:.85em}
table{border-collapse:collapse;font-size:.8em;margin:.5em 0}td,th{border:1px solid #ccc;padding:2px 6px;vertical-align:top}
td.num{text-align:right;white-space:nowrap}
.pass{color:#070}.fail{color:#b00;font-weight:bold}.none{color:#777}.differs{color:#a50}
nav a{margin-right:1em}ul.index{columns:2;font-size:.85em}.dev li{margin-bottom:.3em;font-size:.9em}"""

# Units shown scaled for people: (unit, threshold, factor, shown unit).
SCALED_UNITS = [("N/m", 1e5, 1e-6, "MN/m")]


def people_unit(unit, value):
    """(factor, unit) to show a value of this unit: 473294316.9 N/m as 473.29 MN/m."""
    for u, threshold, factor, shown in SCALED_UNITS:
        if unit == u and abs(value) >= threshold:
            return factor, shown
    return 1.0, unit


def fmt(v, digits=6):
    """A number for people: integers as integers, otherwise `digits` significant digits, no
    exponent unless the number is tiny or huge."""
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return ""
    if float(v) == int(v) and abs(v) < 1e9:
        return "%d" % int(v)
    if v != 0 and (abs(v) < 1e-3 or abs(v) >= 1e7):
        return "%.3g" % v
    return "%.*g" % (digits, v)


def with_unit(text, unit):
    return text if unit in ("", "-") else "%s %s" % (text, unit)


def tolerance_text(tol, value, factor, unit):
    """'exact', '± 0.005 rad/s', 'rel. 1e-09', or a range '10 to 1000' when the allowed band
    is wider than half the value."""
    a, r = tol.get("abs", 0.0), tol.get("rel", 0.0)
    allowed = max(a, r * abs(value))
    if allowed == 0:
        return "exact"
    if value != 0 and allowed >= 0.5 * abs(value):
        return "range %s to %s" % (fmt((value - allowed) * factor, 4), with_unit(fmt((value + allowed) * factor, 4), unit))
    if r and r * abs(value) >= a:
        return "rel. %g" % r
    return "± %s" % with_unit(fmt(a * factor, 3), unit)


def printed_digits(x):
    """Significant digits the thesis printed for x (trailing zeros of an integer not counted)."""
    s = repr(float(x)).lower()
    if "e" in s:
        s = s.split("e")[0]
    s = s.lstrip("-")
    if s.endswith(".0"):
        s = s[:-2].rstrip("0") or "0"
    digits = s.replace(".", "").lstrip("0")
    return max(len(digits), 1)


def agrees_with_thesis(ours, thesis):
    """True when ours, rounded to the digits the thesis printed, is the thesis' number."""
    if thesis == 0:
        return ours == 0
    n = printed_digits(thesis)
    e = math.floor(math.log10(abs(thesis)))
    unit = 10.0 ** (e - n + 1)
    return abs(ours - thesis) <= 0.5 * unit * (1 + 1e-9)


def verdict(r, ours):
    """(text, css class) of the independent check for one number."""
    if ours is None:
        return "not in this run", "none"
    if r.get("quick_run_only"):
        return ("not compared: the reference %s is of the quick run (%s); CTest checks it there"
                % (fmt(r["value"]), r["quick_run_only"])), "none"
    tol = r.get("tolerance", {})
    allowed = max(tol.get("abs", 0.0), tol.get("rel", 0.0) * abs(r["value"]))
    return ("agrees", "pass") if abs(ours - r["value"]) <= allowed else ("FAIL", "fail")


def thesis_against_ours(r, ours, factor, unit):
    """(thesis cell, comparison cell) for one number."""
    thesis, note = r.get("thesis_value"), r.get("note", "")
    if thesis is None and r.get("thesis_text"):   # a claim in words, which ours contradicts (the note says how)
        return "<i>%s</i>" % html.escape(r["thesis_text"]), "<span class='differs'>differs</span>. %s" % html.escape(note)
    if thesis is None:
        return "<span class='none'>not printed</span>", html.escape(note)
    cell = with_unit(("%g" % (thesis * factor)), unit)
    if ours is None:
        return cell, html.escape(note)
    if agrees_with_thesis(ours, thesis):
        return cell, "<span class='pass'>agrees to the printed digits</span>" + (
            ". " + html.escape(note) if note else "")
    dev = ("%+.2g %s" % ((ours - thesis) * factor, unit)) if thesis == 0 else "%+.2f %%" % (100 * (ours - thesis) / abs(thesis))
    return cell, "<span class='differs'>differs: %s</span>. %s" % (html.escape(dev), html.escape(note))


def key_number_rows(ref_file, data_dir):
    if not ref_file.exists():
        return []
    ref = json.load(open(ref_file))["numbers"]
    for r in ref.values():   # a gear example's published value (ISO/TR, FZG drawing) takes the thesis column
        if "thesis_value" not in r and "published_value" in r:
            r["thesis_value"] = r["published_value"]
    ours_file = data_dir / "key_numbers.json"
    ours_all = json.load(open(ours_file)) if ours_file.exists() else {}
    rows = []
    for name, r in ref.items():
        ours = ours_all[name]["value"] if name in ours_all else None
        factor, unit = people_unit(r.get("unit", ""), r["value"])
        text, css = verdict(r, ours)
        thesis_cell, comparison = thesis_against_ours(r, ours, factor, unit)
        rows.append("<tr><td>%s</td><td class='num'>%s</td><td class='num'>%s</td><td class='num'>%s<br>"
                    "<span class='none'>%s</span></td><td class='%s'>%s</td><td>%s</td></tr>" % (
                        html.escape(name), thesis_cell,
                        "" if ours is None else html.escape(with_unit(fmt(ours * factor), unit)),
                        html.escape(with_unit(fmt(r["value"] * factor, 10), unit)),
                        html.escape(tolerance_text(r.get("tolerance", {}), r["value"], factor, unit)),
                        css, html.escape(text), comparison))
    return rows


KEY_TABLE_HEAD = ("<table><tr><th>number</th><th>thesis</th><th>ours (this run)</th>"
                  "<th>independent reference<br>and tolerance</th><th>check</th>"
                  "<th>thesis against ours</th></tr>")


def markdown_inline(text):
    """The README's inline markdown (**bold**, `code`) as HTML."""
    text = html.escape(text)
    text = re.sub(r"\*\*(.+?)\*\*", r"<b>\1</b>", text)
    return re.sub(r"`([^`]+)`", r"<code>\1</code>", text)


def readme_deviations(readme):
    """The bullets of the README's sections on deviations from the thesis: [(heading, [items])]."""
    if not readme.exists():
        return []
    sections, current = [], None
    for line in readme.read_text().splitlines():
        if line.startswith("#"):
            heading = line.lstrip("#").strip()
            wanted = re.search(r"deviation|thesis errors|the kc question", heading, re.I)
            current = (heading, []) if wanted else None
            if current:
                sections.append(current)
        elif current is not None:
            if re.match(r"\s*[*-] ", line):
                current[1].append(line.strip()[2:])
            elif line.strip() and current[1] and line.startswith(" "):
                current[1][-1] += " " + line.strip()
    return [(h, items) for h, items in sections if items]


def figure_html(name, thesis_fig, caption, wide):
    return ('<figure%s id="%s"><a href="%s"><img src="%s" alt="%s"></a><figcaption><b>%s</b> '
            '(<code>%s</code>): %s</figcaption></figure>' % (
                " class='wide'" if wide else "", name, name, name, name, html.escape(thesis_fig), name,
                html.escape(caption)))


def is_wide(png):
    """A multi-panel figure (aspect >= 1.9 or wider than 1300 px) is shown at full width: at half
    width its panels are illegible."""
    with open(png, "rb") as f:
        head = f.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n":
        return False
    w, h = struct.unpack(">II", head[16:24])
    return w >= 1300 or w >= 1.9 * h


def chapter_figures(ch, fig_dir):
    """[(file name, thesis figure, caption, wide)] of the chapter's figures that exist."""
    out = []
    for pattern, thesis_fig, caption in ch["figures"]:
        for path in sorted(fig_dir.glob(pattern)):
            out.append((path.name, thesis_fig, caption, is_wide(path)))
    return out


def chapter_section(build, ch, fig_dir):
    program = ch["program"]
    out = ['<h2 id="%s">%s</h2>' % (program, html.escape(ch["title"]))]
    out.append("<p>Program <code>build/bin/%s</code>; data in <code>build/data/%s/</code>; README "
               "<code>chapters/%s/README.md</code>.</p>" % (program, program, program))
    figs = chapter_figures(ch, fig_dir)
    for pattern, thesis_fig, _ in ch["figures"]:
        if not list(fig_dir.glob(pattern)):
            out.append("<p class='none'>%s (%s): not drawn in this run.</p>" % (html.escape(pattern), thesis_fig))
    out += [figure_html(*f) for f in figs]
    rows = key_number_rows(HERE.parent / "reference" / (program + ".json"), build / "data" / program)
    if rows:
        out.append("<h3>Key numbers: thesis, ours, independent check (reference/%s.json)</h3>" % program)
        if "not printed" in "".join(rows):
            out.append("<p class='none'>\"not printed\": the thesis gives no value for that number (its chapters "
                       "2-6 show figures only); what it says in words is compared in the deviations below.</p>")
        out.append(KEY_TABLE_HEAD)
        out += rows
        out.append("</table>")
    devs = readme_deviations(HERE.parent / "chapters" / program / "README.md")
    if devs:
        out.append("<h3>Deviations from the thesis (chapters/%s/README.md)</h3>" % program)
        for heading, items in devs:
            out.append("<p><i>%s</i></p><ul class='dev'>" % html.escape(heading))
            out += ["<li>%s</li>" % markdown_inline(i) for i in items]
            out.append("</ul>")
    return out, figs


def thesis_number_key(thesis_fig):
    m = re.search(r"\d+", thesis_fig)
    return (0, int(m.group())) if m and thesis_fig.startswith("Fig") else (1, 0)


def figure_index(all_figs):
    """Table at the top: thesis figure number -> image(s)."""
    by_fig = {}
    for name, thesis_fig, _, _ in all_figs:
        by_fig.setdefault(thesis_fig, []).append(name)
    out = ["<h2 id='index'>Thesis figure to image</h2><ul class='index'>"]
    for thesis_fig in sorted(by_fig, key=lambda f: (thesis_number_key(f), f)):
        links = ", ".join('<a href="#%s">%s</a>' % (n, n) for n in by_fig[thesis_fig])
        out.append("<li><b>%s</b>: %s</li>" % (html.escape(thesis_fig), links))
    out.append("</ul>")
    return out


METHOD_NAMES = {"beam": "beam", "pe": "potential energy", "fe": "finite elements"}
CHART_NAMES = {"beam": "beam, consistent reading", "beam_thesis": "beam, thesis reading", "pe": "potential energy",
               "pe_coupled": "potential energy + body coupling",
               "fe": "FE, default sizes", "iso": "ISO 6336-1"}


def largest_torque_stiffness(run_dir):
    """(T1, mean k) at the run's largest torque, or None."""
    try:
        params = json.load(open(run_dir / "params.json"))
        kn = json.load(open(run_dir / "key_numbers.json"))
        i = max(range(len(params["torques"])), key=lambda j: params["torques"][j]) + 1
        return params["torques"][i - 1], kn["mesh_stiffness_mean_N_per_m_%d" % i]["value"], kn
    except (OSError, KeyError, ValueError, TypeError):
        return None


def gear_caption(figure, params):
    """The caption of one figure of a gear run, true for this run: the relief's sentences only
    where the file has a relief."""
    relieved = any(isinstance(g, dict) and isinstance(g.get("tip_relief"), dict) and
                   (g["tip_relief"].get("amount") or 0) > 0 for g in params.get("gears", []))
    caption = GEAR_CAPTIONS.get(figure, "")
    if not relieved:
        caption = GEAR_CAPTIONS_NO_RELIEF.get(figure, caption)
    if (params.get("helix_angle_deg") or 0) > 0:
        caption = GEAR_CAPTIONS_HELICAL.get(figure, caption)
    return caption


def tooth_model_section(run_dir):
    """Which tooth model to trust: the run's mean stiffness at its largest torque beside ISO and the
    other methods' runs of the same pair (the sibling example files <pair>, <pair>_pe, <pair>_fe),
    and the verdict of the tooth-model chart (figures/tooth_model_chart.py, tooth_models.csv)."""
    me = largest_torque_stiffness(run_dir)
    if not me:
        return []
    pair = re.sub(r"_(pe|fe)$", "", run_dir.name)
    out = ["<h2>Which tooth model to trust</h2><table><tr><th>run</th><th>method</th><th>T1 [N m]</th>"
           "<th>mean k [MN/m]</th><th>against this run</th></tr>"]
    for suffix, method in (("", "beam"), ("_pe", "pe"), ("_fe", "fe")):
        other = largest_torque_stiffness(run_dir.parent / (pair + suffix))
        if other:
            out.append("<tr><td>%s%s</td><td>%s</td><td class='num'>%g</td><td class='num'>%.1f</td>"
                       "<td class='num'>%+.1f %%</td></tr>" % (
                           html.escape(pair + suffix), " (this run)" if pair + suffix == run_dir.name else "",
                           METHOD_NAMES[method], other[0], other[1] / 1e6, 100 * (other[1] / me[1] - 1)))
    iso = me[2].get("iso6336_c_gamma_alpha_N_per_m", {}).get("value")
    if iso:
        out.append("<tr><td>ISO 6336-1 method B</td><td>c_gamma_alpha b</td><td class='num'>%g</td>"
                   "<td class='num'>%.1f</td><td class='num'>%+.1f %%</td></tr>"
                   % (me[0], iso / 1e6, 100 * (iso / me[1] - 1)))
    out.append("</table>")
    chart = run_dir.parent / "tooth_models" / "tooth_models.csv"
    rows = list(csv.DictReader(open(chart))) if chart.exists() else []
    mine = {r["model"]: float(r["k_error"]) for r in rows if r["pair"] == pair}
    if mine:
        verdict = ("Verdict (gear_tooth_models.png, this pair, same force and bores for every model): trust the "
                   "finite elements (%+.2f %% from their converged limit); " % (100 * mine["fe"]) +
                   ", ".join("%s %+.0f %%" % (CHART_NAMES[m], 100 * mine[m]) for m in ("pe", "pe_coupled", "beam", "beam_thesis", "iso")))
    elif rows:
        fast = [abs(float(r["k_error"])) for r in rows if r["model"] in ("pe", "pe_coupled", "beam", "beam_thesis")]
        verdict = ("Verdict (gear_tooth_models.png, three other pairs): the finite elements are within 0.5 %% of "
                   "their converged limit, the fast models %.0f-%.0f %% off in mean stiffness: quote the FE's."
                   % (100 * min(fast), 100 * max(fast)))
    else:
        verdict = "No tooth-model chart in this build (make figures draws it)."
    out.append("<p>%s</p>" % html.escape(verdict))
    return out


def gear_run_page(build, run_dir, fig_dir):
    """A page per gear-pair run of make figures (build/data/gearhb_gear/<example>/): its
    figures, its key numbers against reference/gear_examples/<example>.json (the published
    or thesis value where there is one, ours, the independent reference and the check), and
    the run's other key numbers. Returns (page file name, title, figure names)."""
    stem = run_dir.name
    params = json.load(open(run_dir / "params.json")) if (run_dir / "params.json").exists() else {}
    title = params.get("name", stem) if isinstance(params.get("name"), str) else stem
    # This run's own figures only: the copies of the PNGs in its folder (a prefix match would
    # also take gear_<stem>_pe_*.png and the other runs whose names start with this one's).
    figs = sorted("gear_%s_%s" % (stem, p.name) for p in run_dir.glob("*.png")
                  if (fig_dir / ("gear_%s_%s" % (stem, p.name))).exists())
    out = ["<h1>%s</h1>" % html.escape(title),
           "<p><a href='index.html'>back to the report</a>. Gear file "
           "<code>programs/gearhb_gear/examples/%s.json</code>, run by <code>make figures</code> into "
           "<code>build/data/gearhb_gear/%s/</code> (README <code>programs/gearhb_gear/README.md</code>).</p>"
           % (html.escape(stem), html.escape(stem))]
    prefix = "gear_%s_" % stem
    out += [figure_html(f, "gearhb_gear", gear_caption(f[len(prefix):], params), is_wide(fig_dir / f)) for f in figs]
    ref = HERE.parent / "reference" / "gear_examples" / (stem + ".json")
    rows = key_number_rows(ref, run_dir)
    checked = set(json.load(open(ref))["numbers"]) if ref.exists() else set()
    if rows:
        out.append("<h2>Key numbers checked by CTest (reference/gear_examples/%s.json)</h2>" % html.escape(stem))
        out.append(KEY_TABLE_HEAD.replace("<th>thesis</th>", "<th>published or thesis</th>")
                   .replace("<th>thesis against ours</th>", "<th>published against ours</th>"))
        out += rows
        out.append("</table>")
    out += tooth_model_section(run_dir)
    ours = json.load(open(run_dir / "key_numbers.json")) if (run_dir / "key_numbers.json").exists() else {}
    rest = [(k, v) for k, v in ours.items() if k not in checked]
    if rest:
        out.append("<h2>The run's other key numbers (no independent reference)</h2><table>"
                   "<tr><th>number</th><th>value</th><th>unit</th></tr>")
        out += ["<tr><td>%s</td><td class='num'>%s</td><td>%s</td></tr>"
                % (html.escape(k), html.escape(fmt(v["value"])), html.escape(v.get("unit", ""))) for k, v in rest]
        out.append("</table>")
    page = ("<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>%s</title><style>%s</style></head>"
            "<body>%s</body></html>\n" % (html.escape(title), STYLE, "\n".join(out)))
    name = "gear_%s.html" % stem
    tmp = fig_dir / (name + ".tmp")
    tmp.write_text(page)
    tmp.replace(fig_dir / name)
    return name, title, figs


def tool_figures(fig_dir):
    """[(file name, label, caption, wide)] of the tools' figures with a caption: the comparisons of
    TOOL_CAPTIONS and every gearhb_frc and gearhb_planetary run's <prefix>_<example>_<figure>."""
    out = [(name, "gear tools", caption, is_wide(fig_dir / name))
           for name, caption in TOOL_CAPTIONS.items() if (fig_dir / name).exists()]
    for prefix, program, captions in (("frc", "gearhb_frc", FRC_CAPTIONS),
                                      ("planetary", "gearhb_planetary", PLANETARY_CAPTIONS)):
        for path in sorted(fig_dir.glob(prefix + "_*.png")):
            for figure, caption in captions.items():
                if path.name.endswith("_" + figure):
                    example = path.name[len(prefix) + 1:-len(figure) - 1]
                    out.append((path.name, "%s %s" % (program, example), caption, is_wide(path)))
    return out


def write(build):
    build = pathlib.Path(build)
    fig_dir = build / "figures"
    head = ["<h1>gearhb: every figure of the thesis that can be computed</h1>",
            "<p>Made by <code>make figures</code>. Each chapter: its figures with the thesis figure number "
            "and what to notice (click a figure to enlarge it), its key numbers (the thesis' value, ours, the "
            "verdict of the independent check, and where ours and the thesis differ, by how much and why), "
            "and its deviations from the thesis.</p><nav><a href='#index'>figure index</a>"]
    head += ['<a href="#%s">%s</a>' % (c["program"], c["program"]) for c in CHAPTERS] + ["</nav>"]
    body, all_figs = [], []
    for ch in CHAPTERS:
        if not (build / "data" / ch["program"]).exists():
            continue
        part, figs = chapter_section(build, ch, fig_dir)
        body += part
        all_figs += figs
    gear_runs = sorted(p for p in (build / "data" / "gearhb_gear").glob("*") if (p / "key_numbers.json").exists())
    gear_figs = set()
    if gear_runs:
        body.append("<h2 id='gear_runs'>Gear-pair runs (gearhb_gear): one page each</h2><ul>")
        for run_dir in gear_runs:
            name, title, figs = gear_run_page(build, run_dir, fig_dir)
            gear_figs.update(figs)
            body.append("<li><a href='%s'>%s</a> (<code>%s.json</code>, %d figures)</li>"
                        % (name, html.escape(title), html.escape(run_dir.name), len(figs)))
        body.append("</ul>")
        head.insert(len(head) - 1, "<a href='#gear_runs'>gear-pair runs</a>")
    tools = tool_figures(fig_dir)
    if tools:
        body.append("<h2 id='gear_tools'>The tools: your own system (gearhb_frc), the tooth models compared, helical pairs, planetary sets</h2>")
        body += [figure_html(*f) for f in tools]
        head.insert(len(head) - 1, "<a href='#gear_tools'>gear tools</a>")
    shown = {f[0] for f in all_figs} | gear_figs | {f[0] for f in tools}
    extra = sorted(p.name for p in fig_dir.glob("*.png") if p.name not in shown)
    if extra:
        body.append("<h2>Further figures (no caption yet)</h2>")
        body += ['<figure><a href="%s"><img src="%s" alt="%s"></a><figcaption><code>%s</code></figcaption></figure>'
                 % (e, e, e, e) for e in extra]
    body.append("<h2>Thesis figures that cannot be computed</h2><ul>")
    body += ["<li>%s: %s</li>" % (html.escape(f), html.escape(why)) for f, why in NOT_COMPUTABLE]
    body.append("</ul>")
    page = ("<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>gearhb figures</title>"
            "<style>%s</style></head><body>%s</body></html>\n" % (
                STYLE, "\n".join(head + figure_index(all_figs) + body)))
    tmp = fig_dir / "index.html.tmp"
    tmp.write_text(page)
    tmp.replace(fig_dir / "index.html")
    return fig_dir / "index.html"


def check(index):
    index = pathlib.Path(index)
    links = re.findall(r'<img src="([^"]+)"', index.read_text())
    missing = [l for l in links if not (index.parent / l).exists()]
    for m in missing:
        print("missing image: %s" % m)
    print("%s: %d images linked, %d missing" % (index, len(links), len(missing)))
    return 1 if missing or not links else 0


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--check":
        sys.exit(check(sys.argv[2]))
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    print("wrote %s" % write(sys.argv[1]))
