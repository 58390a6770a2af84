#!/usr/bin/python3
"""Reads the JUnit XML results under a folder, prints a line per result file
and per failed test, and a closing 'N passed, N failed' line. Exits 1 when a
test failed, a result file is unreadable, or no test ran at all."""
import glob
import os
import sys
import xml.etree.ElementTree as ET


def case_problem(case):
    """The first line of a test case's failure or error, or None if it passed."""
    for tag in ('failure', 'error'):
        node = case.find(tag)
        if node is not None:
            lines = (node.get('message') or node.text or tag).strip().splitlines()
            return lines[0] if lines else tag
    return None


def count_file(path):
    """{'passed', 'failed', 'skipped'} of one result file; an unreadable one counts as one
    failure."""
    counts = {'passed': 0, 'failed': 0, 'skipped': 0}
    try:
        cases = list(ET.parse(path).getroot().iter('testcase'))
    except (ET.ParseError, OSError):
        counts['failed'] = 1
        return counts
    for case in cases:
        if case_problem(case) is not None:
            counts['failed'] += 1
        elif case.find('skipped') is not None:
            counts['skipped'] += 1
        else:
            counts['passed'] += 1
    return counts


def summarize(results_dir):
    totals = {'passed': 0, 'failed': 0, 'skipped': 0}
    lines, problems = [], []
    files = sorted(glob.glob(os.path.join(results_dir, '**', '*.xml'), recursive=True))
    for path in files:
        name = os.path.relpath(path, results_dir)
        try:
            cases = list(ET.parse(path).getroot().iter('testcase'))
        except ET.ParseError as err:
            problems.append(f'{name}: unreadable result ({err})')
            totals['failed'] += 1
            continue
        counts = {'passed': 0, 'failed': 0, 'skipped': 0}
        for case in cases:
            problem = case_problem(case)
            if problem is not None:
                problems.append(f"{name}: {case.get('classname', '')}.{case.get('name', '')}: "
                                f"{problem}")
                counts['failed'] += 1
            elif case.find('skipped') is not None:
                counts['skipped'] += 1
            else:
                counts['passed'] += 1
        for key in totals:
            totals[key] += counts[key]
        status = 'FAIL' if counts['failed'] else 'ok  '
        lines.append(f"{status} {name}: {counts['passed']} passed, {counts['failed']} failed")
    return totals, lines, problems, len(files)


def main():
    results_dir = sys.argv[1] if len(sys.argv) > 1 else 'build/test_results'
    totals, lines, problems, nfiles = summarize(results_dir)
    print('\n'.join(lines))
    for line in problems:
        print('FAILED', line)
    print(f'{nfiles} result files in {results_dir}')
    print(f"{totals['passed']} passed, {totals['failed']} failed, {totals['skipped']} skipped")
    return 0 if totals['failed'] == 0 and totals['passed'] > 0 else 1


if __name__ == '__main__':
    sys.exit(main())
