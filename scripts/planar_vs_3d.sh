#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Is the planar analysis conservative? (docs/3d.md) The smallest overturning one-sine pulse of a
# square column (0.4 x 0.4 x 1.2 m, mu 0.7) along its axis, at 30 and at 45 degrees, beside the
# planar Housner and 3-DOF blocks of its section; then a fragility curve, planar (h1 alone)
# versus 3D (h1 and h2 at seven incidences) on one generated two-component suite. Prints
# markdown tables; writes its files into a temporary directory.
set -euo pipefail
B="$(cd "$(dirname "$0")/.." && pwd)/build/blockdyn"
W="$(mktemp -d)"
trap 'rm -rf "$W"' EXIT
cd "$W"
D=0.25,0.5,1,2
COL=(--width 0.4 --height 1.2)
"$B" spectrum --model housner "${COL[@]}" --pulse one-sine --durations $D --json --quiet > housner.json
"$B" spectrum --model rigid "${COL[@]}" --mu-s 0.7 --pulse one-sine --durations $D --json --quiet > rigid.json
for az in 0 30 45; do
  "$B" spectrum --model rigid3d "${COL[@]}" --depth 0.4 --mu-s 0.7 --incidence $az --pulse one-sine --durations $D \
    --json --quiet > "box_$az.json"
done
"$B" motion generate --arias 1.2 --d5-95 6 --t-mid 5 --f-mid 2.5 --f-slope -0.05 --t-end 15 --count 20 \
  --components 2 --h2-arias 0.8 --seed 2026 --out suite --quiet
"$B" fragility --model housner "${COL[@]}" --records 'suite/*_h1.AT2' --levels 0.1:0.8:8 --bootstrap 100 \
  --json --quiet > fr_planar.json
"$B" fragility --model rigid3d "${COL[@]}" --mu-s 0.7 --suite suite --incidence 0:90:7 --levels 0.1:0.8:8 \
  --bootstrap 100 --json --quiet > fr_3d.json
/usr/bin/python3 - <<'EOF'
import json
def rows(f):
    return {r["duration"]: r for r in json.load(open(f))["rows"]}
cases = [("Housner (planar)", "housner.json"), ("3-DOF block (planar)", "rigid.json"),
         ("3D box, 0 deg", "box_0.json"), ("3D box, 30 deg", "box_30.json"), ("3D box, 45 deg", "box_45.json")]
print("| model | T = 0.25 s | 0.5 s | 1 s | 2 s |")
print("|---|---|---|---|---|")
for name, f in cases:
    r = rows(f)
    cells = []
    for d in (0.25, 0.5, 1.0, 2.0):
        a = r[d]["min_overturning_amplitude"]
        out = r[d].get("scan_outside_model", 0)
        cells.append(("%.3g g" % a if a is not None else "none") + (" (%d outside)" % out if out else ""))
    print("| %s | %s |" % (name, " | ".join(cells)))
print()
for name, f in (("planar Housner, h1 alone (pga of h1)", "fr_planar.json"),
                ("3D box, h1 and h2 at 0-90 deg (geometric-mean pga)", "fr_3d.json")):
    j = json.load(open(f))
    fit = j["fit"]
    out = sum(l.get("n_outside_model", 0) for l in j["levels"])
    runs = sum(l["n"] + l.get("n_outside_model", 0) for l in j["levels"])
    line = "| %s | %.3g g | %.3g | %d of %d |" % (name, fit["median"], fit["beta"], out, runs)
    if "critical_incidence" in j:
        line += " critical incidence %g deg (median %.3g g) |" % (
            j["critical_incidence"],
            [i["fit"]["median"] for i in j["incidences"] if i["incidence"] == j["critical_incidence"]][0])
    print(line)
EOF
