#!/usr/bin/python3
"""Reads catkin_make's output on stdin and says where the build is: a line when a package
starts compiling and, at the end, each package's time from its first compile line to its
last target built (packages build in parallel with -j2, so the times overlap). Warnings, errors
and catkin's headlines pass through as they come. When nothing was printed for HEARTBEAT_S
(one long compile), a line says which package is being built and how far it is."""
import re
import sys
import threading
import time

HEARTBEAT_S = 25

PASS_THROUGH = re.compile(r'(^#### |^-- ~~ +[a-z]|: (error|warning):|^make.*Error|\*\*\*)')
PACKAGE_WORK = re.compile(r'(Building \w+ object|Linking \w+ \w+ library|Linking \w+ executable'
                          r'|Generating) .*?src/([A-Za-z0-9_]+)/')
TARGET_OF = re.compile(r'src/([A-Za-z0-9_]+)/CMakeFiles/([A-Za-z0-9_.+-]+)\.dir/')
BUILT = re.compile(r'Built target (\S+)')
MAKE_PERCENT = re.compile(r'^\[ *(\d+)%\]')


class Progress:
    def __init__(self, out, clock=time.monotonic):
        self.out, self.clock = out, clock
        self.start = clock()
        self.spans = {}  # package -> [first, last] seconds since start
        self.package_of = {}  # make target -> package, learnt from its object files
        self.files = {}  # package -> object files compiled so far
        self.current = None  # the package of the latest compile line
        self.percent = None  # make's latest progress figure
        self.last_output = 0.0
        self.lock = threading.Lock()

    def stamp(self, seconds):
        return '[%2d:%02d]' % (seconds // 60, seconds % 60)

    def write(self, text, now):
        self.out.write(text)
        self.out.flush()
        self.last_output = now

    def line(self, text):
        with self.lock:
            self.read(text)

    def read(self, text):
        now = self.clock() - self.start
        percent = MAKE_PERCENT.match(text)
        if percent:
            self.percent = int(percent.group(1))
        if PASS_THROUGH.search(text):
            self.write(text if text.endswith('\n') else text + '\n', now)
        target = TARGET_OF.search(text)
        if target:
            self.package_of[target.group(2)] = target.group(1)
        built = BUILT.search(text)
        if built and built.group(1) in self.package_of:
            self.spans[self.package_of[built.group(1)]][1] = now
            return
        match = PACKAGE_WORK.search(text)
        if not match:
            return
        package = match.group(2)
        if package not in self.spans:
            self.spans[package] = [now, now]
            self.write('%s building %s\n' % (self.stamp(now), package), now)
        self.spans[package][1] = now
        self.current = package
        if match.group(1).startswith('Building'):
            self.files[package] = self.files.get(package, 0) + 1

    def heartbeat(self):
        """Says where the build is when nothing was printed for HEARTBEAT_S."""
        with self.lock:
            now = self.clock() - self.start
            if now - self.last_output < HEARTBEAT_S:
                return
            if self.percent is None:
                where = 'configuring'
            elif self.current is None:
                where = 'building: make at %d%%' % self.percent
            else:
                where = 'building %s: %d files compiled so far, make at %d%%' % (
                    self.current, self.files.get(self.current, 0), self.percent)
            self.write('%s %s\n' % (self.stamp(now), where), now)

    def summary(self):
        total = self.clock() - self.start
        lines = ['%s build done; compile and link time per package:' % self.stamp(total)]
        for package, (first, last) in sorted(self.spans.items(), key=lambda kv: kv[1][0]):
            lines.append('  %-28s %6.1f s  (%s .. %s)' % (package, last - first, self.stamp(first),
                                                         self.stamp(last)))
        return '\n'.join(lines) + '\n'


def beat(progress, done):
    while not done.wait(1.0):
        progress.heartbeat()


def follow(lines, progress, log=None):
    """Feeds `lines` to `progress` (and copies them to `log`), with a heartbeat every second
    while it waits for the next line."""
    done = threading.Event()
    beat_thread = threading.Thread(target=beat, args=(progress, done), daemon=True)
    beat_thread.start()
    for text in lines:
        if log is not None:
            log.write(text)
        progress.line(text)
    done.set()
    beat_thread.join()


def main():
    progress = Progress(sys.stdout)
    follow(sys.stdin, progress)
    if progress.spans:
        sys.stdout.write(progress.summary())


if __name__ == '__main__':
    main()
