#!/usr/bin/python3
"""Runs the build of the test programs (the command after `--`), its whole output into a
log, and says where it is: build_progress.py's line as each package starts compiling, its
warnings and errors, and make's last progress line whenever 25 s passed without a line (a
line at least every 30 s, with a second of polling and a loaded machine to spare).
Exits with the build's status."""
import argparse
import re
import subprocess
import sys
import threading
import time

from build_progress import Progress

QUIET_S = 25.0
MAKE_LINE = re.compile(r'^\[ *\d+%\] .*')


class Stamped:
    """An output stream that notes when it was last written to."""

    def __init__(self, out, clock):
        self.out, self.clock = out, clock
        self.last_write = clock()

    def write(self, text):
        self.out.write(text)
        self.last_write = self.clock()

    def flush(self):
        self.out.flush()


class Watched:
    def __init__(self, out, clock=time.monotonic):
        self.out = Stamped(out, clock)
        self.progress = Progress(self.out, clock)
        self.clock = clock
        self.last_make = 'nothing built yet'
        self.lock = threading.Lock()

    def line(self, text):
        with self.lock:
            self.progress.line(text)
            make = MAKE_LINE.match(text)
            if make:
                self.last_make = make.group(0).strip()

    def still_building(self):
        with self.lock:
            now = self.clock()
            if now - self.out.last_write < QUIET_S:
                return
            self.out.write('%s building the test programs: %s\n' % (
                self.progress.stamp(now - self.progress.start), self.last_make))
            self.out.flush()


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument('--log', required=True)
    parser.add_argument('command', nargs=argparse.REMAINDER)
    args = parser.parse_args()
    command = args.command[1:] if args.command[:1] == ['--'] else args.command
    watched = Watched(sys.stdout)
    with open(args.log, 'w') as log:
        build = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                 text=True, errors='replace')
        reader = threading.Thread(target=copy_lines, args=(build.stdout, log, watched))
        reader.start()
        while reader.is_alive():
            watched.still_building()
            reader.join(timeout=1.0)
    return build.wait()


def copy_lines(stream, log, watched):
    for text in stream:
        log.write(text)
        watched.line(text)


if __name__ == '__main__':
    sys.exit(main())
