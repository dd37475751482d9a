#!/usr/bin/env python3
"""Condense `shadowcheck run --out DIR` directories into the committed reference files.

usage: summarize.py OUTROOT RUN_DIR...   (each RUN_DIR named r-<backend with ':' -> '-'>)
Per backend it writes OUTROOT/<backend>/: failures.csv (copied as written by the run: the
baseline), warnings.csv (test,Warn), summary.md (status counts per API path, skip reasons,
failure/warning groups) and report.md (the run's report.md capped at 150 KB); and OUTROOT/SUMMARY.md,
one table over every backend x API path. Needs only results.jsonl, failures.csv and report.md."""
import collections, csv, json, os, shutil, sys

STATUSES = ["Pass", "Warn", "Fail", "Skip", "Crash", "Timeout", "Flake", "KnownFlake", "ExpectedFail"]
CAP = 150_000


def status_key(rec):
    s = rec["status"]
    if isinstance(s, dict):  # e.g. {"UnexpectedImprovement": "Pass"}
        return "+".join(f"{k}({v})" for k, v in s.items())
    return s


def group_of(rec):
    t = rec.get("tags", {})
    return f'{t.get("spec")}/{t.get("target")}/{t.get("format")}/{t.get("filter")}/{t.get("func")}'


def summarize(outroot, run_dir):
    backend = os.path.basename(run_dir.rstrip("/"))[2:]
    dst = os.path.join(outroot, backend)
    os.makedirs(dst, exist_ok=True)
    counts = collections.defaultdict(collections.Counter)
    skips = collections.defaultdict(collections.Counter)
    groups = collections.defaultdict(collections.Counter)
    examples = {}
    warns = []
    last = {}  # a re-run (flake check) appends a second record: the last one is final
    with open(os.path.join(run_dir, "results.jsonl")) as f:
        for line in f:
            rec = json.loads(line)
            if rec.get("kind") == "result":
                last[rec["test"]] = rec
    for rec in last.values():
        if True:
            api, st = rec["api"], status_key(rec)
            counts[api][st] += 1
            if st == "Skip":
                skips[api][rec.get("reason") or "(no reason)"] += 1
            elif st not in ("Pass",):
                key = (api, st, group_of(rec))
                groups[api][key] += 1
                examples.setdefault(key, rec["test"])
            if st == "Warn":
                warns.append(rec["test"])
    shutil.copy(os.path.join(run_dir, "failures.csv"), os.path.join(dst, "failures.csv"))
    with open(os.path.join(dst, "warnings.csv"), "w", newline="") as f:
        w = csv.writer(f)
        for t in sorted(warns):
            w.writerow([t, "Warn"])
    with open(os.path.join(run_dir, "report.md")) as f:
        rep = f.read()
    if len(rep) > CAP:
        cut = rep.rfind("\n", 0, CAP)
        rep = rep[:cut] + f"\n\n... report.md capped at {CAP} bytes of {len(rep)}; re-run with run.sh for the full file.\n"
    with open(os.path.join(dst, "report.md"), "w") as f:
        f.write(rep)
    extra = sorted({s for c in counts.values() for s in c} - set(STATUSES))
    cols = STATUSES + extra
    lines = [f"# {backend} on Mesa 22.3.6\n", "Status per API path (tests = case x API path):\n",
             "| API path | " + " | ".join(cols) + " | total |", "|---|" + "---:|" * (len(cols) + 1)]
    for api in sorted(counts):
        c = counts[api]
        lines.append(f"| {api} | " + " | ".join(str(c.get(s, 0)) for s in cols) + f" | {sum(c.values())} |")
    lines.append("\n## Skip reasons\n")
    for api in sorted(skips):
        for reason, n in skips[api].most_common(12):
            lines.append(f"- `{api}` {n}: {reason}")
    lines.append("\n## Non-pass groups (spec/target/format/filter/func), with one example test\n")
    lines.append("| API path | status | group | tests | example |\n|---|---|---|---:|---|")
    for api in sorted(groups):
        for (a, st, g), n in sorted(groups[api].items(), key=lambda kv: (-kv[1], kv[0])):
            if st == "Skip":
                continue
            lines.append(f"| {a} | {st} | `{g}` | {n} | `{examples[(a, st, g)]}` |")
    with open(os.path.join(dst, "summary.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    return backend, counts, cols


def main():
    outroot, runs = sys.argv[1], sys.argv[2:]
    rows, allcols = [], list(STATUSES)
    for r in runs:
        backend, counts, cols = summarize(outroot, r)
        for c in cols:
            if c not in allcols:
                allcols.append(c)
        rows.append((backend, counts))
    out = ["# Mesa 22.3.6 reference results (default fixtures)\n",
           "One row per backend x API path; a test is one case on one API path. See ../README.md for the causes.\n",
           "| backend | API path | " + " | ".join(allcols) + " |", "|---|---|" + "---:|" * len(allcols)]
    for backend, counts in rows:
        for api in sorted(counts):
            c = counts[api]
            if all(c.get(s, 0) == 0 for s in allcols if s != "Skip"):
                continue  # everything skipped (another spec's API path)
            out.append(f"| {backend} | {api} | " + " | ".join(str(c.get(s, 0)) for s in allcols) + " |")
    with open(os.path.join(outroot, "SUMMARY.md"), "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
