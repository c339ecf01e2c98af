#!/usr/bin/env python3
"""The browsable report build/figures/index.html (`make figures` writes it).

    report.py BUILD_DIR            write BUILD_DIR/figures/index.html
    report.py --check INDEX.html   exit 1 unless every image the page links exists

Every figure grouped by chapter with its thesis figure number and a caption (what it
shows, what to notice: figures/captions.py), the chapter's key numbers with the
thesis value, the reference value, ours and the check status, and the thesis
figures that cannot be computed (listed, not faked). Static HTML, no JavaScript.
"""
import html
import json
import pathlib
import re
import sys

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from captions import CHAPTERS, NOT_COMPUTABLE  # noqa: E402

STYLE = """body{font-family:sans-serif;max-width:1100px;margin:auto;padding:1em;color:#222}
h1{font-size:1.5em}h2{border-bottom:1px solid #ccc;margin-top:2em}
figure{display:inline-block;width:48%;vertical-align:top;margin:0 1% 1.5em 0}
figure img{width:100%;border:1px solid #ddd}figcaption{font-size:.85em}
table{border-collapse:collapse;font-size:.8em;margin:.5em 0}td,th{border:1px solid #ccc;padding:2px 6px}
.pass{color:#070}.fail{color:#b00;font-weight:bold}.none{color:#777}nav a{margin-right:1em}"""


def key_number_rows(ref_file, data_dir):
    if not ref_file.exists():
        return []
    ref = json.load(open(ref_file))["numbers"]
    ours_file = data_dir / "key_numbers.json"
    ours = json.load(open(ours_file)) if ours_file.exists() else {}
    rows = []
    for name, r in ref.items():
        tol = r.get("tolerance", {})
        allowed = max(tol.get("abs", 0.0), tol.get("rel", 0.0) * abs(r["value"]))
        if name in ours:
            v = ours[name]["value"]
            status = ("pass", "pass") if abs(v - r["value"]) <= allowed else ("FAIL", "fail")
            ours_text = "%.10g" % v
        else:
            status, ours_text = ("not in this run", "none"), ""
        thesis = r.get("thesis_value")
        rows.append("<tr><td>%s</td><td>%s</td><td>%.10g</td><td>%s</td><td>%s</td><td>%s</td>"
                    "<td class='%s'>%s</td></tr>" % (
                        html.escape(name), html.escape(r.get("unit", "")), r["value"],
                        "" if thesis is None else html.escape(str(thesis)), ours_text,
                        html.escape(json.dumps(tol)), status[1], status[0]))
    return rows


def chapter_section(build, ch, fig_dir):
    out = ['<h2 id="%s">%s</h2>' % (ch["program"], html.escape(ch["title"]))]
    out.append("<p>Program <code>build/bin/%s</code>; data in <code>build/data/%s/</code>; README "
               "<code>chapters/%s/README.md</code>.</p>" % (ch["program"], ch["program"], ch["program"]))
    shown = set()
    for pattern, thesis_fig, caption in ch["figures"]:
        paths = sorted(fig_dir.glob(pattern))
        if not paths:
            out.append("<p class='none'>%s (thesis %s): not drawn in this run.</p>" % (html.escape(pattern), thesis_fig))
        for path in paths:
            name = path.name
            shown.add(name)
            out.append('<figure><a href="%s"><img src="%s" alt="%s"></a><figcaption><b>Thesis %s</b> '
                       '(<code>%s</code>): %s</figcaption></figure>' % (name, name, name, thesis_fig, name,
                                                                         html.escape(caption)))
    rows = key_number_rows(HERE.parent / "reference" / (ch["program"] + ".json"), build / "data" / ch["program"])
    if rows:
        out.append("<h3>Key numbers (reference/%s.json)</h3><table><tr><th>number</th><th>unit</th>"
                   "<th>reference</th><th>thesis</th><th>ours</th><th>tolerance</th><th>status</th></tr>"
                   % ch["program"])
        out += rows
        out.append("</table>")
    return out, shown


def write(build):
    build = pathlib.Path(build)
    fig_dir = build / "figures"
    body = ["<h1>gearhb: every figure of the thesis that can be computed</h1>",
            "<p>Made by <code>make figures</code>. Each chapter: its figures with the thesis figure number "
            "and what to notice, then its key numbers against <code>reference/</code>.</p><nav>"]
    body += ['<a href="#%s">%s</a>' % (c["program"], c["program"]) for c in CHAPTERS] + ["</nav>"]
    shown = set()
    for ch in CHAPTERS:
        if not (build / "data" / ch["program"]).exists():
            continue
        part, s = chapter_section(build, ch, fig_dir)
        body += part
        shown |= s
    extra = sorted(p.name for p in fig_dir.glob("*.png") if p.name not in shown)
    if extra:
        body.append("<h2>Further figures</h2>")
        body += ['<figure><img src="%s" alt="%s"><figcaption><code>%s</code></figcaption></figure>' % (e, e, e)
                 for e in extra]
    body.append("<h2>Thesis figures that cannot be computed</h2><ul>")
    body += ["<li>%s: %s</li>" % (html.escape(f), html.escape(why)) for f, why in NOT_COMPUTABLE]
    body.append("</ul>")
    page = ("<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>gearhb figures</title>"
            "<style>%s</style></head><body>%s</body></html>\n" % (STYLE, "\n".join(body)))
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
