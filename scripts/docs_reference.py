#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The documentation site's reference pages, generated from the program itself.

usage: docs_reference.py BLOCKDYN OUTDIR [--check]

commands.md: every subcommand's options, defaults and help, from `blockdyn reference` (the option
registry the command line is built from). outputs.md: the JSON keys and CSV columns each command
writes, harvested from small runs of the program (so a key added or removed shows at once), with
their meanings from docs/reference/glossary.toml. --check exits 1 naming every key a run wrote
that the glossary does not describe and every glossary entry no run wrote (so neither can drift).
"""

import json
import os
import re
import subprocess
import sys
import tempfile
import tomllib

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
RECORD = os.path.join(ROOT, "tests", "fixtures", "synthetic_60s.AT2")
HOUSNER = ["--model", "housner", "--width", "0.3", "--height", "1.5"]
FORCED = HOUSNER + ["--beta", "2", "--omega", "5"]

# (scope, arguments, CSV files the run writes). A scope is the glossary table its keys are looked
# up in before [common]; the first case of a scope names its page section.
CASES = [
    ("simulate", ["simulate", "--t-end", "2", "--json", "--trajectory", "w.csv"], ["w.csv"]),
    ("simulate", ["simulate", "--height", "1.8", "--width", "0.45", "--thickness", "0.4", "--density", "2700",
                  "--subgrade-modulus", "2e9", "--t-end", "0.5", "--json", "--trajectory", "wp.csv"], ["wp.csv"]),
    ("simulate", ["simulate"] + HOUSNER + ["--w0", "0.1", "--t-end", "3", "--json", "--trajectory", "h.csv"],
     ["h.csv"]),
    ("simulate", ["simulate", "--model", "rigid", "--width", "0.6", "--height", "1.8", "--mass", "150",
                  "--mu-s", "0.35", "--mu-k", "0.3", "--ground-h-record", RECORD, "--ground-h-scale", "2",
                  "--t-end", "4", "--json", "--trajectory", "r.csv"], ["r.csv"]),
    ("simulate", ["simulate", "--model", "rigid3d", "--width", "0.4", "--depth", "0.3", "--height", "1.2", "--tilt",
                  "0.12", "--tilt-azimuth", "30", "--t-end", "1", "--json", "--trajectory", "r3.csv"], ["r3.csv"]),
    ("simulate", ["simulate", "--model", "rigid3d", "--width", "1", "--depth", "0.8", "--height", "1.2", "--mu-s",
                  "0.3", "--mu-k", "0.25", "--ground-h-pulse", "rect", "--ground-h-amplitude", "0.4",
                  "--ground-h-duration", "0.5", "--ground-azimuth", "30", "--t-end", "1.5", "--json", "--trajectory",
                  "r3s.csv"], ["r3s.csv"]),
    ("assembly", ["assembly", "--preset", "trilith", "--ground-h-pulse", "half-sine", "--ground-h-amplitude", "0.5",
                  "--ground-h-duration", "0.3", "--t-end", "1", "--json", "--trajectory", "a.csv"], ["a.csv"]),
    ("assembly", ["assembly", "--preset", "trilith", "--contact", "rigid", "--tilt", "0.05", "--t-end", "1",
                  "--json", "--trajectory", "ar.csv"], ["ar.csv"]),
    ("limit-analysis", ["limit-analysis", "--preset", "arch", "--json"], []),
    ("limit-analysis", ["limit-analysis", "--preset", "arch", "--min-thickness", "--json"], []),
    ("motion", ["motion", "generate", "--model", "rezaeian", "--arias", "1", "--d5-95", "10", "--t-mid", "8",
                "--f-mid", "3", "--t-end", "30", "--count", "2", "--out", "recs", "--json", "--quiet"], []),
    ("motion", ["motion", "generate", "--model", "rezaeian", "--arias", "1", "--d5-95", "10", "--t-mid", "8",
                "--f-mid", "3", "--t-end", "30", "--count", "2", "--components", "3", "--v-arias", "0.3",
                "--v-f-mid", "6", "--out", "recs3", "--json", "--quiet"], []),
    ("motion", ["motion", "info", RECORD, "--json", "--spectrum"], []),
    ("sweep", ["sweep", "--k", "1e4,1e5", "--t-end", "2", "--output", "sweep.csv", "--quiet"], ["sweep.csv"]),
    ("spectrum", ["spectrum"] + HOUSNER + ["--pulse", "one-sine", "--durations", "0.5,1", "--json", "--quiet",
                                           "--csv", "spectrum.csv"], ["spectrum.csv"]),
    ("survival", ["survival"] + HOUSNER + ["--beta-min", "1", "--beta-max", "3", "--beta-points", "2",
                                           "--omega-min", "2", "--omega-max", "6", "--omega-points", "2",
                                           "--json", "--quiet", "--out", "survival.csv"], ["survival.csv"]),
    ("response-curve", ["response-curve"] + HOUSNER + ["--betas", "1.5", "--omega-min", "2", "--omega-max", "6",
                                                       "--omega-points", "3", "--json", "--quiet", "--out",
                                                       "rc.csv"], ["rc.csv"]),
    ("rocking-spectrum", ["rocking-spectrum", "--model", "housner", "--record", RECORD, "--alpha", "0.25",
                          "--p-min", "1", "--p-max", "3", "--p-points", "3", "--json", "--quiet", "--out",
                          "rs.csv"], ["rs.csv"]),
    ("rocking-spectrum", ["rocking-spectrum", "--model", "rigid3d", "--suite", "recs3", "--alpha", "0.25",
                          "--p-values", "1.5,3", "--incidence", "0:90:2", "--t-end", "5", "--json", "--quiet",
                          "--out", "rs3.csv"], ["rs3.csv"]),
    ("fragility", ["fragility", "--model", "housner", "--width", "0.3", "--height", "1.5", "--records", RECORD,
                   "--levels", "0.2,0.4", "--json", "--quiet", "--out", "frag.csv"], ["frag.csv"]),
    ("fragility", ["fragility", "--model", "rigid3d", "--width", "0.3", "--height", "1.5", "--suite", "recs3",
                   "--incidence", "0:90:2", "--levels", "0.2,0.4", "--bootstrap", "0", "--t-end", "5", "--json",
                   "--quiet", "--out", "frag3.csv"], ["frag3.csv"]),
    ("chaos-map", ["chaos-map"] + HOUSNER + ["--beta-min", "1", "--beta-max", "2", "--beta-points", "2",
                                            "--omega-min", "2", "--omega-max", "4", "--omega-points", "2",
                                            "--periods", "30", "--transient-periods", "10", "--json", "--quiet",
                                            "--out", "cm.csv"],
     ["cm.csv"]),
    ("cycles", ["cycles"] + FORCED + ["--periods", "40", "--json", "--quiet", "--out", "cy.csv"], ["cy.csv"]),
    ("periodic-orbits", ["periodic-orbits", "--width", "0.3", "--height", "1.5", "--ks", "0.3", "--omega", "2",
                         "--json", "--out", "po.csv"], ["po.csv"]),
    ("impact-map", ["impact-map"] + FORCED + ["--periods", "20", "--json", "--out", "im.csv"], ["im.csv"]),
    ("lyapunov", ["lyapunov"] + FORCED + ["--json", "--csv", "ly.csv"], ["ly.csv"]),
    ("lyapunov", ["lyapunov", "--r", "0.2", "--t-end", "20", "--json"], []),
    ("map", ["map", "--k", "1e4,1e6", "--inv-r", "3,5", "--t-end", "2", "--output", "map.csv", "--quiet"], ["map.csv"]),
    ("flight-time", ["flight-time", "--points", "3", "--json", "-", "--csv", "ft.csv"], ["ft.csv"]),
    ("kmin", ["kmin", "--json", "-", "--csv", "kmin.csv"], ["kmin.csv"]),
    ("overturn", ["overturn", "--points", "3", "--json", "-", "--csv", "ov.csv"], ["ov.csv"]),
    ("equilibria", ["equilibria", "--json", "--csv", "eq.csv"], ["eq.csv"]),
    ("bifurcation", ["bifurcation", "--json", "--csv", "bi.csv"], ["bi.csv"]),
    ("response", ["response", "--t-end", "20", "--json"], []),
    ("poincare", ["poincare", "--t-end", "20", "--json", "--csv", "pc.csv"], ["pc.csv"]),
    ("energy-surface", ["energy-surface", "--json"], []),
]


def run_case(blockdyn, args, workdir):
    p = subprocess.run([blockdyn] + args, cwd=workdir, capture_output=True, text=True, timeout=300)
    if p.returncode != 0:
        raise SystemExit(f"docs_reference: `blockdyn {' '.join(args)}` failed ({p.returncode}): {p.stderr.strip()}")
    out = p.stdout.strip()
    return json.loads(out) if out.startswith("{") else None


def column_descriptions(doc, found):
    """The descriptions a sidecar carries itself: every `columns` object of name -> text."""
    if isinstance(doc, dict):
        for k, v in doc.items():
            if k == "columns" and isinstance(v, dict) and all(isinstance(t, str) for t in v.values()):
                found.update(v)
            column_descriptions(v, found)
    elif isinstance(doc, list):
        for v in doc[:200]:
            column_descriptions(v, found)


def key_rows(doc, prefix="", rows=None):
    """Every key of a document as (dotted path, leaf name, JSON type, an example value)."""
    rows = {} if rows is None else rows
    if isinstance(doc, dict):
        for k, v in doc.items():
            path = f"{prefix}.{k}" if prefix else k
            if path not in rows:
                rows[path] = (k, type_name(v), example(v))
            key_rows(v, path, rows)
    elif isinstance(doc, list):
        for v in doc[:200]:
            key_rows(v, prefix + "[]", rows)
    return rows


def type_name(v):
    return {dict: "object", list: "array", str: "string", bool: "boolean", type(None): "null",
            int: "number", float: "number"}[type(v)]


def example(v):
    if isinstance(v, (dict, list)):
        return ""
    text = json.dumps(v)
    return text if len(text) <= 24 else text[:21] + "..."


def harvest(blockdyn):
    """{scope: {"json": {path: row}, "csv": {file: [columns]}}} from every case."""
    pages = {}
    with tempfile.TemporaryDirectory() as work:
        for scope, args, csvs in CASES:
            page = pages.setdefault(scope, {"json": {}, "csv": {}, "commands": [], "described": {}})
            page["commands"].append(args)
            doc = run_case(blockdyn, args, work)
            if doc is not None:
                key_rows(doc, "", page["json"])
                column_descriptions(doc, page["described"])
            for name in csvs:
                with open(os.path.join(work, name)) as f:
                    page["csv"][" ".join(args[:3])] = f.readline().strip().split(",")
                for sidecar in (name + ".json", name[:-4] + ".json"):  # table.csv.json or a runner's table.json
                    if os.path.exists(os.path.join(work, sidecar)):
                        with open(os.path.join(work, sidecar)) as f:
                            side = json.load(f)
                        key_rows(side, "", page["json"])
                        column_descriptions(side, page["described"])
    return pages


def option_meanings(reference):
    """{scope: {key: help}}: a key named after an option (mu_s for --mu-s) means what the option does."""
    table = {}
    for cmd in reference["commands"]:
        scope = cmd["name"].split()[0]
        for o in cmd["options"]:
            for n in o["names"]:
                if n.startswith("--"):
                    table.setdefault(scope, {}).setdefault(n[2:].replace("-", "_"), "the option `" + n + "`: " + o["help"])
    return table


def lookup(table, name):
    """The entry for name: exact, else a pattern (<n> a number, <label> any text); its key too."""
    if table.get(name):
        return name, table[name]
    for key, text in table.items():
        if "<" in key:
            rx = re.escape(key).replace(re.escape("<n>"), r"\d+").replace(re.escape("<label>"), ".+")
            if re.fullmatch(rx, name):
                return key, text
    return None, None


def meaning(glossary, scope, name, described=None):
    for table in (glossary.get(scope, {}), described or {}, glossary.get("common", {}),
                  glossary.get("options", {}).get(scope, {})):
        key, text = lookup(table, name)
        if text:
            return text
    return None


def problems(pages, glossary):
    missing, used = [], set()
    for scope, page in pages.items():
        names = {row[0] for row in page["json"].values()} | {c for cols in page["csv"].values() for c in cols}
        for name in sorted(names):
            own, common = lookup(glossary.get(scope, {}), name)[0], lookup(glossary.get("common", {}), name)[0]
            if own:
                used.add((scope, own))
            elif page["described"].get(name) or glossary.get("options", {}).get(scope, {}).get(name):
                pass
            elif common:
                used.add(("common", common))
            else:
                missing.append(f"{scope}: '{name}' has no description in docs/reference/glossary.toml")
    stale = [f"{scope}: glossary entry '{name}' is written by no run" for scope, table in glossary.items()
             if scope != "options" for name in table if (scope, name) not in used]
    return missing + stale


def cell(text):
    return text.replace("|", "\\|")


def commands_page(reference):
    lines = ["# Commands and options", "",
             "Generated by `scripts/docs.sh` from `blockdyn reference`, the option registry the command line",
             "is built from: every option, its default and its allowed range as the program checks it.", ""]
    for cmd in reference["commands"]:
        lines += [f"## {cmd['name']}", "", cell(cmd["description"]), "", "| option | default | meaning |",
                  "|---|---|---|"]
        for o in cmd["options"]:
            names = ", ".join(f"`{n}`" for n in o["names"])
            default = f"`{o['default']}`" if o["default"] not in ("", None) else ""
            req = " (required)" if o.get("required") else ""
            lines.append(f"| {names} | {default} | {cell(o['help'])}{req} |")
        lines.append("")
    return "\n".join(lines) + "\n"


def outputs_page(pages, glossary):
    lines = ["# JSON keys and CSV columns", "",
             "Generated by `scripts/docs.sh`: each command below was run on a small case and every key of",
             "its JSON document (and of the JSON sidecar beside a CSV table) and every CSV column is listed",
             "with its type, a value from that run and its meaning; a test fails when a run writes a key",
             "this page does not describe. The layout and versioning rules: [Output formats](../output-formats.md).",
             ""]
    for scope, page in pages.items():
        lines += [f"## {scope}", "", "Runs: " + "; ".join(f"`blockdyn {' '.join(short(a) for a in args)}`"
                                                        for args in page["commands"]), ""]
        if page["json"]:
            lines += ["| JSON key | type | example | meaning |", "|---|---|---|---|"]
            for path, (name, kind, ex) in page["json"].items():
                lines.append(f"| `{path}` | {kind} | {cell(ex)} | {cell(meaning(glossary, scope, name, page['described']) or '')} |")
            lines.append("")
        for source, cols in page["csv"].items():
            lines += [f"CSV columns of `blockdyn {short(source)}`:", "", "| column | meaning |", "|---|---|"]
            lines += [f"| `{c}` | {cell(meaning(glossary, scope, c, page['described']) or '')} |" for c in cols]
            lines.append("")
    return "\n".join(lines) + "\n"


def short(arg):
    return os.path.relpath(arg, ROOT) if os.path.isabs(arg) else arg


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    blockdyn, outdir = os.path.abspath(sys.argv[1]), sys.argv[2]
    with open(os.path.join(ROOT, "docs", "reference", "glossary.toml"), "rb") as f:
        glossary = tomllib.load(f)
    pages = harvest(blockdyn)
    reference = json.loads(subprocess.run([blockdyn, "reference"], capture_output=True, text=True,
                                          check=True).stdout)
    glossary["options"] = option_meanings(reference)
    if "--check" in sys.argv[3:]:
        found = problems(pages, glossary)
        for p in found:
            print(p)
        sys.exit(1 if found else 0)
    os.makedirs(outdir, exist_ok=True)
    with open(os.path.join(outdir, "commands.md"), "w") as f:
        f.write(commands_page(reference))
    with open(os.path.join(outdir, "outputs.md"), "w") as f:
        f.write(outputs_page(pages, glossary))


if __name__ == "__main__":
    main()
