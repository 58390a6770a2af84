"""Running Graphviz's dot and writing the graph to .dot, .svg or .png files."""
import os
import subprocess

DOT = '/usr/bin/dot'
FORMATS = ('dot', 'svg', 'png')


class RenderError(RuntimeError):
    """dot failed, or an output file cannot be written; the message says which."""


def render(dot_text, fmt):
    """Lays out and renders DOT text with dot, returns the bytes of format fmt."""
    try:
        result = subprocess.run([DOT, f'-T{fmt}'], input=dot_text.encode(),
                                capture_output=True, timeout=60)
    except (OSError, subprocess.TimeoutExpired) as err:
        raise RenderError(f'cannot run {DOT}: {err}') from None
    if result.returncode != 0:
        raise RenderError(f'{DOT} -T{fmt} failed: {result.stderr.decode().strip()}')
    return result.stdout


def output_format(path):
    """The format named by a file's extension, or RenderError naming the file."""
    fmt = os.path.splitext(path)[1].lower().lstrip('.')
    if fmt not in FORMATS:
        raise RenderError(f'cannot write {path!r}: extension must be one of '
                          f'{", ".join("." + f for f in FORMATS)}')
    return fmt


def write_graph(path, dot_text):
    """Writes DOT text, or its SVG/PNG rendering, to path according to its extension."""
    fmt = output_format(path)
    data = dot_text.encode() if fmt == 'dot' else render(dot_text, fmt)
    try:
        with open(path, 'wb') as out:
            out.write(data)
    except OSError as err:
        raise RenderError(f'cannot write {path!r}: {err.strerror}') from None
