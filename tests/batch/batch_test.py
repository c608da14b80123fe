#!/usr/bin/env python3
"""Checks of `heliostand batch` for CTest (tests/scripts/batch.cmake).

  batch_test.py same ROOT_A ROOT_B
      Every file under both roots is the same, byte for byte, except run.json's timing fields (started_utc,
      finished_utc, wall_seconds, stage_seconds) and the machine that finished the run (finished_on), which are
      compared without them. Both roots must hold the same files, and at least one run.json (an empty batch
      proves nothing).
  batch_test.py same ROOT_A ROOT_B --regrown RUN
      As above, and ROOT_B was a restart of ROOT_A with RUN unfinished: every other run.json is identical
      timings included (those runs were kept, not grown again).
  batch_test.py one-fails ROOT EXIT_STATUS FAILED_RUN REASON
      The batch exited EXIT_STATUS (1), FAILED_RUN is reported failed in summary.csv with REASON in its error,
      and every other run finished (run.json) and has status ok with its final year in summary.csv.
"""
import csv
import json
import os
import sys

TIMING_KEYS = ("started_utc", "finished_utc", "finished_on", "wall_seconds", "stage_seconds")


def files_under(root):
    found = {}
    for folder, _, names in os.walk(root):
        for name in names:
            path = os.path.join(folder, name)
            found[os.path.relpath(path, root)] = path
    return found


def comparable(relative, path):
    with open(path, "rb") as f:
        data = f.read()
    if os.path.basename(relative) != "run.json":
        return data
    manifest = json.loads(data)
    for key in TIMING_KEYS:
        if key not in manifest:
            sys.exit(f"{path}: no '{key}' (run.json's timing fields changed: update batch_test.py)")
        del manifest[key]
    return json.dumps(manifest, sort_keys=True).encode()


def same(root_a, root_b, regrown=None):
    a, b = files_under(root_a), files_under(root_b)
    if set(a) != set(b):
        sys.exit(f"the roots hold different files: only in {root_a}: {sorted(set(a) - set(b))}; "
                 f"only in {root_b}: {sorted(set(b) - set(a))}")
    manifests = [r for r in a if os.path.basename(r) == "run.json"]
    if not manifests:
        sys.exit(f"{root_a}: no run.json: no run finished")
    differing = [r for r in sorted(a) if comparable(r, a[r]) != comparable(r, b[r])]
    if differing:
        sys.exit(f"files differ between {root_a} and {root_b}: {differing}")
    if regrown is not None:
        stand, scenario, seed = regrown.split("/")
        regrown_manifest = os.path.join("runs", stand, scenario, seed, "run.json")
        if regrown_manifest not in a:
            sys.exit(f"no {regrown_manifest} in {root_a}")
        for relative in manifests:
            with open(a[relative], "rb") as fa, open(b[relative], "rb") as fb:
                kept = fa.read() == fb.read()
            if relative != regrown_manifest and not kept:
                sys.exit(f"{relative}: grown again (its timings changed), though it had finished")
    print(f"{len(a)} files identical ({len(manifests)} runs; run.json timings excluded)")


def one_fails(root, exit_status, failed_run, reason):
    if exit_status != "1":
        sys.exit(f"the batch exited {exit_status}, expected 1 (a run failed)")
    with open(os.path.join(root, "summary.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    runs = {}
    for row in rows:
        runs.setdefault(row["run"], []).append(row)
    if failed_run not in runs:
        sys.exit(f"summary.csv has no row for {failed_run}: {sorted(runs)}")
    failed = runs.pop(failed_run)
    if len(failed) != 1 or failed[0]["status"] != "failed" or reason not in failed[0]["error"]:
        sys.exit(f"{failed_run}: expected one 'failed' row whose error names '{reason}', got {failed}")
    if not runs:
        sys.exit("no other run in summary.csv")
    for run, run_rows in runs.items():
        if any(r["status"] != "ok" or not r["stand_age"] for r in run_rows):
            sys.exit(f"{run}: expected status ok with its final year, got {run_rows}")
        stand, scenario, seed = run.split("/")
        if not os.path.isfile(os.path.join(root, "runs", stand, scenario, seed, "run.json")):
            sys.exit(f"{run}: no run.json: it did not finish")
    print(f"{failed_run} failed ({failed[0]['error']}); {len(runs)} others finished")


if __name__ == "__main__":
    if sys.argv[1:2] == ["same"] and len(sys.argv) == 4:
        same(sys.argv[2], sys.argv[3])
    elif sys.argv[1:2] == ["same"] and len(sys.argv) == 6 and sys.argv[4] == "--regrown":
        same(sys.argv[2], sys.argv[3], sys.argv[5])
    elif sys.argv[1:2] == ["one-fails"] and len(sys.argv) == 6:
        one_fails(*sys.argv[2:])
    else:
        sys.exit(__doc__)
