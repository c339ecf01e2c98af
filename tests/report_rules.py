#!/usr/bin/env python3
"""The report's rules (figures/report.py), checked on a synthetic build directory.

    report_rules.py WORK_DIR

For every chapter reference (reference/chNN_*.json) a run is faked whose key numbers are
the reference values, except: every "quick_run_only" number gets a different (full-run)
value, and one ordinary number of chapter 3 is put outside its tolerance. The page must then
  - show no FAIL except the one planted (a quick-run reference is never a failure),
  - say "not compared" on each quick-run-only row,
  - have a thesis column with a cell in every row for every chapter (chapters 2-6 included),
  - flag where ours and the thesis differ (chapter 7's corrected T2C, 25.65 against 24.1 mm; chapter
    6's Fig. 41, which the thesis says stays in full contact),
  - list each chapter's deviations from the thesis from its README,
and every caption of figures/captions.py must be its own (one caption per figure). A faked
gear-pair run (build/data/gearhb_gear/thesis_pair with the reference's values and one figure)
must get its own page, linked from the index, with every checked number, no FAIL, the
figure with its caption and the run's unchecked key numbers listed apart; a gear-tool figure
(gear_models.png) and a planetary run's figure get their captions.
Exit 0 when all hold; each broken rule is printed.
"""
import json
import pathlib
import re
import shutil
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "figures"))
import report  # noqa: E402
from captions import CHAPTERS  # noqa: E402

PLANTED = ("ch03_mass_wall", "omega_open")


def fake_build(work):
    if work.exists():
        shutil.rmtree(work)
    (work / "figures").mkdir(parents=True)
    quick_only = []
    for ref_file in sorted((ROOT / "reference").glob("ch[0-9][0-9]_*.json")):
        program = ref_file.stem
        numbers = json.load(open(ref_file))["numbers"]
        ours = {}
        for name, r in numbers.items():
            v = r["value"]
            if r.get("quick_run_only"):
                v = 3 * v + 7
                quick_only.append((program, name))
            if (program, name) == PLANTED:
                v = 2 * v + 1
            ours[name] = {"value": v, "unit": r.get("unit", "")}
        (work / "data" / program).mkdir(parents=True)
        (work / "data" / program / "key_numbers.json").write_text(json.dumps(ours))
    gear = work / "data" / "gearhb_gear" / "thesis_pair"
    gear.mkdir(parents=True)
    numbers = json.load(open(ROOT / "reference" / "gear_examples" / "thesis_pair.json"))["numbers"]
    ours = {k: {"value": r["value"], "unit": r.get("unit", "")} for k, r in numbers.items()}
    ours["an_unchecked_number"] = {"value": 1.5, "unit": "-"}
    (gear / "key_numbers.json").write_text(json.dumps(ours))
    (gear / "params.json").write_text(json.dumps({"name": "faked thesis pair"}))
    # make figures' layout: the run's own PNG in its folder, copied as gear_<run>_<figure>.png; a
    # PNG of another run whose name starts the same (thesis_pair_pe) must not reach this page.
    png = b"\x89PNG\r\n\x1a\n" + bytes(16)
    (gear / "response.png").write_bytes(png)
    (work / "figures" / "gear_thesis_pair_response.png").write_bytes(png)
    (work / "figures" / "gear_thesis_pair_pe_ste.png").write_bytes(png)
    # the gear tools' figures: one comparison and one planetary run's figure, each with its caption
    (work / "figures" / "gear_models.png").write_bytes(png)
    (work / "figures" / "planetary_some_set_response.png").write_bytes(png)
    return quick_only


def rows_of(page, program):
    """The key-number rows of one chapter's section: [(name, [cells])]."""
    m = re.search(r'<h2 id="%s">(.*?)(?=<h2 |\Z)' % program, page, re.S)
    section = m.group(1) if m else ""
    rows = re.findall(r"<tr><td>(.*?)</tr>", section, re.S)
    return section, [(r.split("</td>")[0], re.findall(r"<td[^>]*>(.*?)</td>", "<td>" + r, re.S), r) for r in rows]


