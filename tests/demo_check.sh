#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The demo's steps (ctest Demo): the reproducible record, then the statue with its figure,
# animation and JSON verdict, in a scratch copy of the examples. The record must be the same file
# on every run (its digest), the run must end in a verdict (overturned or survived) and write
# every output. usage: demo_check.sh SOURCE_DIR BLOCKDYN WORK_DIR
set -euo pipefail
src=$1 cli=$2 work=$3
rm -rf "$work" && mkdir -p "$work/examples" "$work/out" && cd "$work"
cp "$src/examples/statue_earthquake.toml" examples/
for pass in 1 2; do
  "$cli" motion generate --model rezaeian --arias 3.888 --d5-95 12 --t-mid 10 --f-mid 2.5 --f-slope -0.05 \
    --t-end 40 --seed 2026 --out out/demo_record --overwrite --quiet
  sha256sum out/demo_record/rezaeian_0001.AT2 | cut -d' ' -f1 > "digest$pass"
done
cmp digest1 digest2
"$cli" simulate examples/statue_earthquake.toml --json-out out/demo.json --animate out/demo.gif --animate-frames 20
for f in out/demo.png out/demo.svg out/demo.gif out/demo.json out/demo_trajectory.csv; do
  [ -s "$f" ] || { echo "demo: $f not written"; exit 1; }
done
/usr/bin/python3 - <<'PY'
import json
d = json.load(open("out/demo.json"))
assert d["status"] in ("overturned", "t_end"), d["status"]
assert (d["overturn_time"] is not None) == (d["status"] == "overturned")
assert d["max_abs_energy_error"] < 1e-8, d["max_abs_energy_error"]   # joules, of ~4 kJ moved
assert d["ground_motion"]["horizontal"]["record"]["peak_g"] > 0.25    # above the uplift threshold g b/h
print("demo:", d["status"], d["overturn_time"])
PY
