#!/usr/bin/python3
"""Counts test cases in catkin's JUnit XML results, each case once.

catkin_test_results counts every gtest 1.12 case twice and ctest counts executables; this
reads the <testcase> elements themselves. A result file that catkin wrote for a crashed or
missing test binary ("MISSING-RESULT") counts as a failure. Prints the failed cases, each with
the first lines of its failure message (CI logs keep only their tail, so the reason must be
here), then "N passed, N failed[, N skipped]" as the last line; exit status 1 if anything failed
or no test ran.
"""
import pathlib
import sys
import xml.etree.ElementTree as ET

MESSAGE_LINES = 6


def failure_message(case):
    """The first MESSAGE_LINES lines of a failed case's message, indented."""
    verdict = case.find("failure")
    if verdict is None:
        verdict = case.find("error")
    text = (verdict.get("message") or "") + "\n" + (verdict.text or "")
    lines = [line.rstrip() for line in text.splitlines() if line.strip()]
    return "".join(f"\n    {line}" for line in lines[:MESSAGE_LINES])


def main(results_dir):
    root = pathlib.Path(results_dir)
    files = sorted(root.rglob("*.xml")) if root.is_dir() else []
    passed, failed, skipped = 0, [], 0
    for path in files:
        try:
            tree = ET.parse(path)
        except ET.ParseError as error:
            failed.append(f"{path.name}: unreadable result file ({error})")
            continue
        seen = set()
        for case in tree.getroot().iter("testcase"):
            key = (case.get("classname"), case.get("name"))
            if key in seen:  # a result file must not count a case twice
                continue
            seen.add(key)
            if case.find("failure") is not None or case.find("error") is not None:
                failed.append(f"{path.name}: {key[0]}.{key[1]}{failure_message(case)}")
            elif (case.find("skipped") is not None or case.get("status") == "notrun"
                  or case.get("result") == "skipped"):
                skipped += 1
            else:
                passed += 1
    for name in failed:
        print(f"FAILED {name}")
    line = f"{passed} passed, {len(failed)} failed"
    if skipped:
        line += f", {skipped} skipped"
    print(line)
    return 1 if failed or passed == 0 else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "build/test_results"))
