#!/usr/bin/python3
"""Runs the build of the test programs (the command after `--`), its whole output into a
log, and says where it is as build_progress.py does for `make build`: a line as each
package starts compiling, its warnings and errors, and a line whenever 25 s passed without
one (at least every 30 s, with a second of polling and a loaded machine to spare).
Exits with the build's status."""
import argparse
import subprocess
import sys

from build_progress import Progress, follow


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument('--log', required=True)
    parser.add_argument('command', nargs=argparse.REMAINDER)
    args = parser.parse_args()
    command = args.command[1:] if args.command[:1] == ['--'] else args.command
    with open(args.log, 'w') as log:
        build = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                 text=True, errors='replace')
        follow(build.stdout, Progress(sys.stdout), log)
    return build.wait()


if __name__ == '__main__':
    sys.exit(main())
