"""The one-line status the window shows (and prints for tests with print_status)."""


def format_rate(rate_hz):
    """'10.0 Hz', or 'no frames' when no stream is measured."""
    return 'no frames' if rate_hz is None else f'{rate_hz:.1f} Hz'


def status_text(topic, encoding, width, height, rate_hz):
    """Human status, e.g. '/camera/image_raw  640x480 rgb8  30.0 Hz'."""
    if not topic:
        return 'no topic selected'
    if not encoding:
        return f'{topic}  waiting for frames'
    return f'{topic}  {width}x{height} {encoding}  {format_rate(rate_hz)}'


def status_line(topic, encoding, width, height, rate_hz):
    """Machine-readable status: 'status: topic=.. encoding=.. size=WxH rate_hz=..'."""
    rate = 'none' if rate_hz is None else f'{rate_hz:.2f}'
    return (f'status: topic={topic or "none"} encoding={encoding or "none"} '
            f'size={width}x{height} rate_hz={rate}')


def parse_status_line(line):
    """The fields of a status_line as a dict of strings (for tests and tools)."""
    if not line.startswith('status: '):
        raise ValueError(f'not a status line: {line!r}')
    return dict(field.split('=', 1) for field in line[len('status: '):].split())