def main(work):
    work = pathlib.Path(work)
    quick_only = fake_build(work)
    page = report.write(work).read_text()
    errors = []
    if not quick_only:
        errors.append("no reference marks a quick_run_only number (ch05 grid_points, ch06 time_integration_points)")
    fails = []
    for ch in CHAPTERS:
        program = ch["program"]
        section, rows = rows_of(page, program)
        if not rows:
            errors.append("%s: no key-number rows" % program)
        if "<th>thesis</th>" not in section:
            errors.append("%s: no thesis column" % program)
        for name, cells, raw in rows:
            if len(cells) != 6 or not re.sub(r"<[^>]+>", "", cells[1]).strip():
                errors.append("%s %s: the thesis cell is missing or empty" % (program, name))
            if "<td class='fail'>" in raw:
                fails.append((program, name))
            if (program, name) in quick_only and not any("not compared" in c for c in cells):
                errors.append("%s %s: a quick-run reference is compared with the full run" % (program, name))
        readme = ROOT / "chapters" / program / "README.md"
        if report.readme_deviations(readme) and "Deviations from the thesis (chapters/%s" % program not in section:
            errors.append("%s: the README's deviations are not listed" % program)
    if fails != [PLANTED]:
        errors.append("FAIL shown for %s; expected only the planted %s" % (fails, PLANTED))
    _, rows7 = rows_of(page, "ch07_ste")
    t2c = [cells for name, cells, _ in rows7 if name == "corrected_T2C_mm"]
    if not t2c or "differs" not in t2c[0][5]:
        errors.append("ch07_ste corrected_T2C_mm (25.65 against the thesis' 24.1 mm) is not flagged as differing")
    _, rows6 = rows_of(page, "ch06_gear_pair")
    f41 = [cells for name, cells, _ in rows6 if name == "first_change_omega_fig41"]
    if not f41 or "full contact" not in f41[0][1] or "differs" not in f41[0][5]:
        errors.append("ch06_gear_pair first_change_omega_fig41: the thesis' claim (stays in full contact) is not shown "
                      "as differing")
    gear_page = work / "figures" / "gear_thesis_pair.html"
    if "href='gear_thesis_pair.html'" not in page or not gear_page.exists():
        errors.append("the gear-pair run has no page linked from the index")
    else:
        g = gear_page.read_text()
        checked = json.load(open(ROOT / "reference" / "gear_examples" / "thesis_pair.json"))["numbers"]
        errors += ["gear page: checked number %s missing" % n for n in checked if "<tr><td>%s</td>" % n not in g]
        if "class='fail'" in g:
            errors.append("gear page: a FAIL where the run equals its reference")
        if "gear_thesis_pair_response.png" not in g or report.GEAR_CAPTIONS["response.png"][:40] not in g:
            errors.append("gear page: the figure or its caption is missing")
        if "gear_thesis_pair_pe_ste.png" in g:
            errors.append("gear page: shows a figure of another run (gear_thesis_pair_pe_ste.png)")
        if "an_unchecked_number" not in g.split("other key numbers")[-1]:
            errors.append("gear page: the run's unchecked key numbers are not listed apart")
    for name, caption in (("gear_models.png", report.TOOL_CAPTIONS["gear_models.png"]),
                          ("planetary_some_set_response.png", report.PLANETARY_CAPTIONS["response.png"])):
        if "<code>%s</code>): %s" % (name, caption[:40]) not in page:
            errors.append("%s: shown without its caption" % name)
    captions = [c for ch in CHAPTERS for _, _, c in ch["figures"]]
    shared = sorted({c for c in captions if captions.count(c) > 1})
    errors += ["caption shared by several figures: %s" % c[:80] for c in shared]
    for e in errors:
        print(e)
    print("report rules: %d chapters, %d quick-run-only numbers, %d problems" % (len(CHAPTERS), len(quick_only), len(errors)))
    return 1 if errors else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
