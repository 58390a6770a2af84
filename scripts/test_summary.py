#!/usr/bin/python3
"""Reads the JUnit XML results under a folder and prints one line per failed
test and a closing 'N passed, N failed' line. Exits 1 when a test failed, a
result file is missing or unreadable, or no test ran at all."""
import glob
import os
import sys
import xml.etree.ElementTree as ET


def summarize(results_dir):
    passed, failed, skipped, problems = 0, 0, 0, []
    files = sorted(glob.glob(os.path.join(results_dir, '**', '*.xml'), recursive=True))
    for path in files:
        name = os.path.relpath(path, results_dir)
        try:
            root = ET.parse(path).getroot()
        except ET.ParseError as err:
            problems.append(f'{name}: unreadable result ({err})')
            failed += 1
            continue
        cases = root.iter('testcase')
        for case in cases:
            label = f"{name}: {case.get('classname', '')}.{case.get('name', '')}"
            if case.find('failure') is not None or case.find('error') is not None:
                node = case.find('failure') if case.find('failure') is not None else case.find('error')
                message = (node.get('message') or node.text or '').strip().splitlines()
                problems.append(f"{label}: {message[0] if message else 'failed'}")
                failed += 1
            elif case.find('skipped') is not None:
                skipped += 1
            else:
                passed += 1
    return passed, failed, skipped, problems, len(files)


def main():
    results_dir = sys.argv[1] if len(sys.argv) > 1 else 'build/test_results'
    passed, failed, skipped, problems, nfiles = summarize(results_dir)
    for line in problems:
        print('FAILED', line)
    print(f'{nfiles} result files in {results_dir}')
    print(f'{passed} passed, {failed} failed, {skipped} skipped')
    return 0 if failed == 0 and passed > 0 else 1


if __name__ == '__main__':
    sys.exit(main())
