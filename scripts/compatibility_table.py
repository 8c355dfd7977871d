#!/usr/bin/python3
"""The table of docs/compatibility.md: each component of the library on each mesh type, as the
typed test tests/library/mesh_types_test.cpp found it in one build.

usage: compatibility_table.py MESH_TYPES_TEST

Runs the test binary (built against one CGAL) and prints a Markdown table: a row per component, a
column per mesh type, each cell what its test recorded (the output's faces, its mean two-sided
error over the same run's on Surface_mesh with Epick), "fails" when it failed (with what it
recorded), or "Surface_mesh only" where the component has no test on that type (a Surface_mesh
suite's). The CGAL version heads the table. Exits 1 when a test failed.
"""

import json
import os
import subprocess
import sys
import tempfile


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.strip().splitlines()[2])
    binary = sys.argv[1]
    with tempfile.TemporaryDirectory() as folder:
        report = os.path.join(folder, "report.json")
        done = subprocess.run([binary, "--gtest_output=json:" + report], capture_output=True,
                              text=True)
        with open(report) as f:
            suites = json.load(f)["testsuites"]
    types, components, cells = [], [], {}
    for suite in suites:
        mesh_type = suite["name"].split("/")[1]
        if mesh_type not in types:
            types.append(mesh_type)
        for test in suite["testsuite"]:
            name = test["name"]
            if name not in components:
                components.append(name)
            if "faces" in test:
                cell = "%s faces, %.3f" % (test["faces"], float(test["mean_error_vs_surface_mesh"]))
            else:
                cell = "passes"
            if test.get("failures"):
                cell = "**fails**" + (" (%s)" % cell if cell != "passes" else "")
            cells[(name, mesh_type)] = cell
    print("CGAL " + suites[0]["cgal"] + "\n")
    print("| component | " + " | ".join(t.replace("_", " ") for t in types) + " |")
    print("|---|" + "---|" * len(types))
    for component in components:
        print("| %s | %s |" % (component, " | ".join(cells.get((component, t), "Surface_mesh only")
                                                     for t in types)))
    sys.exit(0 if done.returncode == 0 else 1)


if __name__ == "__main__":
    main()
