"""The measurements of bench/compare, how to read each one's figure from its output, and the
table of medians with ratios that it prints. No process is started here (bench/compare does
that), so bench/test_comparison.py tests the parsing, the alternation and the table."""
import re
import statistics

RTF = r"real-time factor ([0-9.]+)\s*(?:\(.*\))?$"
RTF_CPU = r"real-time factor per CPU second ([0-9.]+)$"


class Measurement:
    """One run: the command, and the figures it prints (key, label, regex, unit): each the
    first group of the regex's last match in the run's output."""

    def __init__(self, command, figures, env=None, group=0):
        self.command, self.env, self.group = command, env, group
        self.figures = [(key, label, re.compile(pattern, re.M), unit)
                        for key, label, pattern, unit in figures]
        self.key = self.figures[0][0]

    def parse(self, output):
        values = {}
        for key, label, pattern, _ in self.figures:
            matches = pattern.findall(output)
            if not matches:
                raise ValueError("%s: no figure in the output" % label)
            last = matches[-1]
            values[key] = float(last[0] if isinstance(last, tuple) else last)
        return values


def alternated(measurements, round_index):
    """The run order of one round: each group's members rotated by the round's index, so that
    no peer always runs first (or right after the same neighbour) on a shared machine."""
    groups = {}
    for m in measurements:
        groups.setdefault(m.group, []).append(m)
    order = []
    for group in sorted(groups):
        members = groups[group]
        shift = round_index % len(members)
        order += members[shift:] + members[:shift]
    return order


def summary(values):
    """Median and range of a list of figures."""
    return statistics.median(values), min(values), max(values)


def cell(values, unit):
    med, low, high = summary(values)
    # Real-time factors to three figures: 148x, 38.4x, 10.2x.
    digits = 0 if unit == "x" and med >= 100 else (1 if unit in ("x", "MB") else 2)
    return "%.*f%s (%.*f-%.*f)" % (digits, med, unit if unit == "x" else " " + unit,
                                   digits, low, digits, high)


RATIOS = (
    # (line key, numerator, denominator, invert: higher figure is worse)
    ("vs_mujoco_node", "node", "mujoco", False),
    ("vs_mujoco_core", "core", "mujoco", False),
    ("vs_mujoco_camera", "camera_ours", "camera_mujoco", True),
    ("vs_mujoco_depth", "depth_ours", "depth_mujoco", True),
    ("vs_mujoco_camera_textured", "textured_ours", "textured_mujoco", True),
    ("vs_pybullet_node", "node", "pybullet", False),
)

# Real-time factors (medians) on the summary line: the robots in one node, as a nodelet,
# and in the core alone on every thread and on one.
LINE_FIGURES = ("robots_1", "robots_4", "robots_16", "robots_nodelet_16", "robots_core_1",
                "robots_core_16", "robots_core_16_1thread")
# Then the launch to first /scan (s; roslaunch's own master, a running one), the part of it
# from the simulator's process start, and the node's resident memory (MB), medians.
LINE_LAUNCH = (("launch_own", "%.2f"), ("launch_running", "%.2f"), ("launch_sim_own", "%.2f"),
               ("launch_sim_running", "%.2f"), ("memory", "%.1f"))


# Ratios shown in the table only: the single-process runs by CPU time, which a shared
# machine disturbs less than wall time.
TABLE_RATIOS = RATIOS + (
    (None, "core_cpu", "mujoco_cpu", False),
    (None, "core_cpu", "pybullet_cpu", False),
)


def ratio(results, numerator, denominator, invert):
    a, b = statistics.median(results[numerator]), statistics.median(results[denominator])
    return b / a if invert else a / b


def ratio_notes(results):
    """Ratio text per row key, e.g. '0.9x MuJoCo' beside bullet_sim_node."""
    notes = {}
    for _, numerator, denominator, invert in TABLE_RATIOS:
        if numerator not in results or denominator not in results:
            continue
        peer = "MuJoCo" if "mujoco" in denominator else "PyBullet"
        text = "%.2fx %s" % (ratio(results, numerator, denominator, invert), peer)
        notes[numerator] = notes[numerator] + ", " + text if numerator in notes else text
    return notes


def table(measurements, results):
    """Markdown table of every measurement: median (range) and ratio to the peers."""
    notes = ratio_notes(results)
    lines = ["| | median (range) | ratio |", "|---|---|---|"]
    shown = set()
    for m in measurements:
        for key, label, _, unit in m.figures:
            if key in results and key not in shown:
                shown.add(key)
                lines.append("| %s | %s | %s |" % (label, cell(results[key], unit),
                                                  notes.get(key, "")))
    return "\n".join(lines)


def last_line(results, loadavg):
    """The one summary line: the ratios to MuJoCo and PyBullet, the robots' real-time
    factors, the launch times and memory (medians) and the load average (1, 5, 15
    minutes) when it was printed."""
    parts = ["%s=%.2f" % (key, ratio(results, n, d, inv)) for key, n, d, inv in RATIOS
             if n in results and d in results]
    parts += ["%s=%.1f" % (key, statistics.median(results[key])) for key in LINE_FIGURES
              if key in results]
    parts += [("%s=" + form) % (key, statistics.median(results[key])) for key, form in LINE_LAUNCH
              if key in results]
    parts.append("loadavg=%.2f/%.2f/%.2f" % tuple(loadavg))
    return " ".join(parts)
